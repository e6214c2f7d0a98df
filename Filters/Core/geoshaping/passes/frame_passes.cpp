#include "geoshaping/passes/frame_passes.h"

#include "geoshaping/deform/valid_region.h"

#include <algorithm>

namespace geoshaping
{

void FramePasses::begin_frame()
{
  refining_ = false;
  relaxing_ = false;
  held_back_ = 0;
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
    gated_.assign(std::size_t(links_.size()), 0);
    beyond_.clear();
  }
  links_.frame = deformer.valid_region_frame(); // the passes keep the deformer's region shape
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

template<class Pass, class Before>
void FramePasses::gate(const ChainMailDeformer& deformer, Pass& pass, Before before)
{
  const Obstacles* obstacles = deformer.obstacles();
  if (!obstacles)
    return;
  const double clearance = deformer.obstacle_clearance();
  const Adjacency& adjacency = *links_.adjacency;
  auto rigid_member = [&](index_t v)
  {
    return region_params(links_.params[std::size_t(v)]).rigid() && !links_.is_pinned(v) &&
           !deformer.sliding(v);
  };
  const std::vector<index_t>& changed = pass.changed();
  for (index_t v : changed)
    gated_[std::size_t(v)] = 1; // changed, not gated yet
  for (index_t v : changed)
  {
    if (gated_[std::size_t(v)] != 1)
      continue;
    gated_[std::size_t(v)] = 2;
    if (deformer.sliding(v))
    {
      const Eigen::Vector3d start = before(v);
      if (start != pass.displacement(v))
      {
        pass.correct(v, start);
        ++held_back_;
      }
      continue;
    }
    members_.assign(1, v);
    if (rigid_member(v))
      for (std::size_t k = 0; k < members_.size(); ++k)
        for (const index_t* w = adjacency.begin(members_[k]); w != adjacency.end(members_[k]); ++w)
          if (gated_[std::size_t(*w)] == 1 && rigid_member(*w))
          {
            gated_[std::size_t(*w)] = 2;
            members_.push_back(*w);
          }
    double f = 1.0;
    for (index_t m : members_)
      f = std::min(
        f, obstacles->admissible_fraction(deformer.rest_local(m), pass.displacement(m), clearance));
    if (f < 1.0)
    {
      for (index_t m : members_)
        pass.correct(m, f * pass.displacement(m));
      held_back_ += members_.size();
    }
  }
  for (index_t v : changed)
    gated_[std::size_t(v)] = 0;
}

ProjectionReport FramePasses::refine(
  const ChainMailDeformer& deformer, index_t grasp, const ProjectionOptions& options)
{
  ensure_links(deformer);
  const ProjectionReport report = refine_links(*projector_, deformer, grasp, options);
  gate(deformer, *projector_, [&](index_t v) { return deformer.displacement(v); });
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
  gate(deformer, *relaxer_, [&](index_t v) { return displacement(deformer, v); });
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
