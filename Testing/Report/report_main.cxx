// The error-against-run-time report (docs/design.md, Error against run time):
// every variant (queue x valid-region shape x refinement x relaxation, variants() below) on four
// scenes with its Pareto front of E_link against run time, the paper's Table 1 with the BFS floor,
// memory per vertex, the CGAL ARAP peer at the fault step's and at the paper's scale, and every
// scene on distributed data (split into 1-4 pieces, checked bit for bit against one process).
// Writes CSVs, the per-vertex dumps behind the Figure 6 and 8 pictures, and report.md
// into the output directory; plot_report.py draws the PNGs. Run through run-report.sh.
#include "report_measure.h"
#include "report_peer.h"
#include "report_table1.h"
#include "report_write.h"

#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>

using namespace geoshaping;
using namespace geoshaping::report;

namespace
{
// Every variant the report measures: one line per axis.
std::vector<Variant> variants()
{
  const QueueKind queues[] = { QueueKind::fifo, QueueKind::priority, QueueKind::fifo_priority,
    QueueKind::max_violation };
  const ValidRegionFrame frames[] = { ValidRegionFrame::axes, ValidRegionFrame::link };
  // Trimmed to keep the run near 10 minutes: Dykstra 4 and ADMM 4 (between their
  // neighbours on every front of the last run) are left out; the envelope is Axes only
  // (with the Link region it runs Dykstra); the relaxation (RelaxationIterations 16, tens of
  // times the ChainMail frame) is measured on FIFO Priority, the default queue, after no
  // refinement and after the envelope.
  const std::pair<Refinement, int> refinements[] = { { Refinement::none, 0 },
    { Refinement::dykstra, 1 }, { Refinement::dykstra, 16 }, { Refinement::admm, 16 },
    { Refinement::admm, 64 }, { Refinement::envelope, 1 } };
  const int relaxation = 16;
  std::vector<Variant> list;
  for (QueueKind q : queues)
    for (ValidRegionFrame f : frames)
      for (const auto& [refinement, iterations] : refinements)
      {
        if (refinement == Refinement::envelope && f != ValidRegionFrame::axes)
          continue;
        list.push_back({ q, f, refinement, iterations, 0 });
        if (q == QueueKind::fifo_priority &&
            (refinement == Refinement::none || refinement == Refinement::envelope))
          list.push_back({ q, f, refinement, iterations, relaxation });
      }
  return list;
}
} // namespace

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
  const auto started = std::chrono::steady_clock::now();
  const double scale = o.smoke ? 0.4 : 1.0;
  const int repetitions = o.smoke ? 3 : 9, drag_steps = o.smoke ? 6 : 24;
  const int reference_iterations = o.smoke ? 300 : o.reference_iterations;

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
  const std::vector<Variant> list = variants();
  const std::size_t total = scenes.size() * list.size();
  std::size_t done = 0;
  for (Scene& scene : scenes)
  {
    std::fprintf(stderr, "[report] %s: %s; references (ADMM to %.0e L, cap %d) ...\n",
      scene.title.c_str(), scene.note.c_str(), o.reference_tolerance, reference_iterations);
    SceneBench bench(std::move(scene), o.reference_tolerance, reference_iterations);
    SceneResult sr;
    sr.scene = bench.scene();
    for (ValidRegionFrame f : { ValidRegionFrame::axes, ValidRegionFrame::link })
    {
      const ProjectionReport& ref = bench.reference_report(f);
      std::fprintf(stderr, "[report]   %s reference: %d iterations, %.2f s, violation %.2e L, %s\n",
        frame_name(f), ref.iterations, bench.reference_seconds(f), ref.violation,
        ref.converged ? (ref.finish_iterations > 0 ? "converged after the finish" : "converged")
                      : "NOT converged (capped)");
      sr.reference[int(f)] = ref;
      sr.reference_seconds[int(f)] = bench.reference_seconds(f);
    }
    sr.bytes_per_vertex = double(bench.deformer_bytes()) / double(sr.scene.xyz.size() / 3);
    for (const Variant& v : list)
    {
      sr.rows.push_back({ v, bench.measure(v, repetitions, drag_steps) });
      const Measurement& m = sr.rows.back().second;
      std::fprintf(stderr,
        "[report %3zu/%zu] %-22.22s %-46s: %8.3f ms  E_rigid %.3g  E_link %.3g  "
        "E_temporal %.3g  E_ref %.3g  roughness %.3g\n",
        ++done, total, sr.scene.title.c_str(), variant_name(v).c_str(), m.median_ms, m.e_rigid,
        m.e_link, m.e_temporal, m.e_ref.max, m.roughness);
    }
    write_dumps(o, bench);
    std::fprintf(
      stderr, "[report] %s split into 1-4 pieces (distributed) ...\n", sr.scene.title.c_str());
    results.distributed.push_back(
      { sr.scene.title, run_distributed(bench.scene(), repetitions, drag_steps) });
    results.scenes.push_back(std::move(sr));
  }

  std::fprintf(stderr, "[report] Table 1 on a painted %dx%d grid ...\n", o.smoke ? 200 : 400,
    o.smoke ? 200 : 400);
  results.table1 = run_table1(o.smoke ? 200 : 400, o.smoke ? 3 : 15, true);
  std::fprintf(stderr, "[report] ARAP peer on the fault step ...\n");
  results.peers.push_back(run_peer(results.scenes.front().scene, o.smoke));
  std::fprintf(stderr, "[report] %s\n", results.peers.back().note.c_str());
  std::fprintf(stderr, "[report] ARAP peer and refinement at the paper's scale ...\n");
  const Scene grid = table1_scene(o.smoke ? 200 : 400, o.smoke ? 9152 : 29241);
  results.peers.push_back(run_peer(grid, o.smoke));
  std::fprintf(stderr, "[report] %s\n", results.peers.back().note.c_str());
  results.scale = run_scale(grid, o.smoke ? 1 : 3);
  results.seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  write_results(o, results);
  std::fprintf(stderr, "[report] wrote %s/report.md, report.csv, table1.csv in %.0f s\n",
    o.out.c_str(), results.seconds);
  if (!all_identical(results.distributed))
  {
    std::fprintf(stderr, "[report] ERROR: a partitioned run differs from the single process "
                         "(report.md, \"On distributed data\")\n");
    return 1;
  }
  return 0;
}
