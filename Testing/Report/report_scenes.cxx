#include "report_scenes.h"

#include "geoshaping/metrics/error_metrics.h"
#include "geoshaping/scenes/sample_scenes.h"
#include "test_meshes.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkGocadTSurfReader.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <cmath>
#include <limits>

namespace geoshaping::report
{

index_t nearest_vertex(const std::vector<double>& xyz, const Eigen::Vector3d& p)
{
  index_t best = 0;
  double best_d = std::numeric_limits<double>::infinity();
  for (index_t v = 0; v < index_t(xyz.size() / 3); ++v)
  {
    const double d =
      (Eigen::Vector3d(xyz[3 * v], xyz[3 * v + 1], xyz[3 * v + 2]) - p).squaredNorm();
    if (d < best_d)
    {
      best_d = d;
      best = v;
    }
  }
  return best;
}

namespace
{
FaultStepParams fault_params(double scale, double spacing)
{
  FaultStepParams p;
  p.length = 100.0 * scale;
  p.width = 60.0 * scale;
  p.throw_height = 20.0 * scale;
  p.step_run = 6.0 * scale;
  p.thickness = 6.0 * scale;
  p.spacing = spacing; // a smaller scale means fewer vertices
  return p;
}

// Grasp on the red lower flat beyond the white border; the pull reaches the black step
// through the border, which is where plain FIFO lets soft vertices sponsor rigid ones.
void grasp_beyond_the_step(Scene& s, const FaultStepParams& p)
{
  const double border = 6.0 * p.length / 100.0;
  const double x = p.step_position * p.length + 0.5 * p.step_run + 2.0 * border;
  s.grasp = nearest_vertex(s.xyz, p.origin + Eigen::Vector3d(x, 0.5 * p.width, 0.0));
  s.pull = Eigen::Vector3d(-2.0, 1.0, 10.0) * (p.length / 100.0);
}
} // namespace

Scene fault_step_scene(double scale)
{
  const FaultStepParams p = fault_params(scale, 1.0);
  const SampleMesh mesh = fault_step_horizon(p);
  Scene s;
  s.key = "fault_step";
  s.title = "Fault-step horizon (Figure 5)";
  s.xyz = mesh.xyz;
  s.triangles = mesh.connectivity;
  s.adjacency = mesh.adjacency();
  s.malleability = fault_step_malleability(mesh, p, 6.0 * scale);
  s.note = "fault_step_horizon, " + std::to_string(mesh.num_points()) +
           " vertices: red 0.4, a white border of 6 m, the step black (fault_step_malleability)";
  grasp_beyond_the_step(s, p);
  return s;
}

Scene tet_slab_scene(double scale)
{
  FaultStepParams p = fault_params(scale * 0.6, 2.0);
  p.layers = 3;
  const SampleMesh mesh = fault_step_slab(p);
  Scene s;
  s.key = "tet_slab";
  s.title = "Tetrahedral fault-step slab";
  s.xyz = mesh.xyz;
  s.adjacency = mesh.adjacency();
  s.malleability = fault_step_malleability(mesh, p, 6.0 * scale * 0.6);
  s.note = "fault_step_slab, " + std::to_string(mesh.num_points()) + " vertices, " +
           std::to_string(mesh.num_cells()) + " tetrahedra, painted as the horizon";
  grasp_beyond_the_step(s, p);
  s.grasp = nearest_vertex(s.xyz, Eigen::Vector3d(s.xyz[3 * s.grasp], s.xyz[3 * s.grasp + 1], 0.0));
  return s;
}

Scene equal_malleability_scene(double scale)
{
  const index_t side = index_t(std::lround(81 * scale)) | 1;
  auto mesh = testing::triangle_grid(side, side, 1.0);
  Scene s;
  s.key = "equal_malleability";
  s.title = "Equal malleability 0.5 (Figure 8)";
  s.xyz = mesh.xyz;
  s.adjacency = std::move(mesh.adjacency);
  s.malleability.assign(std::size_t(side) * side, 0.5f);
  s.grasp = (side / 2) * side + side / 2;
  s.pull = Eigen::Vector3d(1.0, 0.5, 12.0) * scale;
  s.note = std::to_string(side) + "x" + std::to_string(side) + " triangle grid, malleability 0.5";
  return s;
}

Scene cfm_scene(const std::string& path)
{
  Scene s;
  s.key = "cfm_fault";
  vtkNew<vtkGocadTSurfReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  vtkPolyData* pd = vtkPolyData::SafeDownCast(reader->GetOutputDataObject(0));
  if (!pd || pd->GetNumberOfPoints() < 3)
  {
    s.note = "could not read " + path;
    return s;
  }
  const std::string file = path.substr(path.find_last_of('/') + 1);
  s.title = "CFM fault " + file.substr(0, file.find('.'));
  const index_t n = index_t(pd->GetNumberOfPoints());
  s.xyz.resize(3 * std::size_t(n));
  for (index_t v = 0; v < n; ++v)
    pd->GetPoint(v, &s.xyz[3 * std::size_t(v)]);
  AdjacencyBuilder builder(n);
  auto cells = vtk::TakeSmartPointer(pd->GetPolys()->NewIterator());
  for (cells->GoToFirstCell(); !cells->IsDoneWithTraversal(); cells->GoToNextCell())
  {
    vtkIdType count;
    const vtkIdType* ids;
    cells->GetCurrentCell(count, ids);
    std::vector<std::int64_t> id64(ids, ids + count);
    builder.add_cell(CellKind::polygon, id64.data(), count);
  }
  s.adjacency = builder.build();

  // Malleability 0.6 with a rigid disc (radius 3 mean edges) 5 mean edges from the grasp.
  std::vector<Eigen::Vector3d> rest(static_cast<std::size_t>(n));
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e300), hi = -lo;
  for (index_t v = 0; v < n; ++v)
  {
    rest[v] = Eigen::Vector3d(s.xyz[3 * v], s.xyz[3 * v + 1], s.xyz[3 * v + 2]);
    lo = lo.cwiseMin(rest[v]);
    hi = hi.cwiseMax(rest[v]);
  }
  const double edge = mean_edge_length(rest, s.adjacency);
  s.grasp = nearest_vertex(s.xyz, 0.5 * (lo + hi));
  const index_t* first = s.adjacency.begin(s.grasp);
  const Eigen::Vector3d dir = (rest[*first] - rest[s.grasp]).normalized();
  const Eigen::Vector3d disc = rest[s.grasp] + 5.0 * edge * dir;
  s.malleability.assign(std::size_t(n), 0.6f);
  index_t rigid = 0;
  for (index_t v = 0; v < n; ++v)
    if ((rest[v] - disc).norm() <= 3.0 * edge)
    {
      s.malleability[v] = 0.0f;
      ++rigid;
    }
  s.pull = Eigen::Vector3d(0.0, 0.0, 6.0 * edge);
  s.note = file + " (CRESCENT CFM, CC BY 4.0), " + std::to_string(n) + " vertices in UTM metres, " +
           "malleability 0.6 with a rigid disc of " + std::to_string(rigid) +
           " vertices; pull 6 mean edges up";
  return s;
}

} // namespace geoshaping::report
