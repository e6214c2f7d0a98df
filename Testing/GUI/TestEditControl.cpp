// The client side of the edit history (ParaViewPlugin/ServerManager/edit_commands.h)
// against the filter's own command semantics (geoshaping::EditSession, docs/editing.md), and the
// point dabs (ParaViewPlugin/Controls/EditControl.h).
#include "EditControl.h"
#include "edit_commands.h"

#include "geoshaping/edit/edit_session.h"
#include "geoshaping/paint/brush.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace interactor = geoshaping::interactor;

namespace
{
// The server side is the filter's own command semantics, geoshaping::EditSession (what
// vtkChainMailDeformationFilter delegates to), over a small grid; the client proxy's
// properties are modelled.
class SessionFilter : public interactor::EditProxy
{
public:
  // Server side.
  geoshaping::testing::Mesh mesh = geoshaping::testing::triangle_grid(8, 8, 1.0);
  geoshaping::ChainMailDeformer deformer;
  geoshaping::EditSession session;
  std::vector<std::string> committed; // every record a commit made, in order
  bool deformed = false;              // the last update had a grasp
  bool markers = false;               // SnapToMarkers has a marker to snap
  int grasps = 0;
  // Client proxy.
  std::vector<std::string> client;
  long long grasp_point_id = 7;
  double displacement = 1.0;
  int pushes = 0;
  // Information as last fetched.
  int info_edits = -1, info_redoable = -1;
  std::string info_last;

  SessionFilter()
  {
    deformer.set_mesh(mesh.xyz.data(), mesh.size(), mesh.adjacency);
    deformer.set_uniform_malleability(0.7);
  }
  // An update with a grasp: each one a different pull.
  void grasp()
  {
    ++grasps;
    EXPECT_TRUE(deformer
                  .deform(geoshaping::testing::grid_id(8, grasps % 8, 3),
                    Eigen::Vector3d(0.0, 0.0, 0.5 * grasps))
                  .ok);
    deformed = true;
  }

  // The server runs a command (what vtkSMProxy::InvokeCommand sends).
  void invoke(const char* command)
  {
    const std::string c = command;
    if (c == "CommitEdit")
    {
      if (!deformed)
        return; // "nothing to commit"
      std::vector<Eigen::Vector3d> u;
      for (geoshaping::index_t v : deformer.moved())
        u.push_back(deformer.displacement(v));
      const std::vector<geoshaping::index_t> moved = deformer.moved();
      ASSERT_TRUE(session.commit(deformer, geoshaping::EditRecipe(), moved, u));
      committed.push_back(session.last_edit());
      deformed = false;
    }
    else if (c == "SnapToMarkers")
    {
      if (!markers)
        return; // refused: "no marker inside"
      // The filter's frames, committed as one edit (a pull standing in for them).
      grasp();
      invoke("CommitEdit");
    }
    else if (c == "UndoEdit")
      session.undo();
    else if (c == "RedoEdit")
      session.redo();
    else if (c == "ResetEdits")
      session.reset();
  }
  void update_information() override
  {
    info_edits = int(session.records().size());
    info_redoable = session.redoable();
    info_last = session.last_edit();
  }
  std::string last_edit() override { return info_last; }
  int number_of_edits() override { return info_edits; }
  int number_of_redoable_edits() override { return info_redoable; }
  std::vector<std::string> history() override { return client; }
  void set_history(const std::vector<std::string>& r) override { client = r; }
  void release() override
  {
    grasp_point_id = -1;
    displacement = 0.0;
  }
  void push() override
  {
    // RemoveAllEdits + AddEdit..., then the update that follows synchronizes.
    ++pushes;
    session.clear();
    for (const std::string& r : client)
      session.add(r);
    std::string error;
    EXPECT_TRUE(session.synchronize(deformer, error)) << error;
  }
};

// What vtkSMChainMailDeformationProxy does for any InvokeCommand: the server runs the
// command, then the client follows.
interactor::EditResult run(interactor::EditCommand command, SessionFilter& f)
{
  f.invoke(interactor::command_property(command));
  return interactor::follow_edit(command, f);
}
}

