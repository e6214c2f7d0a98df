#include "geoshaping/edit/edit_history.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <cstring>

using namespace geoshaping;
using geoshaping::testing::grid_id;

namespace
{
// The current positions of every vertex, as raw bits for == comparison.
std::vector<Eigen::Vector3d> shape(const ChainMailDeformer& d)
{
  std::vector<Eigen::Vector3d> x(std::size_t(d.size()));
  for (index_t v = 0; v < d.size(); ++v)
    x[std::size_t(v)] = d.position(v);
  return x;
}

bool bit_equal(const std::vector<Eigen::Vector3d>& a, const std::vector<Eigen::Vector3d>& b)
{
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(a[0])) == 0;
}

struct Scene
{
  geoshaping::testing::Mesh mesh = geoshaping::testing::triangle_grid(30, 30, 1.0);
  ChainMailDeformer deformer;
  EditHistory history;
  Scene()
  {
    // UTM-sized coordinates: the local origin must keep replay exact.
    for (std::size_t i = 0; i < mesh.xyz.size(); i += 3)
      mesh.xyz[i] += 512345.25, mesh.xyz[i + 1] += 4123456.5;
    deformer.set_mesh(mesh.xyz.data(), mesh.size(), mesh.adjacency);
    deformer.set_uniform_malleability(0.8);
  }
  // Drag `grasp` by `d` and commit the frame as an edit.
  const Edit& edit(index_t grasp, const Eigen::Vector3d& d)
  {
    EXPECT_TRUE(deformer.deform(grasp, d).ok);
    std::vector<Eigen::Vector3d> u;
    for (index_t v : deformer.moved())
      u.push_back(deformer.displacement(v));
    EditRecipe recipe;
    recipe.grasp = grasp;
    recipe.displacement = d;
    return history.commit(deformer, recipe, deformer.moved(), u);
  }
};
} // namespace

TEST(EditHistory, CommitKeepsTheDeformedShapeAsTheNewRest)
{
  Scene s;
  ASSERT_TRUE(s.deformer.deform(grid_id(30, 15, 15), { 0.0, 0.0, 3.0 }).ok);
  const auto dragged = shape(s.deformer);
  const std::size_t moved = s.deformer.moved().size();
  s.deformer.commit();
  EXPECT_TRUE(bit_equal(shape(s.deformer), dragged));
  s.deformer.reset();
  EXPECT_TRUE(bit_equal(shape(s.deformer), dragged)) << "the next frame starts from the commit";
  EXPECT_GT(moved, 1u);
  // A second grasp pulls from the committed shape, not the original one.
  ASSERT_TRUE(s.deformer.deform(grid_id(30, 15, 15), { 0.0, 0.0, 1.0 }).ok);
  EXPECT_EQ(s.deformer.position(grid_id(30, 15, 15)).z(), 4.0);
}

TEST(EditHistory, HistoryCommitMatchesTheDeformersCommitBitForBit)
{
  Scene a, b;
  a.edit(grid_id(30, 10, 12), { 1.0, -2.0, 3.5 });
  ASSERT_TRUE(b.deformer.deform(grid_id(30, 10, 12), { 1.0, -2.0, 3.5 }).ok);
  b.deformer.commit();
  b.deformer.reset();
  EXPECT_TRUE(bit_equal(shape(a.deformer), shape(b.deformer)));
  for (index_t v = 0; v < a.deformer.size(); ++v)
    ASSERT_EQ(a.deformer.committed_offset(v), b.deformer.committed_offset(v));
}

TEST(EditHistory, UndoRedoAndResetRestoreEveryStepBitExactly)
{
  Scene s;
  std::vector<std::vector<Eigen::Vector3d>> steps{ shape(s.deformer) };
  const Eigen::Vector3d pulls[] = { { 0, 0, 3 }, { 1.5, 0, -2 }, { 0, 0.25, 7 }, { -3, 1, 1 } };
  const index_t grasps[] = { grid_id(30, 15, 15), grid_id(30, 16, 15), grid_id(30, 5, 20),
    grid_id(30, 15, 14) };
  for (int i = 0; i < 4; ++i)
  {
    s.edit(grasps[i], pulls[i]);
    steps.push_back(shape(s.deformer));
  }
  for (int i = 3; i >= 0; --i)
  {
    ASSERT_TRUE(s.history.undo(s.deformer));
    EXPECT_TRUE(bit_equal(shape(s.deformer), steps[std::size_t(i)])) << "undo to " << i;
  }
  EXPECT_FALSE(s.history.undo(s.deformer));
  for (index_t v = 0; v < s.deformer.size(); ++v)
    ASSERT_EQ(s.deformer.committed_offset(v), Eigen::Vector3d::Zero());
  for (int i = 1; i <= 4; ++i)
  {
    ASSERT_TRUE(s.history.redo(s.deformer));
    EXPECT_TRUE(bit_equal(shape(s.deformer), steps[std::size_t(i)])) << "redo to " << i;
  }
  EXPECT_FALSE(s.history.redo(s.deformer));
  std::string error;
  ASSERT_TRUE(s.history.synchronize(s.deformer, {}, error));
  EXPECT_TRUE(bit_equal(shape(s.deformer), steps[0])) << "reset to the original";
}

