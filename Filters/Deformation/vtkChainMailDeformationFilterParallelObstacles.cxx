// The obstacles of input port 1 on several processes (docs/obstacles.md, docs/mpi.md):
// each process holds a piece of every obstacle (possibly none); the pieces are gathered
// to every process, obstacle by obstacle and process by process, so every process's
// deformer holds the same triangles in the same order (and, when an obstacle comes
// whole from one process, the order one process would hold), built into its tree once
// per obstacle geometry. PartitionedChainMail then gates each owned vertex on its owner.
#include "vtkChainMailDeformationFilterInternals.h"

#include "geoshaping/mesh/bit_cast.h"
#include "geoshaping/parallel/exchange.h"

namespace
{
// True on every process when `ok` is true on every process.
bool Everywhere(geoshaping::Exchange& ex, bool ok)
{
  for (const auto& v : ex.all_gather({ ok ? 1 : 0 }))
    if (!v[0])
      return false;
  return true;
}
} // namespace

bool vtkChainMailDeformationFilter::UpdateObstaclesParallel(
  vtkPointSet* input, geoshaping::Exchange& ex)
{
  vtkInternals& state = *this->Internals;
  // The connections and the clearance are the pipeline's: the same on every process.
  const int count = this->GetNumberOfInputConnections(1);
  if (count == 0)
  {
    state.Deformer.clear_obstacles();
    state.ObstacleSources.clear();
    return Everywhere(ex, this->UpdateSliding(input));
  }
  std::vector<std::pair<vtkDataObject*, vtkMTimeType>> sources;
  if (!vtkChainMailDeformationFilterDetail::ObstacleSources(this, state.Deformer, sources))
    return false;
  if (!Everywhere(ex, sources == state.ObstacleSources && state.Deformer.obstacles()))
  {
    state.ObstacleSources.clear();
    state.Deformer.clear_obstacles();
    // This process's piece of each obstacle, then, per obstacle, what each process found:
    // (non-finite points or -1 when not a data set, triangles, whether its piece is empty).
    // An obstacle empty on every process is no obstacle (IsEmptyObstacle).
    std::vector<std::vector<double>> xyz(static_cast<std::size_t>(count));
    std::vector<std::vector<std::int64_t>> tri(static_cast<std::size_t>(count));
    std::vector<std::int64_t> found;
    for (int i = 0; i < count; ++i)
    {
      const auto k = std::size_t(i);
      found.push_back(
        vtkChainMailDeformationFilterDetail::AppendObstacle(sources[k].first, xyz[k], tri[k]));
      found.push_back(std::int64_t(tri[k].size() / 3));
      found.push_back(vtkChainMailDeformationFilterDetail::IsEmptyObstacle(sources[k].first));
    }
    const auto all = ex.all_gather(found);
    for (int i = 0; i < count; ++i)
    {
      std::int64_t bad = 0, triangles = 0, notData = -1, empty = 0;
      for (std::size_t p = 0; p < all.size(); ++p)
      {
        const std::int64_t b = all[p][3 * std::size_t(i)];
        notData = b < 0 && notData < 0 ? std::int64_t(p) : notData;
        bad += std::max<std::int64_t>(b, 0);
        triangles += all[p][3 * std::size_t(i) + 1];
        empty += all[p][3 * std::size_t(i) + 2];
      }
      if (empty == std::int64_t(all.size()))
        continue;
      if (notData >= 0)
        vtkErrorMacro("Obstacle " << i << " is not a vtkDataSet on process " << notData
                                  << "; output is the undeformed input.");
      else if (bad > 0)
        vtkErrorMacro("Obstacle " << i << " has " << bad
                                  << " points with non-finite coordinates (over all "
                                     "processes); output is the undeformed input.");
      else if (triangles == 0)
        vtkErrorMacro("Obstacle " << i
                                  << " has no triangles or polygons on any process; output is "
                                     "the undeformed input.");
      if (notData >= 0 || bad > 0 || triangles == 0)
        return false; // the same decision on every process
    }
    // Every piece to every process: per obstacle, points (bits) and triangles.
    std::vector<std::int64_t> mine;
    for (int i = 0; i < count; ++i)
    {
      const auto k = std::size_t(i);
      mine.push_back(std::int64_t(xyz[k].size() / 3));
      mine.push_back(std::int64_t(tri[k].size() / 3));
      for (double x : xyz[k])
        mine.push_back(geoshaping::bit_cast<std::int64_t>(x));
      mine.insert(mine.end(), tri[k].begin(), tri[k].end());
    }
    const auto pieces = ex.all_gather(mine);
    std::vector<std::size_t> at(pieces.size(), 0); // read position in each process's piece
    std::vector<double> points;
    std::vector<std::int64_t> triangles;
    for (int i = 0; i < count; ++i)
      for (std::size_t p = 0; p < pieces.size(); ++p)
      {
        const std::vector<std::int64_t>& piece = pieces[p];
        std::size_t& r = at[p];
        const auto np = std::size_t(piece[r]), nt = std::size_t(piece[r + 1]);
        r += 2;
        const auto base = std::int64_t(points.size() / 3);
        for (std::size_t j = 0; j < 3 * np; ++j)
          points.push_back(geoshaping::bit_cast<double>(piece[r + j]));
        r += 3 * np;
        for (std::size_t j = 0; j < 3 * nt; ++j)
          triangles.push_back(base + piece[r + j]);
        r += 3 * nt;
      }
    if (!triangles.empty() &&
        !vtkChainMailDeformationFilterDetail::SetObstacles(this, state.Deformer, points, triangles))
      return false;
    state.ObstacleSources = std::move(sources);
  }
  return Everywhere(ex, this->UpdateSliding(input));
}
