#pragma once
// Output of the report: CSVs, per-vertex dumps for the pictures, and report.md.
#include "report_measure.h"
#include "report_peer.h"
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
  int reference_sweeps = 20000;
};

struct SceneResult
{
  Scene scene;
  ProjectionReport reference;
  double reference_seconds = 0.0;
  double bytes_per_vertex = 0.0;
  std::vector<std::pair<Variant, Measurement>> rows;
  const Measurement* find(QueueKind q, int sweeps) const;
};

struct Results
{
  std::vector<SceneResult> scenes;
  Table1 table1;
  PeerResult peer;
};

// Per-vertex CSVs behind the Figure 6 (fault step) and Figure 8 (equal malleability)
// pictures; other scenes write nothing.
void write_dumps(const Options& o, SceneBench& bench);
// report.csv, table1.csv and report.md.
void write_results(const Options& o, const Results& r);

} // namespace geoshaping::report