TEST(EditControl, CommandProperties)
{
  EXPECT_STREQ(interactor::command_property(interactor::EditCommand::commit), "CommitEdit");
  EXPECT_STREQ(interactor::command_property(interactor::EditCommand::undo), "UndoEdit");
  EXPECT_STREQ(interactor::command_property(interactor::EditCommand::redo), "RedoEdit");
  EXPECT_STREQ(interactor::command_property(interactor::EditCommand::reset), "ResetEdits");
  EXPECT_STREQ(interactor::command_property(interactor::EditCommand::snap), "SnapToMarkers");
  for (auto c :
    { interactor::EditCommand::commit, interactor::EditCommand::undo, interactor::EditCommand::redo,
      interactor::EditCommand::reset, interactor::EditCommand::snap })
  {
    interactor::EditCommand parsed = interactor::EditCommand::reset;
    EXPECT_TRUE(interactor::is_edit_command(interactor::command_property(c), parsed));
    EXPECT_EQ(parsed, c);
  }
  interactor::EditCommand unused;
  EXPECT_FALSE(interactor::is_edit_command("Displacement", unused));
  EXPECT_FALSE(interactor::is_edit_command("", unused));
}

// SnapToMarkers is followed as a commit: its one record appended, the grasp released; a
// refused snap (no markers) leaves the list and says so.
TEST(EditControl, SnapIsFollowedAsOneEditAndSaysWhenNothingSnapped)
{
  SessionFilter f;
  interactor::EditResult r = run(interactor::EditCommand::snap, f);
  EXPECT_FALSE(r.changed);
  EXPECT_EQ(r.message, "no marker snapped");
  EXPECT_TRUE(f.client.empty());
  EXPECT_EQ(f.grasp_point_id, -1);
  f.markers = true;
  r = run(interactor::EditCommand::snap, f);
  EXPECT_TRUE(r.changed);
  EXPECT_EQ(r.edits, 1u);
  ASSERT_EQ(f.client.size(), 1u);
  EXPECT_EQ(f.client[0], f.committed[0]);
  EXPECT_EQ(f.session.records(), f.client);
  r = run(interactor::EditCommand::undo, f);
  EXPECT_TRUE(r.changed);
  EXPECT_TRUE(f.client.empty());
}

TEST(EditControl, CommitAppendsLastEditAndReleases)
{
  SessionFilter f;
  f.grasp();
  const interactor::EditResult r = run(interactor::EditCommand::commit, f);
  EXPECT_TRUE(r.changed);
  EXPECT_EQ(r.edits, 1u);
  EXPECT_EQ(r.redoable, 0);
  EXPECT_TRUE(r.message.empty()) << r.message;
  ASSERT_EQ(f.client.size(), 1u);
  EXPECT_EQ(f.client[0], f.committed[0]);
  EXPECT_EQ(f.session.records(), f.client);
  EXPECT_EQ(f.grasp_point_id, -1);
  EXPECT_EQ(f.displacement, 0.0);
  EXPECT_EQ(f.pushes, 1);
}

TEST(EditControl, CommitWithNothingToCommitDoesNotDuplicateTheLastRecord)
{
  SessionFilter f;
  f.grasp();
  run(interactor::EditCommand::commit, f);
  // Press and release without a deformation: LastEdit is still the first edit.
  const interactor::EditResult r = run(interactor::EditCommand::commit, f);
  EXPECT_FALSE(r.changed);
  EXPECT_EQ(r.message, "nothing to commit");
  EXPECT_EQ(f.client.size(), 1u);
  EXPECT_EQ(f.grasp_point_id, -1);
}

