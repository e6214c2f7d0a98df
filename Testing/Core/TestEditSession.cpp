// geoshaping::EditSession: the EditHistory list and its commands (docs/editing.md).
#include "geoshaping/edit/edit_session.h"
#include "geoshaping/parallel/in_process_exchange.h"
#include "geoshaping/parallel/partitioned_chainmail.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <array>
#include <cstring>
#include <map>
#include <thread>

using namespace geoshaping;
using geoshaping::testing::grid_id;

namespace
{
struct Scene
{
  geoshaping::testing::Mesh mesh = geoshaping::testing::triangle_grid(20, 20, 1.0);
  ChainMailDeformer deformer;
  EditSession session;
  Scene()
  {
    deformer.set_mesh(mesh.xyz.data(), mesh.size(), mesh.adjacency);
    deformer.set_uniform_malleability(0.8);
  }
  std::vector<Eigen::Vector3d> shape() const
  {
    std::vector<Eigen::Vector3d> x;
    for (index_t v = 0; v < deformer.size(); ++v)
      x.push_back(deformer.position(v));
    return x;
  }
  // Drags `grasp` by `d`, commits the frame, and returns the committed shape.
  std::vector<Eigen::Vector3d> commit(index_t grasp, const Eigen::Vector3d& d)
  {
    EXPECT_TRUE(deformer.deform(grasp, d).ok);
    std::vector<Eigen::Vector3d> u;
    for (index_t v : deformer.moved())
      u.push_back(deformer.displacement(v));
    EXPECT_TRUE(session.commit(deformer, EditRecipe(), deformer.moved(), u));
    deformer.reset();
    return shape();
  }
  void sync()
  {
    std::string error;
    EXPECT_TRUE(session.synchronize(deformer, error)) << error;
  }
};
} // namespace

TEST(EditSession, CommandsChangeTheListAndSynchronizeAppliesIt)
{
  Scene s;
  const auto rest = s.shape();
  const auto one = s.commit(grid_id(20, 10, 10), { 0.0, 0.0, 2.0 });
  ASSERT_EQ(s.session.records().size(), 1u);
  EXPECT_EQ(s.session.last_edit(), s.session.records()[0]);
  EXPECT_FALSE(s.session.pending()) << "a commit is applied at once";
  const auto two = s.commit(grid_id(20, 5, 5), { 1.0, 0.0, -1.0 });
  EXPECT_NE(one, two);

  EXPECT_TRUE(s.session.undo());
  EXPECT_TRUE(s.session.pending());
  EXPECT_EQ(s.session.redoable(), 1);
  s.sync();
  EXPECT_EQ(s.shape(), one);
  EXPECT_TRUE(s.session.redo());
  s.sync();
  EXPECT_EQ(s.shape(), two);
  EXPECT_EQ(s.session.last_edit(), s.session.records()[1]);
  EXPECT_TRUE(s.session.reset());
  s.sync();
  EXPECT_EQ(s.shape(), rest);
  EXPECT_EQ(s.session.redoable(), 2) << "reset keeps every edit redoable";
  EXPECT_FALSE(s.session.reset() || s.session.undo()) << "an empty list";

  // A commit after an undo drops the redo tail.
  EXPECT_TRUE(s.session.redo());
  s.sync();
  s.commit(grid_id(20, 15, 3), { 0.0, 1.0, 0.0 });
  EXPECT_EQ(s.session.redoable(), 0);
  EXPECT_FALSE(s.session.redo());
}

TEST(EditSession, ACommitWaitsForAPendingChangeOfTheList)
{
  Scene s;
  s.commit(grid_id(20, 10, 10), { 0.0, 0.0, 2.0 });
  s.session.undo();
  ASSERT_TRUE(s.deformer.deform(grid_id(20, 3, 3), { 0.0, 0.0, 1.0 }).ok);
  std::vector<Eigen::Vector3d> u(s.deformer.moved().size(), Eigen::Vector3d(0.0, 0.0, 1.0));
  EXPECT_FALSE(s.session.commit(s.deformer, EditRecipe(), s.deformer.moved(), u))
    << "the frame was computed on a rest shape the list no longer gives";
  EXPECT_TRUE(s.session.records().empty());
}

