#pragma once
// The passes after a ChainMail frame (docs/deformer.md "Refinement" and "Relaxation"):
// refinement (LinkProjector) then relaxation (Relaxer), on one set of link data, and the
// frame's final shape read sparsely. A caller runs the deformer's frame, then refine()
// and/or relax(), then reads displacement(v) for the deformer's moved vertices and for
// beyond(), the vertices the passes moved outside that set.
//
//   start(refine) = the frame:          (moved, u_chainmail)
//   start(relax)  = the frame's shape:  (moved + beyond(), displacement(v))
//   displacement(v) = u_relax(v) if relax() ran since begin_frame(),
//                     else u_refine(v) if refine() ran, else u_chainmail(v)
//
// Invariants: beyond() holds each vertex once and none the frame moved; the refined ones
// come first in the projector's order, then those only the relaxation moved, in its
// order. After begin_frame() no pass result is read (displacement is the deformer's).
//
// Obstacles (the deformer's, docs/obstacles.md "The passes"): after each pass, every
// vertex it changed goes through the deformer's rule. A vertex whose straight path from
// rest to its pass result would cross an obstacle, or come closer than the clearance,
// moves to the last admissible point of that path (f u, f the admissible fraction); the
// members of a rigid set (rigid vertices joined by edges, pins and sliding vertices left
// out), which the refinement moves as one, all take the smallest f among them; a sliding
// vertex keeps its position from before the pass (on the obstacle). held_back() counts
// the vertices the gate moved. Without obstacles the passes are untouched.
//
// Cost: each pass is O(its region) per sweep (link_projection.h, relaxation.h), beyond()
// O(what the passes changed). The link data (O(mesh)) is built on the first pass and
// rebuilt only after invalidate() or when the deformer's transfer function changes;
// invalidate() when the deformer's malleability, pins or rest shape change.
#include "geoshaping/deform/chainmail_deformer.h"
#include "geoshaping/metrics/error_metrics.h"
#include "geoshaping/passes/link_projection.h"
#include "geoshaping/passes/relaxation.h"

#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

namespace geoshaping
{

class FramePasses
{
public:
  FramePasses() = default;
  FramePasses(const FramePasses&) = delete; // the passes hold references to links_
  FramePasses& operator=(const FramePasses&) = delete;

  // The link data no longer matches the deformer (malleability, pins or rest changed):
  // the passes' results go with it (a new frame begins) and the data is rebuilt on the
  // next pass.
  void invalidate()
  {
    begin_frame();
    projector_.reset();
    relaxer_.reset();
  }
  // A new frame: forgets the passes' results (the lists stay until the next pass).
  void begin_frame();

  // Refinement from the deformer's frame (refine_links): grasp and pins fixed.
  ProjectionReport refine(
    const ChainMailDeformer& deformer, index_t grasp, const ProjectionOptions& options);
  // Refinement computed by `run` on this frame's link data, which leaves its result in
  // the projector (LinkProjector::assign): the partitioned envelope (docs/mpi.md).
  ProjectionReport refine_with(const ChainMailDeformer& deformer,
    const std::function<ProjectionReport(const LinkMesh&, LinkProjector&)>& run);
  // Relaxation from the frame's shape so far (after refine() if it ran this frame):
  // grasp, pins and rigid vertices fixed, links kept in the deformer's valid-region shape.
  RelaxationReport relax(
    const ChainMailDeformer& deformer, index_t grasp, const RelaxationOptions& options);

  bool refined() const { return refining_; }
  bool relaxed() const { return relaxing_; }
  // Displacement of v from rest in the frame's final shape.
  const Eigen::Vector3d& displacement(const ChainMailDeformer& deformer, index_t v) const
  {
    return relaxing_   ? relaxer_->displacement(v)
           : refining_ ? projector_->displacement(v)
                       : deformer.displacement(v);
  }
  // Vertices the passes of this frame moved that the frame did not (see above).
  const std::vector<index_t>& beyond() const { return beyond_; }
  // What each pass of this frame changed (empty when it did not run).
  std::size_t refined_count() const { return refining_ ? projector_->changed().size() : 0; }
  std::size_t relaxed_count() const { return relaxing_ ? relaxer_->changed().size() : 0; }
  // Vertices the obstacle gate held back in this frame's passes (both passes counted).
  std::size_t held_back() const { return held_back_; }

  // The frame's final shape, sparsely: the deformer's moved vertices, then beyond(), with
  // their displacements (parallel arrays).
  void final_shape(
    const ChainMailDeformer& deformer, std::vector<index_t>& vertices, Displacements& values) const;

private:
  void ensure_links(const ChainMailDeformer& deformer);
  void add_beyond(const ChainMailDeformer& deformer, const std::vector<index_t>& changed);
  // The obstacle gate (above) on a pass's result; `before(v)` is v's displacement
  // before the pass.
  template<class Pass, class Before>
  void gate(const ChainMailDeformer& deformer, Pass& pass, Before before);

  LinkMesh links_;
  TransferFunction links_transfer_; // what links_ was built with
  std::unique_ptr<LinkProjector> projector_;
  std::unique_ptr<Relaxer> relaxer_;
  bool refining_ = false, relaxing_ = false;
  std::vector<index_t> beyond_;
  std::vector<std::uint8_t> in_beyond_; // dense mark of beyond_, cleared sparsely
  std::size_t held_back_ = 0;
  std::vector<std::uint8_t> gated_; // dense mark of the vertices the gate has seen
  std::vector<index_t> members_;    // scratch: one rigid set
};

} // namespace geoshaping