TEST(EditControl, UndoRedoResetKeepTheClientListInStep)
{
  SessionFilter f;
  for (int i = 0; i < 3; ++i)
  {
    f.grasp();
    run(interactor::EditCommand::commit, f);
  }
  const std::vector<std::string> all = f.client;
  ASSERT_EQ(all.size(), 3u);

  interactor::EditResult r = run(interactor::EditCommand::undo, f);
  EXPECT_TRUE(r.changed);
  EXPECT_EQ(f.client, std::vector<std::string>(all.begin(), all.begin() + 2));
  EXPECT_EQ(r.redoable, 1);
  r = run(interactor::EditCommand::undo, f);
  EXPECT_EQ(f.client, std::vector<std::string>(all.begin(), all.begin() + 1));
  EXPECT_EQ(r.redoable, 2);

  r = run(interactor::EditCommand::redo, f);
  EXPECT_TRUE(r.changed);
  EXPECT_EQ(f.client, std::vector<std::string>(all.begin(), all.begin() + 2));
  EXPECT_EQ(r.redoable, 1);

  r = run(interactor::EditCommand::reset, f);
  EXPECT_TRUE(r.changed);
  EXPECT_TRUE(f.client.empty());
  EXPECT_EQ(r.redoable, 3);

  for (int i = 0; i < 3; ++i)
    run(interactor::EditCommand::redo, f);
  EXPECT_EQ(f.client, all);
  r = run(interactor::EditCommand::redo, f);
  EXPECT_FALSE(r.changed);
  EXPECT_EQ(r.message, "nothing to redo");
  EXPECT_EQ(f.client, all);
}

TEST(EditControl, UndoOnAnEmptyListSaysSo)
{
  SessionFilter f;
  const interactor::EditResult r = run(interactor::EditCommand::undo, f);
  EXPECT_FALSE(r.changed);
  EXPECT_EQ(r.message, "nothing to undo");
  EXPECT_TRUE(f.client.empty());
  EXPECT_TRUE(f.session.records().empty());
}

TEST(EditControl, CommitAfterUndoDropsTheRedoTail)
{
  SessionFilter f;
  f.grasp();
  run(interactor::EditCommand::commit, f);
  f.grasp();
  run(interactor::EditCommand::commit, f);
  run(interactor::EditCommand::undo, f);
  f.grasp();
  const interactor::EditResult r = run(interactor::EditCommand::commit, f);
  EXPECT_EQ(r.edits, 2u);
  EXPECT_EQ(r.redoable, 0);
  ASSERT_EQ(f.committed.size(), 3u);
  EXPECT_EQ(f.client, std::vector<std::string>({ f.committed[0], f.committed[2] }));
}

TEST(EditControl, EveryCommandSenderKeepsTheListInStep)
{
  // The panel's Undo button used to change the server only; now every InvokeCommand is
  // followed, so after any mix of senders the client's list is the server's.
  SessionFilter f;
  for (int i = 0; i < 3; ++i)
  {
    f.grasp();
    run(interactor::EditCommand::commit, f);
  }
  run(interactor::EditCommand::undo, f);
  f.grasp();
  const interactor::EditResult r = run(interactor::EditCommand::commit, f);
  EXPECT_TRUE(r.message.empty()) << r.message;
  EXPECT_EQ(f.client.size(), 3u);
  EXPECT_EQ(f.session.records(), f.client);
  ASSERT_EQ(f.committed.size(), 4u);
  EXPECT_EQ(f.client.back(), f.committed[3]);
}

namespace
{
std::vector<double> RestPositions(SessionFilter& f)
{
  std::vector<double> xyz;
  for (geoshaping::index_t v = 0; v < f.mesh.size(); ++v)
  {
    const Eigen::Vector3d x = f.deformer.rest_local(v) + f.deformer.committed_offset(v);
    xyz.insert(xyz.end(), { x.x(), x.y(), x.z() });
  }
  return xyz;
}
}