TEST(EditSession, AMeshSetAgainReplaysEveryRecordAndABadOneStopsTheReplay)
{
  Scene s;
  s.commit(grid_id(20, 10, 10), { 0.0, 0.0, 2.0 });
  const auto two = s.commit(grid_id(20, 5, 5), { 1.0, 0.0, -1.0 });
  s.deformer.set_mesh(s.mesh.xyz.data(), s.mesh.size(), s.mesh.adjacency);
  s.session.forget_applied();
  ASSERT_TRUE(s.session.pending());
  s.sync();
  EXPECT_EQ(s.shape(), two);

  Scene fresh;
  fresh.session.add(s.session.records()[0]);
  fresh.session.add("GSE1 junk");
  fresh.session.add(s.session.records()[1]);
  std::string error;
  EXPECT_FALSE(fresh.session.synchronize(fresh.deformer, error));
  EXPECT_FALSE(error.empty());
  Scene first;
  first.commit(grid_id(20, 10, 10), { 0.0, 0.0, 2.0 });
  EXPECT_EQ(fresh.shape(), first.shape()) << "the edit before the bad record is applied";
}

// ---- Edits on a partitioned mesh (docs/mpi.md, "Edits"): pieces run by threads
// exchanging through InProcessExchange, against the whole mesh given the same global ids.
namespace
{
constexpr index_t kSide = 24;

// Global ids: a shuffled, sparse numbering (not the vertex ids).
std::vector<std::int64_t> shuffled_ids(index_t n)
{
  std::vector<std::int64_t> gid(static_cast<std::size_t>(n));
  for (index_t v = 0; v < n; ++v)
    gid[std::size_t(v)] = 7 * std::int64_t((v * 37) % n) + 1000;
  return gid;
}

// A step of the script every piece (and the whole mesh) runs.
struct Step
{
  enum Kind
  {
    drag,
    commit,
    undo,
    redo,
    reset,
    add
  } kind;
  std::int64_t grasp = -1; // drag: a global id
  Eigen::Vector3d pull = Eigen::Vector3d::Zero();
  std::string record; // add
};

// What a run saw after each step: rest and offset (and the frame's displacement) by
// global id, and the session's last edit and list.
struct Trace
{
  std::vector<std::map<std::int64_t, std::array<Eigen::Vector3d, 3>>> shapes;
  std::vector<std::string> last, records, errors;
};

std::array<Eigen::Vector3d, 3> state_of(const ChainMailDeformer& d, index_t v)
{
  return { d.rest_local(v), d.committed_offset(v), d.displacement(v) };
}

// Runs the steps on one deformer (a whole mesh or a piece); `frame` deforms.
template<class Frame>
Trace run_steps(ChainMailDeformer& deformer, EditSession& session, const EditPlace& place,
  const std::vector<Step>& steps, const Frame& frame)
{
  Trace t;
  for (const Step& s : steps)
  {
    std::string error;
    switch (s.kind)
    {
      case Step::drag:
        EXPECT_TRUE(session.synchronize(deformer, error, {}, place)) << error;
        frame(s.grasp, s.pull);
        break;
      case Step::commit:
      {
        std::vector<Eigen::Vector3d> u;
        for (index_t v : deformer.moved())
          u.push_back(deformer.displacement(v));
        EditRecipe recipe;
        recipe.grasp = s.grasp;
        EXPECT_TRUE(session.commit(deformer, recipe, deformer.moved(), u, place));
        break;
      }
      case Step::undo:
        EXPECT_TRUE(session.undo());
        break;
      case Step::redo:
        EXPECT_TRUE(session.redo());
        break;
      case Step::reset:
        EXPECT_TRUE(session.reset());
        break;
      case Step::add:
        session.add(s.record);
        break;
    }
    if (s.kind != Step::drag && s.kind != Step::commit)
      session.synchronize(deformer, error, {}, place);
    t.errors.push_back(error);
    std::map<std::int64_t, std::array<Eigen::Vector3d, 3>> shape;
    for (index_t v = 0; v < deformer.size(); ++v)
      if (deformer.owned(v))
        shape[deformer.global_id(v)] = state_of(deformer, v);
    t.shapes.push_back(std::move(shape));
    t.last.push_back(session.last_edit());
    t.records.push_back(session.records().empty() ? "" : session.records().back());
  }
  return t;
}

Trace run_whole(const std::vector<Step>& steps)
{
  const auto mesh = geoshaping::testing::triangle_grid(kSide, kSide, 1.0);
  const auto gid = shuffled_ids(mesh.size());
  ChainMailDeformer deformer;
  deformer.set_mesh(mesh.xyz.data(), mesh.size(), mesh.adjacency);
  deformer.set_global_ids(gid.data());
  deformer.set_uniform_malleability(0.8);
  deformer.set_queue(QueueKind::fifo_priority);
  GlobalIdMap ids;
  ids.set(gid.data(), mesh.size());
  EditSession session;
  return run_steps(deformer, session, ids.place(), steps,
    [&](std::int64_t g, const Eigen::Vector3d& d)
    { EXPECT_TRUE(deformer.deform(ids.find(g), d).ok); });
}

// The grid split into `pieces` bands of columns (vertex i % kSide), each with its ghost ring.
std::vector<Trace> run_pieces(int pieces, const std::vector<Step>& steps)
{
  const auto mesh = geoshaping::testing::triangle_grid(kSide, kSide, 1.0);
  const auto gid = shuffled_ids(mesh.size());
  const auto owner = [&](index_t v) { return int((v % kSide) * pieces / kSide); };
  InProcessHub hub(pieces);
  std::vector<Trace> traces(static_cast<std::size_t>(pieces));
  std::vector<std::thread> threads;
  for (int p = 0; p < pieces; ++p)
    threads.emplace_back(
      [&, p]
      {
        std::vector<index_t> global;
        std::vector<index_t> local_of(static_cast<std::size_t>(mesh.size()), -1);
        for (index_t v = 0; v < mesh.size(); ++v)
        {
          bool held = owner(v) == p;
          for (const index_t* it = mesh.adjacency.begin(v); !held && it != mesh.adjacency.end(v);
               ++it)
            held = owner(*it) == p;
          if (held)
          {
            local_of[std::size_t(v)] = index_t(global.size());
            global.push_back(v);
          }
        }
        std::vector<double> xyz;
        std::vector<std::int64_t> ids;
        std::vector<std::uint8_t> owned;
        Adjacency adjacency;
        adjacency.offsets.push_back(0);
        for (index_t v : global)
        {
          xyz.insert(xyz.end(), &mesh.xyz[3 * std::size_t(v)], &mesh.xyz[3 * std::size_t(v)] + 3);
          ids.push_back(gid[std::size_t(v)]);
          owned.push_back(owner(v) == p);
          for (const index_t* it = mesh.adjacency.begin(v); it != mesh.adjacency.end(v); ++it)
            if (local_of[std::size_t(*it)] >= 0)
              adjacency.neighbors.push_back(local_of[std::size_t(*it)]);
          adjacency.offsets.push_back(std::int64_t(adjacency.neighbors.size()));
        }
        InProcessExchange ex(hub, p);
        ChainMailDeformer deformer;
        PartitionedChainMail partition(deformer);
        EXPECT_EQ(partition.set_piece(xyz.data(), index_t(global.size()), std::move(adjacency),
                    ids.data(), owned.data(), ex),
          "");
        deformer.set_uniform_malleability(0.8);
        deformer.set_queue(QueueKind::fifo_priority);
        EditPlace place;
        place.holders = [&partition](std::int64_t g, std::vector<index_t>& out)
        { partition.holders(g, out); };
        place.exchange = &ex;
        EditSession session;
        traces[std::size_t(p)] = run_steps(deformer, session, place, steps,
          [&](std::int64_t g, const Eigen::Vector3d& d)
          { EXPECT_TRUE(partition.deform(g, d, ex).ok); });
      });
  for (auto& t : threads)
    t.join();
  return traces;
}

// The pieces' owned states, joined, must be the whole mesh's at every step, bit for bit;
// every piece's list and last edit the whole mesh's text.
void expect_equal_to_whole(const std::vector<Trace>& pieces, const Trace& whole)
{
  for (std::size_t step = 0; step < whole.shapes.size(); ++step)
  {
    std::map<std::int64_t, std::array<Eigen::Vector3d, 3>> joined;
    for (const Trace& t : pieces)
    {
      joined.insert(t.shapes[step].begin(), t.shapes[step].end());
      EXPECT_EQ(t.last[step], whole.last[step]) << "step " << step;
      EXPECT_EQ(t.records[step], whole.records[step]) << "step " << step;
      EXPECT_EQ(t.errors[step], whole.errors[step]) << "step " << step;
    }
    ASSERT_EQ(joined.size(), whole.shapes[step].size());
    for (const auto& [g, s] : whole.shapes[step])
      for (int k = 0; k < 3; ++k)
        ASSERT_TRUE(std::memcmp(joined[g][std::size_t(k)].data(), s[std::size_t(k)].data(),
                      sizeof(Eigen::Vector3d)) == 0)
          << "step " << step << ", global id " << g << ", quantity " << k;
  }
}

std::int64_t gid_at(index_t i, index_t j)
{
  return shuffled_ids(kSide * kSide)[std::size_t(grid_id(kSide, i, j))];
}
} // namespace

