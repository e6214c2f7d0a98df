#pragma once
// Output of the report: CSVs, per-vertex dumps for the pictures, and report.md.
#include "report_distributed.h"
#include "report_measure.h"
#include "report_peer.h"
#include "report_scale.h"
#include "report_table1.h"

#include <string>
#include <utility>
#include <vector>

namespace geoshaping::report
{

struct Options
{
  std::string out = "build/report";
  std::string cfm;
  bool smoke = false;
  double reference_tolerance = 1e-6; // L
  int reference_iterations = 5000;   // ADMM iterations
};

struct SceneResult
{
  Scene scene;
  ProjectionReport reference[2]; // per ValidRegionFrame
  double reference_seconds[2] = { 0.0, 0.0 };
  double bytes_per_vertex = 0.0;
  std::vector<std::pair<Variant, Measurement>> rows;
  const Measurement* find(const Variant& v) const;
  // Per row: on the Pareto front of (median_ms, E_link): no other row is at most as slow
  // and at most as wrong, and better in one.
  std::vector<bool> front() const;
};

struct Results
{
  std::vector<SceneResult> scenes;
  Table1 table1;
  std::vector<PeerResult> peers;             // the fault step, the Table 1 grid at 29,241
  ScaleResult scale;                         // refinement at 29,241
  std::vector<DistributedScene> distributed; // the scenes split into pieces
  double seconds = 0.0;                      // the report's run time
};

// Per-vertex CSVs behind the Figure 6 (fault step) and Figure 8 (equal malleability)
// pictures; other scenes write nothing.
void write_dumps(const Options& o, SceneBench& bench);
// report.csv, table1.csv and report.md.
void write_results(const Options& o, const Results& r);

} // namespace geoshaping::report