TEST(EditControl, RestoringTheListBeforeACommitIsTheCommandUndo)
{
  // ParaView's undo stack steps back over a commit by restoring the list before it, and
  // forth by restoring the list after it: the same list, redoable count and rest shape as
  // the dock's Undo and Redo (the commands), bit for bit.
  SessionFilter byCommand, byList;
  for (SessionFilter* f : { &byCommand, &byList })
  {
    f->grasp();
    run(interactor::EditCommand::commit, *f);
  }
  const std::vector<std::string> before = byList.client;
  for (SessionFilter* f : { &byCommand, &byList })
  {
    f->grasp();
    run(interactor::EditCommand::commit, *f);
  }
  const std::vector<std::string> after = byList.client;
  const std::vector<double> committed = RestPositions(byList);

  const interactor::EditResult undone = run(interactor::EditCommand::undo, byCommand);
  byList.grasp_point_id = 5; // a grasp left on the proxy is released too
  const interactor::EditResult restored = interactor::restore_edits(before, byList);
  EXPECT_TRUE(restored.changed);
  EXPECT_EQ(byList.client, byCommand.client);
  EXPECT_EQ(byList.session.records(), byCommand.session.records());
  EXPECT_EQ(restored.edits, undone.edits);
  EXPECT_EQ(restored.redoable, undone.redoable);
  EXPECT_EQ(restored.redoable, 1);
  EXPECT_EQ(RestPositions(byList), RestPositions(byCommand));
  EXPECT_NE(RestPositions(byList), committed);
  EXPECT_EQ(byList.grasp_point_id, -1);

  const interactor::EditResult redone = run(interactor::EditCommand::redo, byCommand);
  const interactor::EditResult again = interactor::restore_edits(after, byList);
  EXPECT_EQ(byList.client, after);
  EXPECT_EQ(again.redoable, redone.redoable);
  EXPECT_EQ(RestPositions(byList), RestPositions(byCommand));
  EXPECT_EQ(RestPositions(byList), committed);
  EXPECT_FALSE(interactor::restore_edits(after, byList).changed);
}

TEST(PointDabs, TriplesOfTheVerticesUnderTheBrush)
{
  std::vector<double> triples = { 99.0, 0.1, 0.2 }; // earlier dabs are kept
  interactor::append_point_dabs(
    { 4, 8, 15 }, { 0.0, 1.0, 2.0 }, 2.0, 0.8, 0.5, geoshaping::Falloff::linear, triples);
  // The core (half the radius) at full strength; the rim (weight 0) is left out.
  const std::vector<double> expected = { 99.0, 0.1, 0.2, 4.0, 0.8, 0.5, 8.0, 0.8, 0.5 };
  EXPECT_EQ(triples, expected);

  std::vector<double> clamped;
  interactor::append_point_dabs(
    { 1 }, { 0.0 }, 1.0, 7.0, -1.0, geoshaping::Falloff::constant, clamped);
  EXPECT_TRUE(clamped.empty()); // strength clamped to 0: nothing painted
  interactor::append_point_dabs(
    { 1 }, { 0.0 }, 1.0, 7.0, 2.0, geoshaping::Falloff::constant, clamped);
  EXPECT_EQ(clamped, (std::vector<double>{ 1.0, 1.0, 1.0 }));

  std::vector<double> none;
  interactor::append_point_dabs(
    { 1 }, { 0.0 }, 0.0, 0.5, 0.5, geoshaping::Falloff::constant, none); // zero radius
  interactor::append_point_dabs(
    { 1, 2 }, { 0.0 }, 1.0, 0.5, 0.5, geoshaping::Falloff::constant, none); // size mismatch
  interactor::append_point_dabs(
    { -1 }, { 0.0 }, 1.0, 0.5, 0.5, geoshaping::Falloff::constant, none); // bad id
  EXPECT_TRUE(none.empty());
}

TEST(RedoableSteps, CountTheEditsAndTheStrokesRedoWillRestore)
{
  using geoshaping::interactor::redoable_steps;
  // A stroke undone: Redo restores it, though the deformation has nothing to redo.
  EXPECT_EQ(redoable_steps(0, { "Paint Stroke" }, "Paint Stroke"), 1);
  // Then the pull before it: two presses of Redo restore something.
  EXPECT_EQ(redoable_steps(1, { "Paint Stroke", "Edit Commit" }, "Paint Stroke"), 2);
  // Another proxy's step is not the dock's to redo.
  EXPECT_EQ(redoable_steps(0, { "Delete", "Paint Stroke" }, "Paint Stroke"), 1);
  EXPECT_EQ(redoable_steps(-1, {}, "Paint Stroke"), 0);
}