TEST(EditSession, OnPiecesEveryStepEqualsTheWholeMeshBitForBit)
{
  // Drag across the piece borders, commit, drag again, commit, undo, redo, reset, redo.
  const std::vector<Step> steps{ { Step::drag, gid_at(12, 12), { 1.0, 0.5, 4.0 } },
    { Step::commit, gid_at(12, 12) }, { Step::drag, gid_at(7, 15), { -2.0, 0.0, 3.0 } },
    { Step::commit, gid_at(7, 15) }, { Step::undo }, { Step::redo }, { Step::undo },
    { Step::drag, gid_at(16, 6), { 0.0, 0.0, -3.0 } }, { Step::commit, gid_at(16, 6) },
    { Step::reset }, { Step::redo } };
  const Trace whole = run_whole(steps);
  EXPECT_EQ(whole.records[1].rfind("GSE2 ", 0), 0u);
  for (int pieces : { 1, 2, 3 })
  {
    SCOPED_TRACE(pieces);
    expect_equal_to_whole(run_pieces(pieces, steps), whole);
  }
}

TEST(EditSession, ARecordMadeOnThreePiecesReplaysOnOneAndTwo)
{
  const std::vector<Step> make{ { Step::drag, gid_at(11, 9), { 0.5, 0.5, 5.0 } },
    { Step::commit, gid_at(11, 9) }, { Step::drag, gid_at(13, 14), { 0.0, -1.0, 2.0 } },
    { Step::commit, gid_at(13, 14) } };
  const std::vector<Trace> three = run_pieces(3, make);
  const std::string first = three[0].last[1], second = three[0].last[3];
  ASSERT_FALSE(first.empty());
  const std::vector<Step> load{ { Step::add, -1, {}, first }, { Step::add, -1, {}, second } };
  const Trace whole = run_whole(load);
  EXPECT_TRUE(whole.errors[1].empty()) << whole.errors[1];
  expect_equal_to_whole(run_pieces(2, load), whole);
  // And the loaded shape is the committed one.
  std::map<std::int64_t, std::array<Eigen::Vector3d, 3>> made;
  for (const Trace& t : three)
    made.insert(t.shapes[3].begin(), t.shapes[3].end());
  for (const auto& [g, s] : whole.shapes[1])
    ASSERT_TRUE(s[0] == made[g][0] && s[1] == made[g][1]) << g;
}

