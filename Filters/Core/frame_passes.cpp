#include "geoshaping/frame_passes.h"

namespace geoshaping
{

void FramePasses::begin_frame()
{
  refining_ = false;
  relaxing_ = false;
  for (index_t v : beyond_)
    in_beyond_[std::size_t(v)] = 0;
  beyond_.clear();
}

void FramePasses::ensure_links(const ChainMailDeformer& deformer)
{
  if (!projector_ || !(deformer.transfer_function() == links_transfer_))
  {
    links_ = link_mesh(deformer);
    links_transfer_ = deformer.transfer_function();
    projector_ = std::make_unique<LinkProjector>(links_);
    relaxer_ = std::make_unique<Relaxer>(links_);
    in_beyond_.assign(std::size_t(links_.size()), 0);
    beyond_.clear();
  }
  links_.frame = deformer.valid_region_frame(); // the passes keep the frame's regions
}

void FramePasses::add_beyond(const ChainMailDeformer& deformer, const std::vector<index_t>& changed)
{
  for (index_t v : changed)
    if (!deformer.moved_this_frame(v) && !in_beyond_[std::size_t(v)])
    {
      in_beyond_[std::size_t(v)] = 1;
      beyond_.push_back(v);
    }
}

ProjectionReport FramePasses::refine(
  const ChainMailDeformer& deformer, index_t grasp, const ProjectionOptions& options)
{
  ensure_links(deformer);
  const ProjectionReport report = refine_links(*projector_, deformer, grasp, options);
  refining_ = true;
  add_beyond(deformer, projector_->changed());
  return report;
}

ProjectionReport FramePasses::refine_with(const ChainMailDeformer& deformer,
  const std::function<ProjectionReport(const LinkMesh&, LinkProjector&)>& run)
{
  ensure_links(deformer);
  const ProjectionReport report = run(links_, *projector_);
  refining_ = true;
  add_beyond(deformer, projector_->changed());
  return report;
}

RelaxationReport FramePasses::relax(
  const ChainMailDeformer& deformer, index_t grasp, const RelaxationOptions& options)
{
  ensure_links(deformer);
  std::vector<index_t> vertices;
  Displacements values;
  final_shape(deformer, vertices, values);
  const RelaxationReport report = relaxer_->relax(grasp, vertices, values, options);
  relaxing_ = true;
  add_beyond(deformer, relaxer_->changed());
  return report;
}

void FramePasses::final_shape(
  const ChainMailDeformer& deformer, std::vector<index_t>& vertices, Displacements& values) const
{
  vertices = deformer.moved();
  vertices.insert(vertices.end(), beyond_.begin(), beyond_.end());
  values.clear();
  values.reserve(vertices.size());
  for (index_t v : vertices)
    values.push_back(displacement(deformer, v));
}

} // namespace geoshaping
