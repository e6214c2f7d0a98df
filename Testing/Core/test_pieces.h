#pragma once
// A whole mesh split into pieces as ParaView's distributed pipeline hands them to ranks
// (partitioned_chainmail.h): each piece holds the vertices it owns and one ring of
// ghosts, every vertex with its global id. Shared by the partitioned tests and the
// report's distributed section; O(pieces x n log n), for tests only.
#include "geoshaping/mesh/adjacency.h"
#include "geoshaping/parallel/in_process_exchange.h"
#include "geoshaping/parallel/partitioned_chainmail.h"
#include "test_meshes.h"

#include <cstdint>
#include <functional>
#include <vector>

namespace geoshaping::testing
{

struct MeshPiece
{
  std::vector<index_t> global; // local -> whole-mesh vertex
  std::vector<double> xyz;
  Adjacency adjacency; // local ids
  std::vector<std::int64_t> gid;
  std::vector<std::uint8_t> owned;

  index_t size() const { return index_t(global.size()); }
  // The piece's values of a per-vertex array of the whole mesh.
  template<class T>
  std::vector<T> gather(const std::vector<T>& whole) const
  {
    std::vector<T> out;
    out.reserve(global.size());
    for (index_t v : global)
      out.push_back(whole[std::size_t(v)]);
    return out;
  }
};

// Which links a piece keeps between two ghosts: all of the whole mesh's, or none (only
// links with an owned end, as a layer of ghost cells around the owned ones would give
// for lines).
enum class GhostLinks
{
  all,
  to_owned
};

// Piece p holds the vertices whose owner is p, their neighbours (the ghost ring) and
// extra[p] (more ghosts), in a shuffled local order (seeded), each row of its adjacency
// sorted.
std::vector<MeshPiece> split_mesh(const std::vector<double>& xyz, const Adjacency& adjacency,
  const std::vector<std::int64_t>& gid, const std::vector<int>& owner, int pieces,
  const std::vector<std::vector<index_t>>& extra = {}, unsigned seed = 1,
  GhostLinks links = GhostLinks::all);

// The partitioned tests' meshes: malleability, pins and global ids painted on a mesh.
struct PaintedMesh
{
  Mesh mesh;
  std::vector<float> malleability;
  std::vector<std::uint8_t> pins;
  std::vector<std::int64_t> gid; // not the vertex ids: shuffled, sparse and large
};
// A random permutation of 0 .. n - 1, made sparse and large: 3 id + 1000000007.
std::vector<std::int64_t> shuffled_ids(index_t n, unsigned seed);
// A jittered triangle grid painted in bands (0.2 ... 0.9), a rigid (0) 6 x 5 block at
// (nx / 3, ny / 2) and a wall of pins along row ny / 4.
PaintedMesh painted_grid(index_t nx, index_t ny);
// A tetrahedral slab, UTM-sized (5e5 + ...): a jittered nx x ny x nz lattice cut into six
// tetrahedra per cube, malleability in quarters at random, one pin at (nx / 2, 1, 0).
PaintedMesh tet_slab(index_t nx, index_t ny, index_t nz);

// A piece with the pins and malleability of its vertices.
struct PaintedPiece : MeshPiece
{
  std::vector<std::uint8_t> pins;
  std::vector<float> malleability;
};
std::vector<PaintedPiece> split(const PaintedMesh& m, const std::vector<int>& owner, int pieces,
  const std::vector<std::vector<index_t>>& extra = {}, unsigned seed = 1,
  GhostLinks links = GhostLinks::all);

// Owners by slabs of equal width along x (a spatial partition, like ParaView's
// RedistributeDataSet in one direction).
std::vector<int> striped_owner(const std::vector<double>& xyz, int pieces);
// Each vertex owned by a random one of `choices`.
std::vector<int> random_owner(index_t n, const std::vector<int>& choices, unsigned seed);

// The tests' stand-in for mpiexec -n pieces (in_process_exchange.h).
using geoshaping::run_in_pieces;

} // namespace geoshaping::testing