TEST(EditSession, ABadRecordIsRefusedOnEveryPieceAlike)
{
  const std::vector<Step> make{ { Step::drag, gid_at(11, 9), { 0.5, 0.5, 5.0 } },
    { Step::commit, gid_at(11, 9) } };
  const std::string good = run_whole(make).last[1];
  Edit e;
  std::string error;
  ASSERT_TRUE(decode_edit(good, e, error)) << error;
  Edit stranger = e; // an id no vertex has
  stranger.ids.back() = 99999999;
  const std::vector<Step> load{ { Step::add, -1, {}, good }, { Step::add, -1, {}, "GSE2 junk" },
    { Step::reset }, { Step::add, -1, {}, encode_edit(stranger) } };
  const Trace whole = run_whole(load);
  EXPECT_NE(whole.errors[1].find("malformed edit record"), std::string::npos) << whole.errors[1];
  EXPECT_NE(whole.errors[3].find("edit 0 moves 1 of its"), std::string::npos) << whole.errors[3];
  EXPECT_NE(whole.errors[3].find("not in the mesh"), std::string::npos);
  expect_equal_to_whole(run_pieces(3, load), whole); // same errors, same shapes
}

TEST(EditSession, AGse1RecordStillReplaysAsPointIndicesOnOneProcess)
{
  // A GSE1 record names point indices, whatever global ids the mesh has.
  Scene s;
  const auto one = s.commit(grid_id(20, 10, 10), { 0.0, 0.0, 2.0 });
  Edit e;
  std::string error;
  ASSERT_TRUE(decode_edit(s.session.records()[0], e, error));
  e.version = 1;
  const std::string gse1 = encode_edit(e);
  EXPECT_EQ(gse1.rfind("GSE1 ", 0), 0u);
  EXPECT_LT(gse1.size(), s.session.records()[0].size()) << "28 bytes per vertex, not 32";
  Scene fresh;
  std::vector<std::int64_t> gid(std::size_t(fresh.deformer.size()));
  for (std::size_t v = 0; v < gid.size(); ++v)
    gid[v] = std::int64_t(gid.size() - v) * 3;
  fresh.deformer.set_global_ids(gid.data());
  GlobalIdMap ids;
  ids.set(gid.data(), fresh.deformer.size());
  fresh.session.add(gse1);
  ASSERT_TRUE(fresh.session.synchronize(fresh.deformer, error, {}, ids.place())) << error;
  EXPECT_EQ(fresh.shape(), one);
  EXPECT_TRUE(fresh.session.redo() == false);
}
