#pragma once
// Error and run time of one deformation variant (queue x refinement sweeps) on a scene.
#include "report_scenes.h"

#include "geoshaping/chainmail_deformer.h"
#include "geoshaping/link_projection.h"

#include <memory>

namespace geoshaping::report
{

struct Variant
{
  QueueKind queue = QueueKind::fifo_priority;
  int sweeps = 0; // refinement iterations
};

struct Measurement
{
  std::size_t displaced = 0; // vertices off rest after the frame (ChainMail + refinement)
  double median_ms = 0.0;    // one frame: deform + refine
  double e_rigid = 0.0, e_link = 0.0, e_temporal = 0.0;
  ReferenceError e_ref;
};

// One scene's deformer, metric mesh, projector and reference, built once and shared by
// the variants.
class SceneBench
{
public:
  // The reference is the point of F nearest the FIFO Priority result (least total
  // movement from it), by Dykstra capped at `reference_sweeps`.
  SceneBench(Scene scene, int reference_sweeps);
  const Scene& scene() const { return scene_; }
  const ProjectionReport& reference_report() const { return reference_report_; }
  double reference_seconds() const { return reference_seconds_; }
  std::size_t deformer_bytes() const { return deformer_.memory_bytes(); }

  // Times `repetitions` frames at the scene's pull (median), then measures the errors
  // of that frame and E_temporal over a drag of `drag_steps` small steps.
  Measurement measure(const Variant& v, int repetitions, int drag_steps);

  // The dense displacements of one frame of `v` at `pull`.
  Displacements frame(const Variant& v, const Eigen::Vector3d& pull);
  const LinkMesh& link_mesh() const { return links_; }

private:
  // Runs one frame; returns the vertices whose displacement may be non-zero and fills
  // `values` with theirs when asked.
  const std::vector<index_t>& run(const Variant& v, const Eigen::Vector3d& pull);
  const Eigen::Vector3d& value(const Variant& v, index_t vertex) const;

  Scene scene_;
  ChainMailDeformer deformer_;
  LinkMesh links_;
  std::unique_ptr<LinkProjector> projector_;
  Displacements reference_;
  ProjectionReport reference_report_;
  double reference_seconds_ = 0.0;
};

double median(std::vector<double> v);

} // namespace geoshaping::report
