#include "report_measure.h"

#include <algorithm>
#include <chrono>

namespace geoshaping::report
{

double median(std::vector<double> v)
{
  if (v.empty())
    return 0.0;
  std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
  return v[v.size() / 2];
}

std::string refinement_name(const Variant& v)
{
  switch (v.refinement)
  {
    case Refinement::dykstra:
      return "Dykstra " + std::to_string(v.iterations);
    case Refinement::admm:
      return "ADMM " + std::to_string(v.iterations);
    case Refinement::envelope:
      return "Envelope";
    default:
      return "none";
  }
}

std::string variant_name(const Variant& v)
{
  std::string s =
    std::string(queue_name(v.queue)) + ", " + frame_name(v.frame) + ", " + refinement_name(v);
  if (v.relaxation > 0)
    s += ", relax " + std::to_string(v.relaxation);
  return s;
}

bool same_variant(const Variant& a, const Variant& b)
{
  return a.queue == b.queue && a.frame == b.frame && a.refinement == b.refinement &&
         (a.refinement == Refinement::none || a.iterations == b.iterations) &&
         a.relaxation == b.relaxation;
}

double roughness(const LinkMesh& lm, const Displacements& u)
{
  const Adjacency& adj = *lm.adjacency;
  double worst = 0.0;
  for (index_t v = 0; v < lm.size(); ++v)
  {
    if (u[std::size_t(v)].isZero(0.0) || lm.rigid[std::size_t(v)] || adj.degree(v) == 0)
      continue;
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    for (const index_t* n = adj.begin(v); n != adj.end(v); ++n)
      mean += u[std::size_t(*n)];
    mean /= double(adj.degree(v));
    worst = std::max(worst, (u[std::size_t(v)] - mean).norm());
  }
  return worst / lm.scale();
}

namespace
{
double seconds_since(std::chrono::steady_clock::time_point t)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}
} // namespace

SceneBench::SceneBench(Scene scene, double reference_tolerance, int reference_iterations)
  : scene_(std::move(scene))
{
  deformer_.set_mesh(scene_.xyz.data(), index_t(scene_.xyz.size() / 3), scene_.adjacency);
  deformer_.set_malleability(scene_.malleability.data());
  for (ValidRegionFrame f : { ValidRegionFrame::axes, ValidRegionFrame::link })
  {
    deformer_.set_valid_region_frame(f);
    links_[int(f)] = geoshaping::link_mesh(deformer_);
    // Started from the FIFO Priority result (one reference per frame shared by every
    // variant of that frame).
    deformer_.set_queue(QueueKind::fifo_priority);
    deformer_.deform(scene_.grasp, scene_.pull);
    const Displacements start = displacements(deformer_);
    ProjectionOptions options;
    options.tolerance = reference_tolerance;
    options.max_iterations = reference_iterations;
    const auto t = std::chrono::steady_clock::now();
    reference_[int(f)] = reference_configuration(
      links_[int(f)], scene_.grasp, start, &reference_report_[int(f)], options);
    reference_seconds_[int(f)] = seconds_since(t);
  }
}

const std::vector<index_t>& SceneBench::run(const Variant& v, const Eigen::Vector3d& pull)
{
  deformer_.set_queue(v.queue);
  deformer_.set_valid_region_frame(v.frame);
  deformer_.deform(scene_.grasp, pull);
  last_ = ProjectionReport();
  FramePasses& passes = passes_[int(v.frame)];
  passes.begin_frame();
  if (v.refinement != Refinement::none)
  {
    ProjectionOptions o;
    o.solver = v.refinement == Refinement::admm
                 ? ProjectionSolver::admm
                 : (v.refinement == Refinement::envelope ? ProjectionSolver::envelope
                                                         : ProjectionSolver::dykstra);
    o.max_iterations = v.iterations;
    o.tolerance = 1e-6; // the filter's default RefinementTolerance
    last_ = passes.refine(deformer_, scene_.grasp, o);
  }
  if (v.relaxation > 0)
  {
    RelaxationOptions ro;
    ro.iterations = v.relaxation;
    passes.relax(deformer_, scene_.grasp, ro);
  }
  if (!passes.refined() && !passes.relaxed())
    return deformer_.moved();
  touched_ = deformer_.moved();
  touched_.insert(touched_.end(), passes.beyond().begin(), passes.beyond().end());
  return touched_;
}

const Eigen::Vector3d& SceneBench::value(const Variant& v, index_t vertex) const
{
  return passes_[int(v.frame)].displacement(deformer_, vertex);
}

Displacements SceneBench::frame(const Variant& v, const Eigen::Vector3d& pull)
{
  Displacements u(std::size_t(deformer_.size()), Eigen::Vector3d::Zero());
  for (index_t w : run(v, pull))
    u[std::size_t(w)] = value(v, w);
  return u;
}

Measurement SceneBench::measure(const Variant& v, int repetitions, int drag_steps)
{
  Measurement m;
  std::vector<double> ms;
  for (int r = 0; r < repetitions; ++r)
  {
    // Each repetition starts from another frame (a drag position) so that the ADMM
    // factorisation is not reused from the previous repetition: the time is that of a
    // frame whose region changed, as in a drag.
    if (v.refinement == Refinement::admm)
      run(v, 0.5 * scene_.pull);
    const auto t = std::chrono::steady_clock::now();
    run(v, scene_.pull);
    ms.push_back(1e3 * seconds_since(t));
  }
  m.median_ms = median(ms);

  const Displacements u = frame(v, scene_.pull);
  m.iterations_run = last_.iterations;
  for (const Eigen::Vector3d& w : u)
    m.displaced += !w.isZero(0.0);
  const LinkMesh& lm = links_[int(v.frame)];
  m.e_rigid = rigid_error(lm, u);
  m.e_link = link_error(lm, u);
  m.e_ref = reference_error(lm, u, reference_[int(v.frame)]);
  m.roughness = roughness(lm, u);

  // A slow drag over the last quarter of the pull, in small steps.
  TemporalError temporal(deformer_.size());
  Displacements values;
  for (int k = 0; k < drag_steps; ++k)
  {
    const Eigen::Vector3d drag = scene_.pull * (0.75 + 0.25 * k / std::max(1, drag_steps - 1));
    const std::vector<index_t>& vertices = run(v, drag);
    values.clear();
    for (index_t w : vertices)
      values.push_back(value(v, w));
    temporal.add_frame(drag, vertices, values);
  }
  m.e_temporal = temporal.value();
  return m;
}

} // namespace geoshaping::report
