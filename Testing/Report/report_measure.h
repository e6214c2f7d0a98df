#pragma once
// Error and run time of one deformation variant (queue x valid-region shape x refinement
// x relaxation) on a scene.
#include "report_scenes.h"

#include "geoshaping/deform/chainmail_deformer.h"
#include "geoshaping/passes/frame_passes.h"
#include "geoshaping/passes/link_projection.h"
#include "geoshaping/passes/relaxation.h"

#include <memory>
#include <string>

namespace geoshaping::report
{

enum class Refinement
{
  none,
  dykstra, // `iterations` Dykstra sweeps
  admm,    // at most `iterations` ADMM iterations (RefinementIterations), tolerance 1e-6 L
  envelope // the envelope (link_projection.h): exactly feasible in one pass, Axes region
};

struct Variant
{
  QueueKind queue = QueueKind::fifo_priority;
  ValidRegionFrame frame = ValidRegionFrame::axes;
  Refinement refinement = Refinement::none;
  int iterations = 0; // refinement iterations (sweeps for Dykstra)
  int relaxation = 0; // RelaxationIterations: relaxation sweeps after the refinement
};
// "none", "Dykstra 4", "ADMM 16", ...
std::string refinement_name(const Variant& v);
// "FIFO Priority, Axes, ADMM 16"
std::string variant_name(const Variant& v);
bool same_variant(const Variant& a, const Variant& b);

struct Measurement
{
  std::size_t displaced = 0; // vertices off rest after the frame (ChainMail + refinement)
  double median_ms = 0.0;    // one frame: deform + refine
  double e_rigid = 0.0, e_link = 0.0, e_temporal = 0.0;
  // Roughness: the largest umbrella Laplacian of the displacement, |u_v - mean of u over
  // v's neighbours| / L, over the displaced soft vertices (0 on any affine field: a
  // translation, a uniform slope; ChainMail's facet ridges and teeth are its maxima).
  double roughness = 0.0;
  ReferenceError e_ref;
  int iterations_run = 0; // refinement iterations the frame ran
};

// One scene's deformer, metric meshes, projectors and references (one per frame), built
// once and shared by the variants.
class SceneBench
{
public:
  // The reference of each frame is the point of its F nearest the FIFO Priority result
  // in that frame (least total movement from it), by ADMM to `reference_tolerance` L,
  // capped at `reference_iterations`.
  SceneBench(Scene scene, double reference_tolerance, int reference_iterations);
  const Scene& scene() const { return scene_; }
  const ProjectionReport& reference_report(ValidRegionFrame f) const
  {
    return reference_report_[int(f)];
  }
  double reference_seconds(ValidRegionFrame f) const { return reference_seconds_[int(f)]; }
  std::size_t deformer_bytes() const { return deformer_.memory_bytes(); }

  // Times `repetitions` frames at the scene's pull (median), then measures the errors
  // of that frame and E_temporal over a drag of `drag_steps` small steps.
  Measurement measure(const Variant& v, int repetitions, int drag_steps);

  // The dense displacements of one frame of `v` at `pull`.
  Displacements frame(const Variant& v, const Eigen::Vector3d& pull);
  const LinkMesh& link_mesh(ValidRegionFrame f = ValidRegionFrame::axes) const
  {
    return links_[int(f)];
  }

private:
  // Runs one frame; returns the vertices whose displacement may be non-zero.
  const std::vector<index_t>& run(const Variant& v, const Eigen::Vector3d& pull);
  const Eigen::Vector3d& value(const Variant& v, index_t vertex) const;

  Scene scene_;
  ChainMailDeformer deformer_;
  LinkMesh links_[2]; // what the errors are measured on, one per frame
  // The passes after the frame, as the filter runs them (one per frame, so each keeps its
  // own ADMM factorisation).
  FramePasses passes_[2];
  std::vector<index_t> touched_; // the frame's vertices: moved, then the passes' beyond()
  Displacements reference_[2];
  ProjectionReport reference_report_[2];
  double reference_seconds_[2] = { 0.0, 0.0 };
  ProjectionReport last_;
};

double median(std::vector<double> v);
// Measurement::roughness of a dense configuration (O(n): for the report, not per frame).
double roughness(const LinkMesh& lm, const Displacements& u);

} // namespace geoshaping::report
