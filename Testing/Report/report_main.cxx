// The error-against-run-time report (issue 5, DESIGN.md section 6): every variant (four
// queues x refinement 0, 1, 2, 4, 8, 16) on four scenes, the paper's Table 1 with the
// BFS floor, memory per vertex, and the optional CGAL ARAP peer. Writes CSVs, the
// per-vertex dumps behind the Figure 6 and 8 pictures, and report.md into the output
// directory; plot_report.py draws the PNGs. Run through run-report.sh.
#include "report_measure.h"
#include "report_peer.h"
#include "report_table1.h"
#include "report_write.h"

#include <cstdio>
#include <cstring>
#include <string>

using namespace geoshaping;
using namespace geoshaping::report;

int main(int argc, char** argv)
{
  Options o;
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    if (a == "--out" && i + 1 < argc)
      o.out = argv[++i];
    else if (a == "--cfm" && i + 1 < argc)
      o.cfm = argv[++i];
    else if (a == "--smoke")
      o.smoke = true;
    else
    {
      std::fprintf(stderr, "usage: %s --out DIR [--cfm FILE.ts] [--smoke]\n", argv[0]);
      return 2;
    }
  }
  const double scale = o.smoke ? 0.4 : 1.0;
  const int repetitions = o.smoke ? 3 : 9, drag_steps = o.smoke ? 6 : 24;
  const int reference_sweeps = o.smoke ? 2000 : o.reference_sweeps;

  std::vector<Scene> scenes;
  scenes.push_back(fault_step_scene(scale));
  scenes.push_back(equal_malleability_scene(scale));
  if (!o.cfm.empty())
  {
    Scene cfm = cfm_scene(o.cfm);
    if (cfm.xyz.empty())
      std::fprintf(stderr, "[report] CFM scene left out: %s\n", cfm.note.c_str());
    else
      scenes.push_back(std::move(cfm));
  }
  scenes.push_back(tet_slab_scene(scale));

  Results results;
  const int sweeps[6] = { 0, 1, 2, 4, 8, 16 };
  const std::size_t total = scenes.size() * 24;
  std::size_t done = 0;
  for (Scene& scene : scenes)
  {
    std::fprintf(stderr, "[report] %s: %s; reference (Dykstra, cap %d sweeps) ...\n",
      scene.title.c_str(), scene.note.c_str(), reference_sweeps);
    SceneBench bench(std::move(scene), reference_sweeps);
    const ProjectionReport& ref = bench.reference_report();
    std::fprintf(stderr, "[report]   reference: %d sweeps, %.2f s, violation %.2e L, %s\n",
      ref.iterations, bench.reference_seconds(), ref.violation,
      ref.converged ? "converged" : "NOT converged (capped)");
    SceneResult sr;
    sr.scene = bench.scene();
    sr.reference = ref;
    sr.reference_seconds = bench.reference_seconds();
    sr.bytes_per_vertex = double(bench.deformer_bytes()) / double(sr.scene.xyz.size() / 3);
    for (int q = 0; q < 4; ++q)
      for (int s : sweeps)
      {
        const Variant v{ QueueKind(q), s };
        sr.rows.push_back({ v, bench.measure(v, repetitions, drag_steps) });
        const Measurement& m = sr.rows.back().second;
        std::fprintf(stderr,
          "[report %3zu/%zu] %-28s %-13s refine %2d: %8.3f ms  E_rigid %.3g  E_link %.3g  "
          "E_temporal %.3g  E_ref %.3g\n",
          ++done, total, sr.scene.title.c_str(), queue_name(v.queue), s, m.median_ms, m.e_rigid,
          m.e_link, m.e_temporal, m.e_ref.max);
      }
    write_dumps(o, bench);
    results.scenes.push_back(std::move(sr));
  }

  std::fprintf(stderr, "[report] Table 1 on a painted %dx%d grid ...\n", o.smoke ? 200 : 400,
    o.smoke ? 200 : 400);
  results.table1 = run_table1(o.smoke ? 200 : 400, o.smoke ? 3 : 15, true);
  std::fprintf(stderr, "[report] ARAP peer ...\n");
  results.peer = run_peer(results.scenes.front().scene, o.smoke);
  std::fprintf(stderr, "[report] %s\n", results.peer.note.c_str());
  write_results(o, results);
  std::fprintf(stderr, "[report] wrote %s/report.md, report.csv, table1.csv\n", o.out.c_str());
  return 0;
}
