#pragma once
// Committed edits of a ChainMail deformer: commit on release, undo, redo, and a
// lossless text record per edit so a ParaView state file reproduces the shape bit-exactly.
#include "geoshaping/deform/chainmail_deformer.h"

#include <Eigen/Core>

#include <cstdint>
#include <functional>
#include <string>
#include <unordered_map>
#include <vector>

namespace geoshaping
{

class Exchange; // exchange.h

// Where the vertices a record names are (docs/editing.md, "Ids"). A record names vertices
// by global id (ChainMailDeformer::global_id), so it does not depend on how the mesh is
// split: on a piece of a partitioned mesh, an edit applies to the entries whose id the
// piece holds (owned or ghost), and commit gathers every piece's owned entries.
struct EditPlace
{
  // Appends this deformer's vertices that hold global id `id`: none when another piece
  // holds it, several for the copies of a point held twice. Empty: the ids are the
  // deformer's vertex indices (a whole mesh without global ids).
  std::function<void(std::int64_t id, std::vector<index_t>& holders)> holders;
  // The pieces' collectives when the mesh is split (every call is then collective);
  // null when this deformer holds the whole mesh.
  Exchange* exchange = nullptr;
};

// Global id -> vertex of a whole mesh (one process): built once per mesh, O(n); each
// lookup O(1). Without ids, or with ids that are not distinct, the ids are the vertex
// indices (place() has no holders).
class GlobalIdMap
{
public:
  void set(const std::int64_t* gid, index_t n);
  void clear() { local_.clear(); }
  bool empty() const { return local_.empty(); }
  // The vertex with global id `id`, -1 when none.
  index_t find(std::int64_t id) const
  {
    const auto it = local_.find(id);
    return it == local_.end() ? -1 : it->second;
  }
  EditPlace place() const;

private:
  std::unordered_map<std::int64_t, index_t> local_;
};

// What produced an edit (informational: replay uses the result, not the recipe, so a
// repainted malleability or changed curves never alter a replayed edit).
struct EditRecipe
{
  std::int64_t grasp = -1; // global id (GSE1: point index)
  Eigen::Vector3d displacement = Eigen::Vector3d::Zero();
  int queue = int(QueueKind::fifo_priority);
  double stretch[2] = { 1.0, 2.0 }; // at m = 0, at m = 1
  double compression[2] = { 1.0, 0.5 };
  double shear[2] = { 0.0, 0.5 };
  int curve_shape = 0; // the filter's TransferCurveShape
  double step_threshold = 0.5;
  int refinement_iterations = 0;
};

// One edit: its recipe and its result, the vertices it moved (by global id, every
// piece's) with their displacements u (rest positions become x0 + u). Where it applies on
// this deformer (`vertices`, each with its entry) and the undo data (the previous rest
// positions and offsets) are filled when the edit is placed and applied.
struct Edit
{
  EditRecipe recipe;
  int version = 2;                            // of its record: 1 = GSE1, 2 = GSE2
  std::vector<std::int64_t> ids;              // global ids (GSE2: increasing)
  std::vector<Eigen::Vector3d> displacements; // by entry
  std::vector<index_t> vertices;              // this deformer's vertices it moves
  std::vector<std::uint32_t> entries;         // the entry of each
  std::vector<Eigen::Vector3d> old_rest, old_offset;
  std::size_t owned = 0;  // entries an owned vertex here holds
  std::uint64_t hash = 0; // of its record
};

// The record of an edit, one line of ASCII:
//
//   GSE2 grasp dx dy dz queue s0 s1 c0 c1 h0 h1 shape threshold refinement count payload
//
// doubles as C99 hex floats (%a: exact), `payload` the base64 of `count` little-endian
// (int64 global id, 3 x float64 u), ids increasing = 32 bytes per moved vertex (~43
// characters); `grasp` is a global id. The same shape gives the same record whatever the
// partition. GSE1 (still read) is the same with int32 point indices (28 bytes).
std::string encode_edit(const Edit& edit);
// False (with a reason) on a malformed record (GSE2: ids not increasing, non-finite u).
// Fills recipe, version, ids and displacements.
bool decode_edit(const std::string& record, Edit& edit, std::string& error);
std::uint64_t record_hash(const std::string& record); // FNV-1a 64

// A linear history: edits [0, applied()) are applied to the deformer, the rest can be
// redone. Every operation costs time in proportion to the vertices of the edits it
// applies or undoes, never the mesh size (plus, on a partitioned mesh, one all-gather of
// the edit's entries per commit and one of three numbers per replayed record):
// - apply: for each vertex, keep (x0, offset), then x0 += u and offset += u — the same
//   additions as ChainMailDeformer::commit(), so a replay gives the same bits;
// - undo: restore the kept values (bit-exact).
class EditHistory
{
public:
  // Makes the given shape (the deformer's last frame: `vertices` moved by
  // `displacements` from rest, e.g. ChainMail plus refinement) the rest shape, as a new
  // edit after the applied ones (dropping the redo tail). Resets the frame first.
  // Partitioned (collective): the record's entries are every piece's owned (global id,
  // u), gathered and sorted by id, so every piece makes the same record; each applies the
  // entries it holds, owned or ghost (a ghost's u is its owner's, bit for bit).
  const Edit& commit(ChainMailDeformer& deformer, const EditRecipe& recipe,
    const std::vector<index_t>& vertices, const std::vector<Eigen::Vector3d>& displacements,
    const EditPlace& place = {});
  bool undo(ChainMailDeformer& deformer);
  bool redo(ChainMailDeformer& deformer);

  // Brings the applied edits to `records` with the least work: keeps the common prefix,
  // undoes the edits beyond it, then redoes kept edits whose record matches and decodes
  // the others. Stops at the first bad record (false, `error` says which; the edits
  // before it stay applied): a malformed one, one naming an id no vertex (no piece) owns,
  // or one after which `fits` (if given) rejects a vertex it moved (e.g. a caller whose
  // output cannot hold the position). Partitioned (collective): one agreement per
  // replayed record, so every piece stops at the same record with the same error.
  // A GSE1 record's ids are point indices on a whole mesh, global ids on a piece.
  bool synchronize(ChainMailDeformer& deformer, const std::vector<std::string>& records,
    std::string& error, const std::function<bool(index_t)>& fits = {}, const EditPlace& place = {});
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
  // Fills edit.vertices/entries/owned from its ids.
  static void locate(const ChainMailDeformer& deformer, Edit& edit, const EditPlace& place);
  // After the edit at applied_ - 1 was applied: true (same on every piece) when a piece
  // owns fewer of its ids than it has, or `fits` rejects a vertex; it is then undone
  // and dropped with the redo tail.
  bool refused(ChainMailDeformer& deformer, std::size_t i, const std::function<bool(index_t)>& fits,
    const EditPlace& place, std::string& error);
  void apply(ChainMailDeformer& deformer, Edit& edit);
  void revert(ChainMailDeformer& deformer, const Edit& edit);

  std::vector<Edit> edits_;
  std::size_t applied_ = 0;
  std::vector<index_t> touched_;
};

} // namespace geoshaping
