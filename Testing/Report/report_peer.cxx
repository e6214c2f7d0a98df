#include "report_peer.h"

#include "report_measure.h"

#include <chrono>

#ifdef GEOSHAPING_WITH_CGAL
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_deformation.h>
#endif

namespace geoshaping::report
{

#ifndef GEOSHAPING_WITH_CGAL
PeerResult run_peer(const Scene&, bool)
{
  PeerResult r;
  r.note = "Left out: CGAL was not found at configure time (find_package(CGAL QUIET); Debian "
           "libcgal-dev), so the ARAP peer was not built.";
  return r;
}
#else
PeerResult run_peer(const Scene& scene, bool smoke)
{
  using Kernel = CGAL::Simple_cartesian<double>;
  using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
  using Vertex = Mesh::Vertex_index;
  using Deformation = CGAL::Surface_mesh_deformation<Mesh>; // ARAP, spokes and rims
  using clock = std::chrono::steady_clock;
  const auto ms = [](clock::time_point t)
  { return std::chrono::duration<double, std::milli>(clock::now() - t).count(); };
  PeerResult r;
  r.scene = scene.title;
  if (scene.triangles.empty())
  {
    r.note = "Left out: the scene has no triangles.";
    return r;
  }
  const index_t n = index_t(scene.xyz.size() / 3);
  Mesh mesh;
  std::vector<Vertex> vertex(static_cast<std::size_t>(n));
  for (index_t v = 0; v < n; ++v)
    vertex[v] = mesh.add_vertex(
      Kernel::Point_3(scene.xyz[3 * v], scene.xyz[3 * v + 1], scene.xyz[3 * v + 2]));
  for (std::size_t t = 0; t + 2 < scene.triangles.size(); t += 3)
    mesh.add_face(
      vertex[scene.triangles[t]], vertex[scene.triangles[t + 1]], vertex[scene.triangles[t + 2]]);

  // Region of interest: what ChainMail FIFO Priority displaces on the same pull.
  ChainMailDeformer chainmail;
  chainmail.set_mesh(scene.xyz.data(), n, scene.adjacency);
  chainmail.set_malleability(scene.malleability.data());
  chainmail.set_queue(QueueKind::fifo_priority);
  chainmail.deform(scene.grasp, scene.pull);
  const std::vector<index_t> roi = chainmail.moved();
  r.roi = roi.size();

  Deformation arap(mesh);
  auto t = clock::now();
  for (index_t v : roi)
    arap.insert_roi_vertex(vertex[v]);
  arap.insert_control_vertex(vertex[scene.grasp]);
  const bool ok = arap.preprocess();
  r.preprocess_ms = ms(t);
  if (!ok)
  {
    r.note = "CGAL ARAP preprocess failed (singular system); peer left out.";
    return r;
  }
  r.iterations = 5;
  const int frames = smoke ? 3 : 9;
  std::vector<double> peer, ours;
  const double* x0 = &scene.xyz[3 * std::size_t(scene.grasp)];
  for (int f = 0; f < frames; ++f)
  {
    const Eigen::Vector3d pull = scene.pull * (0.9 + 0.1 * f / frames);
    t = clock::now();
    arap.set_target_position(
      vertex[scene.grasp], Kernel::Point_3(x0[0] + pull.x(), x0[1] + pull.y(), x0[2] + pull.z()));
    arap.deform(r.iterations, 0.0);
    peer.push_back(ms(t));
    t = clock::now();
    chainmail.deform(scene.grasp, pull);
    ours.push_back(ms(t));
  }
  r.frame_ms = median(peer);
  r.chainmail_ms = median(ours);
  r.ran = true;
  r.note = "CGAL " CGAL_STR(CGAL_VERSION) " Surface_mesh_deformation (ARAP, spokes and rims, "
                                          "Eigen solver) on the " +
           scene.title +
           ": same mesh, handle = the grasp, region of "
           "interest = the vertices ChainMail FIFO Priority displaces (outside it fixed); " +
           std::to_string(r.iterations) +
           " ARAP iterations per frame (CGAL's default), median of " + std::to_string(frames) +
           " frames, in the same run as ChainMail.";
  return r;
}
#endif

} // namespace geoshaping::report
