#pragma once
// A script for the GUI tests (GEOSHAPING_HAPTICS_SCRIPT): with
// GEOSHAPING_HAPTICS_REPLAY=mouse it drives the mouse hand (painting, pulls), with a
// trace it runs beside the replayed stylus (until, dump). Steps separated by ';', one
// per poll of the hook, positions as fractions of the render view (x right, y up):
//   press X Y [ctrl]   left button down (with Ctrl: paint), the pick written to <out>.picks
//                      (the verb, ParaView's point on the surface, VTK's picker's point)
//   move X Y           the mouse moves there (button held), the pick written too
//   release            left button up
//   hover X Y [ctrl]   the mouse moves there, no button (with Ctrl held), the pick written
//   leave              the mouse leaves the view
//   key K              the key K pressed and released on the render view's window, as the
//                      window system delivers it (Qt's shortcuts first, then the view)
//   ctrlup             Ctrl released while the keyboard focus is on the dock, not the view
//   swatch I           clicks the dock's malleability swatch I (0 ... 10)
//   radius R           types R into the dock's brush radius
//   exaggeration S     types S into the dock's vertical exaggeration
//   undo | redo        clicks the dock's Undo / Redo
//   snap               clicks the dock's Snap to markers
//   showmarkers        clicks the dock's Show markers (the snapshot then writes how the
//                      Marker Misfit filter is drawn: marker_misfit_*)
//   editundo | editredo  Edit > Undo / Redo (ParaView's undo stack, Ctrl+Z / Ctrl+Y)
//   until T            waits until T s have passed since the dock started (`since` of
//                      step(): a replayed trace's clock starts inside the dock's start,
//                      so the stylus is past T too)
//   dump NAME          the server's ranks write their points (the scene's
//                      ProgrammableFilter, gui_pvserver.py, runs with `name = 'NAME'`),
//                      and <out>-NAME.txt holds the deformation proxy's grasp,
//                      Displacement and EditHistory, the paint proxy's Dabs and
//                      PointDabs, and the force hand 1's last scene asks for (writeForce)
//   open READER        File > Open of GEOSHAPING_GUI_SURFACE with the reader READER
//                      (sources group), then Apply
//   apply NAME         Filters > NAME on the active source, then Apply
//   obstacle NAME      in the Properties panel, the ChainMailDeformation's Obstacles
//                      (its Pipeline Connection's Input) set to the source NAME, Apply
//   savestate          File > Save State to <out>.pvsm
//   snapshot NAME      writes <out>-NAME.csv (per point: the paint's input x y z, the shown
//                      surface's x y z, the painted malleability), <out>-NAME.txt (the
//                      brush, the paint lists' sizes, the pull (Displacement, grasp,
//                      the dock's Pull row), the shown cursors (centre, radius, representation,
//                      stretch along z), the
//                      deformation's display Scale and its obstacles', its grasped
//                      vertex's pixel as drawn
//                      and the mouse's pixel, the
//                      dock's texts, NumberOfObstacleBlockedPoints, the lines shown
//                      from a grasp marker to its cursor, the Pipeline Browser's rows)
//                      and <out>-NAME.png
//                      (the render view)
//   wait               nothing this poll
// Each step waits for one interactor frame after the previous one, so that the frames
// see every event whatever the machine's speed. When the steps are over, step() returns
// true and the hook writes its results.
#include "geoshaping/haptics/force_model.h"

#include <QString>
#include <QStringList>

#include <chrono>

class pqHapticsDockPanel;
class QTextStream;

class pqHapticsTestScript
{
public:
  pqHapticsTestScript(pqHapticsDockPanel* dock, const QString& script, const QString& output);
  // `since`: when the dock started (for `until`).
  bool step(std::chrono::steady_clock::time_point since);
  // `force_from_last_scene` (N, device coordinates), `force_status` and
  // `in_contact_last_scene` of a hand's figure (pqHapticsInteractor::Figures::force).
  static void writeForce(QTextStream& out, const geoshaping::haptics::ForceResult& force);

private:
  void snapshot(const QString& name);
  void chooseObstacle(const QString& name);
  void dump(const QString& name);
  void mouse(const QStringList& words);
  void key(const QString& key);

  pqHapticsDockPanel* Dock;
  QStringList Steps;
  QString Output;
  int Next = 0;
  int AfterFrame = 1; // the interactor's frame count the next step waits for (the first
                      // frame attaches the mouse)
};
