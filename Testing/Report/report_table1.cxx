#include "report_table1.h"

#include "report_measure.h"

#include "bench_scenes.h"

#include <chrono>
#include <cstdio>

namespace geoshaping::report
{

namespace
{
const std::size_t targets[5] = { 9152, 14088, 17289, 18225, 29241 };
const double paper[5][3] = { { 38, 46, 45 }, { 76, 96, 79 }, { 111, 130, 125 }, { 159, 164, 167 },
  { 195, 302, 298 } };

template<class F>
double time_ms(F f)
{
  const auto t = std::chrono::steady_clock::now();
  f();
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t).count();
}

double bytes_per_vertex(int side)
{
  std::vector<float> m;
  auto mesh = bench::painted_grid(side, m);
  ChainMailDeformer d;
  d.set_mesh(mesh.xyz.data(), mesh.size(), std::move(mesh.adjacency));
  d.set_malleability(m.data());
  d.deform((side / 2) * side + side / 2, { 0.0, 0.0, 20.0 });
  return double(d.memory_bytes()) / double(d.size());
}
} // namespace

Table1 run_table1(int side, int repetitions, bool progress)
{
  Table1 table;
  std::vector<float> m;
  auto mesh = bench::painted_grid(side, m);
  ChainMailDeformer d;
  d.set_mesh(mesh.xyz.data(), mesh.size(), std::move(mesh.adjacency));
  d.set_malleability(m.data());
  table.mesh_vertices = std::size_t(d.size());
  const index_t grasp = (side / 2) * side + side / 2;
  std::vector<std::uint32_t> mark(std::size_t(d.size()), 0);
  std::vector<index_t> queue;
  std::uint32_t stamp = 0;

  for (int t = 0; t < 5; ++t)
  {
    Table1Row row;
    row.target = targets[t];
    for (int q = 0; q < 3; ++q)
      row.paper_ms[q] = paper[t][q];
    const double pull = bench::pull_for_count(d, grasp, row.target);
    std::vector<double> ms[5];
    // Interleaved: every repetition runs each queue and the floor once, so drifts of
    // the machine's speed hit all variants alike.
    for (int r = 0; r < repetitions; ++r)
    {
      for (int q = 0; q < 4; ++q)
      {
        d.set_queue(QueueKind(q));
        ms[q].push_back(time_ms(
          [&] {
            row.displaced[q] = d.deform(grasp, { 0.0, 0.0, pull }).moved;
          }));
      }
      d.set_queue(QueueKind::fifo_priority);
      d.deform(grasp, { 0.0, 0.0, pull });
      const std::vector<std::uint8_t> region = bench::moved_mask(d);
      ms[4].push_back(
        time_ms([&] { bench::bfs_floor(d.adjacency(), grasp, region, mark, ++stamp, queue); }));
    }
    for (int q = 0; q < 4; ++q)
      row.ms[q] = median(ms[q]);
    row.bfs_ms = median(ms[4]);
    table.rows.push_back(row);
    if (progress)
      std::fprintf(stderr,
        "[table 1] %zu displaced: FIFO %.3f ms, Priority %.3f, FIFO Priority %.3f, BFS %.3f\n",
        row.displaced[2], row.ms[0], row.ms[1], row.ms[2], row.bfs_ms);
  }
  d.reset();
  table.bytes_per_vertex = double(d.memory_bytes()) / double(d.size());
  const int large = 1000;
  table.large_vertices = std::size_t(large) * large;
  table.large_bytes_per_vertex = bytes_per_vertex(large);
  return table;
}

} // namespace geoshaping::report
