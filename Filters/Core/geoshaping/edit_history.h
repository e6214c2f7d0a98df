#pragma once
// Committed edits of a ChainMail deformer: commit on release, undo, redo, and a
// lossless text record per edit so a ParaView state file reproduces the shape bit-exactly.
#include "geoshaping/chainmail_deformer.h"

#include <Eigen/Core>

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace geoshaping
{

// What produced an edit (informational: replay uses the result, not the recipe, so a
// repainted malleability or changed curves never alter a replayed edit).
struct EditRecipe
{
  index_t grasp = -1;
  Eigen::Vector3d displacement = Eigen::Vector3d::Zero();
  int queue = int(QueueKind::fifo_priority);
  double stretch[2] = { 1.0, 2.0 }; // at m = 0, at m = 1
  double compression[2] = { 1.0, 0.5 };
  double shear[2] = { 0.0, 0.5 };
  int curve_shape = 0; // the filter's TransferCurveShape
  double step_threshold = 0.5;
  int refinement_iterations = 0;
};

// One edit: its recipe and its result, the vertices it moved with their displacements u
// (rest positions become x0 + u). Undo data (the previous rest positions and offsets) is
// filled when the edit is applied.
struct Edit
{
  EditRecipe recipe;
  std::vector<index_t> vertices;
  std::vector<Eigen::Vector3d> displacements;
  std::vector<Eigen::Vector3d> old_rest, old_offset;
  std::uint64_t hash = 0; // of its record
};

// The record of an edit, one line of ASCII:
//
//   GSE1 grasp dx dy dz queue s0 s1 c0 c1 h0 h1 shape threshold refinement count payload
//
// doubles as C99 hex floats (%a: exact), `payload` the base64 of `count` little-endian
// (int32 vertex, 3 x float64 u) = 28 bytes per moved vertex (~38 characters).
std::string encode_edit(const Edit& edit);
// False (with a reason) on a malformed record or a vertex outside [0, n).
bool decode_edit(const std::string& record, index_t n, Edit& edit, std::string& error);
std::uint64_t record_hash(const std::string& record); // FNV-1a 64

// A linear history: edits [0, applied()) are applied to the deformer, the rest can be
// redone. Every operation costs time in proportion to the vertices of the edits it
// applies or undoes, never the mesh size:
// - apply: for each vertex, keep (x0, offset), then x0 += u and offset += u — the same
//   additions as ChainMailDeformer::commit(), so a replay gives the same bits;
// - undo: restore the kept values (bit-exact).
class EditHistory
{
public:
  // Makes the given shape (the deformer's last frame: `vertices` moved by
  // `displacements` from rest, e.g. ChainMail plus refinement) the rest shape, as a new
  // edit after the applied ones (dropping the redo tail). Resets the frame first.
  const Edit& commit(ChainMailDeformer& deformer, const EditRecipe& recipe,
    const std::vector<index_t>& vertices, const std::vector<Eigen::Vector3d>& displacements);
  bool undo(ChainMailDeformer& deformer);
  bool redo(ChainMailDeformer& deformer);

  // Brings the applied edits to `records` with the least work: keeps the common prefix,
  // undoes the edits beyond it, then redoes kept edits whose record matches and decodes
  // the others. Stops at the first bad record (false, `error` says which; the edits
  // before it stay applied): a malformed one, or one after which `fits` (if given)
  // rejects a vertex it moved (e.g. a caller whose output cannot hold the position).
  bool synchronize(ChainMailDeformer& deformer, const std::vector<std::string>& records,
    std::string& error, const std::function<bool(index_t)>& fits = {});
  // Forgets every edit without touching the deformer (after set_mesh).
  void clear();

  std::size_t size() const { return edits_.size(); }
  std::size_t applied() const { return applied_; }
  const Edit& edit(std::size_t i) const { return edits_[i]; }
  std::string record(std::size_t i) const { return encode_edit(edits_[i]); }

  // Vertices whose rest position changed since the last call (repeats possible), for a
  // caller mirroring positions; clears the list.
  std::vector<index_t> take_touched();
  std::size_t memory_bytes() const;

private:
  void apply(ChainMailDeformer& deformer, Edit& edit);
  void revert(ChainMailDeformer& deformer, const Edit& edit);

  std::vector<Edit> edits_;
  std::size_t applied_ = 0;
  std::vector<index_t> touched_;
};

} // namespace geoshaping
