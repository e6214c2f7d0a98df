#pragma once
// A hook for the GUI test and the demo, off unless asked for by the environment:
//   GEOSHAPING_HAPTICS_REPLAY=<trace>       hand 1 replays the trace with the Deform tool,
//                                           started once a ChainMailDeformation exists;
//                                           "mouse": hand 1 is the mouse, and the hook
//                                           drags it up on the surface (Deform);
//                                           "pull": the same, and pqPullTestDriver
//                                           pulls and measures (gui_setup_pull.py);
//                                           "openhaptics": hand 1 is OpenHaptics on the
//                                           fake HD library GEOSHAPING_LIBHD names, which
//                                           the hook faults after 1 s (fakehd_inject_fault);
//                                           "state": hand 1 is the mouse, not dragged,
//                                           after GEOSHAPING_GUI_STATE=<file.pvsm> is
//                                           loaded as File > Load State does (also
//                                           with "mouse": the scene, loaded before
//                                           the dock starts);
//   GEOSHAPING_GUI_SERVER_PROCESSES=N        paraview connects to an N-process pvserver
//                                           (--url): the hook waits for that
//                                           connection before loading or starting;
//   GEOSHAPING_HAPTICS_TEST_TIMEOUT=<s>      the hook gives up after s seconds (45);
//   GEOSHAPING_HAPTICS_SCRIPT=<steps>        the hook plays these steps
//                                           (pqHapticsTestScript.h): with "mouse"
//                                           instead of its drag, with a trace beside
//                                           the replay (until, dump: gui_pvserver.py);
//   GEOSHAPING_HAPTICS_TOOL1=hold_and_turn  hand 1 holds and turns the object instead;
//   GEOSHAPING_HAPTICS_REPLAY2=<trace>      hand 2 replays this trace with the Paint tool
//                                           (two hands at once);
//   GEOSHAPING_HAPTICS_STALL=<at>,<for>     the GUI stalls: <at> s into the replay the
//                                           hook blocks the GUI thread for <for> s (no
//                                           frame, no scene published; the servo runs on);
//   GEOSHAPING_HAPTICS_TEST_OUTPUT=<prefix> when the replay is over, write <prefix>.png
//                                           (the main window), <prefix>-view.png (the
//                                           render view) and <prefix>.txt (key = value
//                                           figures and the deformed output), then quit.
#include <QObject>

#include <chrono>
#include <memory>

class pqHapticsDockPanel;
class pqPullTestDriver;
class pqHapticsTestScript;
class QTextStream;
class vtkPointSet;

class pqHapticsTestHook : public QObject
{
  Q_OBJECT

public:
  static void installIfRequested(pqHapticsDockPanel* dock);

private Q_SLOTS:
  void poll();

private:
  pqHapticsTestHook(pqHapticsDockPanel* dock, const QString& trace, const QString& output);
  bool serverReady() const;
  void dragMouse();
  void faultOpenHaptics();
  void writeResults();
  void writePaint(QTextStream& out);
  void writeCommittedDisplacement(QTextStream& out);
  void checkEdits(QTextStream& out, vtkPointSet* input, vtkPointSet* output);

  pqHapticsDockPanel* Dock;
  std::shared_ptr<pqHapticsTestScript> Script;
  QString Trace;
  QString Trace2;
  QString Output;
  QString FakeForce; // the fake device's last force after the fault, "x y z" N
  bool Started = false;
  bool TimedOut = false;
  enum class LoadStage
  {
    NotAsked,
    Loading,
    Loaded
  };
  LoadStage StateLoad = LoadStage::NotAsked; // of GEOSHAPING_GUI_STATE
  int FinishedPolls = 0;
  // When the replayed traces are over: start() plus the longest trace's duration (the
  // replay devices' clocks start inside start(), so they are past their last sample then).
  std::chrono::steady_clock::time_point ReplaysEnd;
  // GEOSHAPING_HAPTICS_STALL: when (since start()) and how long, in s; done once.
  double StallAt = -1.0;
  double StallFor = 0.0;
  double Stalled = 0.0; // s the GUI thread was blocked, measured
  std::chrono::steady_clock::time_point ReplaysStart;
  int Polls = 0;
  int ReadyPolls = 0;
  int MouseSteps = 0;
  int FaultSteps = 0;
  int Commits = 0; // edits the dock was told of (editsChanged) that changed the list
  std::shared_ptr<pqPullTestDriver> Pull;
};
