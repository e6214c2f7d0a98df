#include "report_scale.h"

#include "report_measure.h"

#include "bench_scenes.h"

#include <chrono>
#include <cstdio>
#include <memory>

namespace geoshaping::report
{

Scene table1_scene(int side, std::size_t target)
{
  Scene s;
  auto mesh = bench::painted_grid(side, s.malleability);
  s.key = "table1_grid";
  s.title = "Table 1 grid";
  s.xyz = mesh.xyz;
  s.adjacency = std::move(mesh.adjacency);
  // The triangles of testing::triangle_grid: (a, c, d) and (a, d, e) per grid square.
  for (index_t j = 0; j + 1 < side; ++j)
    for (index_t i = 0; i + 1 < side; ++i)
    {
      const index_t a = j * side + i, c = a + 1, d = a + side + 1, e = a + side;
      s.triangles.insert(s.triangles.end(), { a, c, d, a, d, e });
    }
  s.grasp = (side / 2) * side + side / 2;
  ChainMailDeformer d;
  d.set_mesh(s.xyz.data(), index_t(s.xyz.size() / 3), s.adjacency);
  d.set_malleability(s.malleability.data());
  s.pull = Eigen::Vector3d(0.0, 0.0, bench::pull_for_count(d, s.grasp, target));
  s.note = "painted " + std::to_string(side) + "x" + std::to_string(side) +
           " triangle grid of Table 1, centre grasp pulled up until FIFO Priority displaces " +
           std::to_string(target);
  return s;
}

namespace
{
double ms_since(std::chrono::steady_clock::time_point t)
{
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t).count();
}
} // namespace

ScaleResult run_scale(const Scene& scene, int repetitions)
{
  ScaleResult r;
  ChainMailDeformer d;
  d.set_mesh(scene.xyz.data(), index_t(scene.xyz.size() / 3), scene.adjacency);
  d.set_malleability(scene.malleability.data());
  d.set_queue(QueueKind::fifo_priority);
  const LinkMesh lm = link_mesh(d);
  LinkProjector projector(lm);
  struct Setting
  {
    std::string name;
    ProjectionOptions options;
    bool cold = false; // a fresh projector each time: the envelope's link cache is empty
  };
  std::vector<Setting> settings;
  {
    ProjectionOptions o;
    o.solver = ProjectionSolver::envelope;
    o.tolerance = 1e-6;
    o.max_iterations = 1;
    settings.push_back({ "Envelope", o });
    settings.push_back({ "Envelope, first call", o, true });
  }
  for (int n : { 1, 4, 16, 64 })
  {
    ProjectionOptions o;
    o.solver = ProjectionSolver::dykstra;
    o.max_iterations = n;
    settings.push_back({ "Dykstra " + std::to_string(n), o });
  }
  for (int n : { 4, 16, 64 }) // 256 left out: 2,045x the frame for 0.91 L in the last run
  {
    ProjectionOptions o;
    o.tolerance = 1e-6;
    o.max_iterations = n;
    settings.push_back({ "ADMM " + std::to_string(n), o });
  }
  if (repetitions < 3) // a smoke run: the cheap settings only
    settings.resize(3);
  std::vector<std::vector<double>> ms(settings.size());
  std::vector<double> chainmail;
  r.rows.resize(settings.size());
  for (int rep = 0; rep < repetitions; ++rep)
  {
    auto t = std::chrono::steady_clock::now();
    r.displaced = d.deform(scene.grasp, scene.pull).moved;
    chainmail.push_back(ms_since(t));
    for (std::size_t k = 0; k < settings.size(); ++k)
    {
      // Another pull first, so the factorisation is never reused from the last frame.
      d.deform(scene.grasp, 0.5 * scene.pull);
      refine_links(projector, d, scene.grasp, settings[k].options);
      std::unique_ptr<LinkProjector> fresh;
      if (settings[k].cold) // allocated untimed, as a filter does once
        fresh = std::make_unique<LinkProjector>(lm);
      LinkProjector& used = fresh ? *fresh : projector;
      t = std::chrono::steady_clock::now();
      d.deform(scene.grasp, scene.pull);
      const ProjectionReport rep_k = refine_links(used, d, scene.grasp, settings[k].options);
      ms[k].push_back(ms_since(t));
      ScaleRow& row = r.rows[k];
      row.solver = settings[k].name;
      row.e_link = link_error(lm, used.displacements(), used.region());
      row.iterations = rep_k.iterations;
      row.factorisations = rep_k.factorisations;
      row.region = rep_k.region;
      std::fprintf(stderr, "[scale] %-16s %9.1f ms  E_link %.3g  %d iterations\n",
        row.solver.c_str(), ms[k].back(), row.e_link, row.iterations);
    }
  }
  d.deform(scene.grasp, scene.pull);
  r.e_link = link_error(lm, displacements(d), d.moved());
  r.chainmail_ms = median(chainmail);
  for (std::size_t k = 0; k < settings.size(); ++k)
    r.rows[k].ms = median(ms[k]);
  return r;
}

} // namespace geoshaping::report