TEST(EditHistory, RecordsReplayBitExactlyInAFreshDeformerWhateverItsMalleability)
{
  Scene s;
  s.edit(grid_id(30, 15, 15), { 0.1, 0.2, 3.3 });
  s.edit(grid_id(30, 3, 4), { -1.0 / 3.0, 0.0, 2.0 });
  std::vector<std::string> records{ s.history.record(0), s.history.record(1) };

  Scene fresh;
  fresh.deformer.set_uniform_malleability(0.1); // repainted: the result still replays
  std::string error;
  ASSERT_TRUE(fresh.history.synchronize(fresh.deformer, records, error)) << error;
  EXPECT_EQ(fresh.history.applied(), 2u);
  EXPECT_TRUE(bit_equal(shape(fresh.deformer), shape(s.deformer)));
  EXPECT_EQ(fresh.history.record(1), records[1]);
  EXPECT_EQ(fresh.history.edit(0).recipe.displacement, Eigen::Vector3d(0.1, 0.2, 3.3));
}

TEST(EditHistory, SynchronizeUndoesAndRedoesOnlyTheDifference)
{
  Scene s;
  s.edit(grid_id(30, 15, 15), { 0, 0, 3 });
  const auto one = shape(s.deformer);
  s.edit(grid_id(30, 15, 16), { 0, 0, 2 });
  const auto two = shape(s.deformer);
  std::vector<std::string> records{ s.history.record(0), s.history.record(1) };
  s.history.take_touched();
  std::string error;
  ASSERT_TRUE(s.history.synchronize(s.deformer, records, error));
  EXPECT_TRUE(s.history.take_touched().empty()) << "same records: nothing to do";
  ASSERT_TRUE(s.history.synchronize(s.deformer, { records[0] }, error));
  EXPECT_TRUE(bit_equal(shape(s.deformer), one));
  EXPECT_EQ(s.history.take_touched().size(), s.history.edit(1).vertices.size());
  EXPECT_EQ(s.history.size(), 2u) << "the undone edit stays redoable";
  ASSERT_TRUE(s.history.synchronize(s.deformer, records, error));
  EXPECT_TRUE(bit_equal(shape(s.deformer), two));
}

TEST(EditHistory, CommitUndoAndRedoTouchOnlyTheMovedVertices)
{
  Scene s;
  s.deformer.set_uniform_malleability(1.0); // soft: a small pull moves a small patch
  const Edit& e = s.edit(grid_id(30, 15, 15), { 0, 0, 1.0 });
  const std::size_t moved = e.vertices.size();
  EXPECT_LT(moved, 40u);
  EXPECT_EQ(s.history.take_touched().size(), moved);
  s.history.undo(s.deformer);
  EXPECT_EQ(s.history.take_touched().size(), moved);
  s.history.redo(s.deformer);
  EXPECT_EQ(s.history.take_touched().size(), moved);
}

TEST(EditHistory, MalformedRecordsAreRefusedWithAReason)
{
  Scene s;
  s.edit(grid_id(30, 15, 15), { 0, 0, 3 });
  const std::string good = s.history.record(0);
  Edit e;
  std::string error;
  EXPECT_TRUE(decode_edit(good, e, error));
  EXPECT_FALSE(decode_edit("GSE2 1 2", e, error));
  EXPECT_FALSE(decode_edit(good.substr(0, good.size() - 4), e, error));
  // Ids beyond a smaller mesh: refused when replayed, the edit undone.
  Scene small;
  small.mesh = geoshaping::testing::triangle_grid(3, 3, 1.0);
  small.deformer.set_mesh(small.mesh.xyz.data(), small.mesh.size(), small.mesh.adjacency);
  EXPECT_FALSE(small.history.synchronize(small.deformer, { good }, error));
  EXPECT_NE(error.find("not in the mesh"), std::string::npos) << error;
  EXPECT_EQ(small.history.applied(), 0u);
  for (index_t v = 0; v < small.deformer.size(); ++v)
    ASSERT_EQ(small.deformer.committed_offset(v), Eigen::Vector3d::Zero());
  // Ids must increase.
  Edit swapped = e;
  std::swap(swapped.ids[0], swapped.ids[1]);
  EXPECT_FALSE(decode_edit(encode_edit(swapped), e, error));
  EXPECT_NE(error.find("not increasing"), std::string::npos) << error;
  Scene fresh;
  EXPECT_FALSE(fresh.history.synchronize(fresh.deformer, { good, "junk" }, error));
  EXPECT_EQ(fresh.history.applied(), 1u) << "the edits before the bad one stay applied";
}
