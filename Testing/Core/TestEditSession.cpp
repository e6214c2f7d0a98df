// geoshaping::EditSession: the EditHistory list and its commands (docs/editing.md).
#include "geoshaping/edit_session.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

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
