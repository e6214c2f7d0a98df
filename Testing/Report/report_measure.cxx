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

namespace
{
double seconds_since(std::chrono::steady_clock::time_point t)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}
} // namespace

SceneBench::SceneBench(Scene scene, int reference_sweeps)
  : scene_(std::move(scene))
{
  deformer_.set_mesh(scene_.xyz.data(), index_t(scene_.xyz.size() / 3), scene_.adjacency);
  deformer_.set_malleability(scene_.malleability.data());
  links_ = geoshaping::link_mesh(deformer_);
  projector_ = std::make_unique<LinkProjector>(links_);
  // Started from the FIFO Priority result (one reference shared by every variant):
  // from rest with only the grasp displaced Dykstra grows its region one ring per sweep
  // and did not get under 0.8 L of violation in 2,000 sweeps on the fault step.
  deformer_.set_queue(QueueKind::fifo_priority);
  deformer_.deform(scene_.grasp, scene_.pull);
  const Displacements start = displacements(deformer_);
  ProjectionOptions options;
  options.max_iterations = reference_sweeps;
  const auto t = std::chrono::steady_clock::now();
  reference_ =
    reference_configuration(links_, scene_.grasp, start, &reference_report_, options);
  reference_seconds_ = seconds_since(t);
}

const std::vector<index_t>& SceneBench::run(const Variant& v, const Eigen::Vector3d& pull)
{
  deformer_.set_queue(v.queue);
  deformer_.deform(scene_.grasp, pull);
  if (v.sweeps == 0)
    return deformer_.moved();
  refine_links(*projector_, deformer_, scene_.grasp, v.sweeps);
  return projector_->region();
}

const Eigen::Vector3d& SceneBench::value(const Variant& v, index_t vertex) const
{
  return v.sweeps == 0 ? deformer_.displacement(vertex) : projector_->displacement(vertex);
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
    const auto t = std::chrono::steady_clock::now();
    run(v, scene_.pull);
    ms.push_back(1e3 * seconds_since(t));
  }
  m.median_ms = median(ms);

  const Displacements u = frame(v, scene_.pull);
  for (const Eigen::Vector3d& w : u)
    m.displaced += !w.isZero(0.0);
  m.e_rigid = rigid_error(links_, u);
  m.e_link = link_error(links_, u);
  m.e_ref = reference_error(links_, u, reference_);

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
