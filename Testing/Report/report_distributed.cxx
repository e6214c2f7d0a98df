#include "report_distributed.h"

#include "report_measure.h"
#include "test_pieces.h"

#include "geoshaping/metrics/error_metrics.h"
#include "geoshaping/parallel/partitioned_chainmail.h"

#include <chrono>
#include <cstdio>
#include <cstring>
#include <numeric>

namespace geoshaping::report
{
namespace
{

using geoshaping::testing::MeshPiece;

// A frame's output over the whole mesh: displacement and moved flag per vertex.
struct Gathered
{
  Displacements u;
  std::vector<std::uint8_t> moved;
};

struct Run
{
  std::vector<Gathered> frames;                       // the scene's pull, then the drag
  std::vector<double> ms;                             // the timed repetitions at the scene's pull
  std::vector<std::size_t> bytes, supersteps, rounds; // per frame (bytes: all pieces)
};

std::vector<Eigen::Vector3d> pulls(const Scene& s, int drag_steps)
{
  std::vector<Eigen::Vector3d> out{ s.pull };
  for (int k = 0; k < drag_steps; ++k) // report_measure.cxx's drag
    out.push_back(s.pull * (0.75 + 0.25 * k / std::max(1, drag_steps - 1)));
  return out;
}

double ms_since(std::chrono::steady_clock::time_point t)
{
  return 1e3 * std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

void setup(ChainMailDeformer& d, const std::vector<float>& malleability, ValidRegionFrame f)
{
  d.set_malleability(malleability.data());
  d.set_queue(QueueKind::fifo_priority);
  d.set_valid_region_frame(f);
}

Run run_whole(const Scene& s, ChainMailDeformer& d, const std::vector<std::int64_t>& gid,
  ValidRegionFrame f, int repetitions, int drag_steps)
{
  const index_t n = index_t(s.xyz.size() / 3);
  d.set_mesh(s.xyz.data(), n, s.adjacency);
  d.set_global_ids(gid.data());
  setup(d, s.malleability, f);
  Run run;
  for (int r = 0; r < repetitions; ++r)
  {
    const auto t = std::chrono::steady_clock::now();
    d.deform(s.grasp, s.pull);
    run.ms.push_back(ms_since(t));
  }
  for (const Eigen::Vector3d& pull : pulls(s, drag_steps))
  {
    d.deform(s.grasp, pull);
    Gathered g{ Displacements(std::size_t(n), Eigen::Vector3d::Zero()),
      std::vector<std::uint8_t>(std::size_t(n), 0) };
    for (index_t v : d.moved())
    {
      g.u[std::size_t(v)] = d.displacement(v);
      g.moved[std::size_t(v)] = 1;
    }
    run.frames.push_back(std::move(g));
    run.bytes.push_back(0);
    run.supersteps.push_back(0);
    run.rounds.push_back(0);
  }
  return run;
}

// Every piece in its own thread; each writes the vertices it owns into the gathered
// frames (one writer per vertex).
Run run_pieces(const Scene& s, std::vector<MeshPiece>& parts, std::int64_t grasp,
  ValidRegionFrame f, int repetitions, int drag_steps, std::string& error)
{
  const std::size_t n = s.xyz.size() / 3;
  const std::vector<Eigen::Vector3d> frames = pulls(s, drag_steps);
  Run run;
  run.frames.assign(frames.size(),
    Gathered{ Displacements(n, Eigen::Vector3d::Zero()), std::vector<std::uint8_t>(n, 0) });
  run.supersteps.assign(frames.size(), 0);
  run.rounds.assign(frames.size(), 0);
  std::vector<std::vector<std::size_t>> bytes(
    parts.size(), std::vector<std::size_t>(frames.size(), 0));
  std::vector<std::string> errors(parts.size());
  geoshaping::testing::run_in_pieces(int(parts.size()),
    [&](int p, Exchange& ex)
    {
      const MeshPiece& piece = parts[std::size_t(p)];
      ChainMailDeformer d;
      PartitionedChainMail pc(d);
      std::string& err = errors[std::size_t(p)];
      err = pc.set_piece(
        piece.xyz.data(), piece.size(), piece.adjacency, piece.gid.data(), piece.owned.data(), ex);
      if (!err.empty())
        return; // the same answer on every piece
      const std::vector<float> malleability = piece.gather(s.malleability);
      setup(d, malleability, f);
      for (int r = 0; r < repetitions; ++r)
      {
        const auto t = std::chrono::steady_clock::now();
        pc.deform(grasp, s.pull, ex);
        if (p == 0)
          run.ms.push_back(ms_since(t));
      }
      for (std::size_t i = 0; i < frames.size(); ++i)
      {
        const std::size_t before = ex.bytes_sent();
        const FrameResult r = pc.deform(grasp, frames[i], ex);
        if (!r.ok)
        {
          err = r.message;
          return;
        }
        bytes[std::size_t(p)][i] = ex.bytes_sent() - before;
        if (p == 0)
        {
          run.supersteps[i] = pc.supersteps();
          run.rounds[i] = pc.rounds();
        }
        for (index_t v = 0; v < piece.size(); ++v)
          if (piece.owned[std::size_t(v)] && d.moved_this_frame(v))
          {
            const std::size_t g = std::size_t(piece.global[std::size_t(v)]);
            run.frames[i].u[g] = d.displacement(v);
            run.frames[i].moved[g] = 1;
          }
      }
    });
  for (const std::string& e : errors)
    if (!e.empty())
      error = e;
  run.bytes.assign(frames.size(), 0);
  for (const auto& piece_bytes : bytes)
    for (std::size_t i = 0; i < frames.size(); ++i)
      run.bytes[i] += piece_bytes[i];
  return run;
}

bool same(const Run& a, const Run& b)
{
  if (a.frames.size() != b.frames.size())
    return false;
  for (std::size_t i = 0; i < a.frames.size(); ++i)
    if (a.frames[i].moved != b.frames[i].moved ||
        std::memcmp(a.frames[i].u.data(), b.frames[i].u.data(),
          a.frames[i].u.size() * sizeof(Eigen::Vector3d)) != 0)
      return false;
  return true;
}

// The errors of a run, measured on its gathered frames.
DistributedRow measure(const LinkMesh& lm, const Run& run, const std::vector<Eigen::Vector3d>& drag)
{
  DistributedRow row;
  const Displacements& u = run.frames.front().u;
  for (const Eigen::Vector3d& w : u)
    row.displaced += !w.isZero(0.0);
  row.e_rigid = rigid_error(lm, u);
  row.e_link = link_error(lm, u);
  TemporalError temporal(lm.size());
  std::vector<index_t> vertices;
  Displacements values;
  for (std::size_t i = 1; i < run.frames.size(); ++i)
  {
    vertices.clear();
    values.clear();
    for (std::size_t v = 0; v < run.frames[i].moved.size(); ++v)
      if (run.frames[i].moved[v])
      {
        vertices.push_back(index_t(v));
        values.push_back(run.frames[i].u[v]);
      }
    temporal.add_frame(drag[i], vertices, values);
  }
  row.e_temporal = temporal.value();
  row.supersteps = run.supersteps.front();
  row.rounds = run.rounds.front();
  row.bytes_per_frame =
    double(std::accumulate(run.bytes.begin() + 1, run.bytes.end(), std::size_t(0))) /
    double(std::max<std::size_t>(1, run.bytes.size() - 1));
  row.median_ms = median(run.ms);
  return row;
}

} // namespace

std::vector<DistributedRow> run_distributed(const Scene& s, int repetitions, int drag_steps)
{
  const index_t n = index_t(s.xyz.size() / 3);
  std::vector<std::int64_t> gid(static_cast<std::size_t>(n));
  std::iota(gid.begin(), gid.end(), std::int64_t(0));
  const std::vector<Eigen::Vector3d> drag = pulls(s, drag_steps);
  struct Partition
  {
    std::string name;
    int pieces;
    std::vector<int> owner;
  };
  std::vector<Partition> partitions;
  for (int k = 1; k <= 4; ++k)
    partitions.push_back({ k == 1 ? std::string("1 piece") : std::to_string(k) + " slabs", k,
      geoshaping::testing::striped_owner(s.xyz, k) });
  partitions.push_back({ "3 random", 3, geoshaping::testing::random_owner(n, { 0, 1, 2 }, 7) });

  std::vector<DistributedRow> rows;
  for (ValidRegionFrame f : { ValidRegionFrame::axes, ValidRegionFrame::link })
  {
    ChainMailDeformer whole;
    const Run reference = run_whole(s, whole, gid, f, repetitions, drag_steps);
    const LinkMesh lm = link_mesh(whole);
    DistributedRow one = measure(lm, reference, drag);
    one.frame = f;
    one.partition = "one process";
    one.pieces = 0;
    rows.push_back(one);
    for (Partition& partition : partitions)
    {
      std::vector<MeshPiece> parts =
        geoshaping::testing::split_mesh(s.xyz, s.adjacency, gid, partition.owner, partition.pieces);
      std::string error;
      const Run run =
        run_pieces(s, parts, gid[std::size_t(s.grasp)], f, repetitions, drag_steps, error);
      DistributedRow row;
      if (error.empty())
        row = measure(lm, run, drag);
      row.frame = f;
      row.partition = partition.name + (error.empty() ? "" : " (refused: " + error + ")");
      row.pieces = partition.pieces;
      row.identical = error.empty() && same(run, reference);
      rows.push_back(row);
    }
  }
  return rows;
}

bool all_identical(const std::vector<DistributedScene>& scenes)
{
  for (const DistributedScene& s : scenes)
    for (const DistributedRow& row : s.rows)
      if (!row.identical)
        return false;
  return true;
}

void write_distributed(std::ostream& md, const std::vector<DistributedScene>& scenes)
{
  if (scenes.empty())
    return;
  auto num = [](const char* f, double x)
  {
    char b[64];
    std::snprintf(b, sizeof b, f, x);
    return std::string(b);
  };
  md << "## On distributed data\n\n"
        "Each scene split into pieces with one ghost ring, as ParaView's distributed pipeline "
        "hands them to MPI ranks (slabs of equal width along x, and random owners), global ids "
        "= vertex ids; FIFO Priority run by the partitioned core (partitioned_chainmail.h) with "
        "one thread per piece exchanging through InProcessExchange (the stand-in for `mpiexec "
        "-n pieces`; on MPI the same core runs in vtkChainMailDeformationFilter, docs/mpi.md); "
        "every piece's owned displacements gathered and the errors measured on that gathered "
        "output. `identical`: every vertex's displacement and moved flag equal to the single "
        "process, bit for bit, at the pull and over the drag (the report exits with an error "
        "otherwise). Rounds: the synchronisations of that frame (a piece alone with the lowest "
        "key runs ahead while it has nothing to send; partitioned_chainmail.h). Bytes: frontier "
        "sent by all pieces per frame of the drag. ms: the frame at "
        "the pull, median, wall clock on piece 0, threads on this machine's cores (more pieces "
        "than cores share them).\n\n";
  md << "| scene | frame | partition | identical | displaced | E_rigid | E_link | E_temporal | "
        "supersteps | rounds | bytes/frame | ms "
        "|\n|---|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const DistributedScene& s : scenes)
    for (const DistributedRow& r : s.rows)
      md << "| " << s.title << " | " << frame_name(r.frame) << " | " << r.partition << " | "
         << (r.pieces == 0  ? "—"
              : r.identical ? "yes"
                            : "**NO**")
         << " | " << r.displaced << " | " << num("%.3g", r.e_rigid) << " | "
         << num("%.3g", r.e_link) << " | " << num("%.3g", r.e_temporal) << " | "
         << (r.pieces == 0 ? "—" : std::to_string(r.supersteps)) << " | "
         << (r.pieces == 0 ? "—" : std::to_string(r.rounds)) << " | "
         << (r.pieces == 0 ? "—" : num("%.0f", r.bytes_per_frame)) << " | "
         << num("%.3f", r.median_ms) << " |\n";
  md << "\n";
}

} // namespace geoshaping::report
