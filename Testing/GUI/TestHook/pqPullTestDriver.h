#pragma once
// The GUI pull test's driver (GEOSHAPING_HAPTICS_REPLAY=pull, gui_setup_pull.py): mouse
// pulls on the fault-step horizon at two data scales ("Pull unit", "Pull 1000 km") and
// under two cameras, one step per call, each measured against the cursor: the grasped
// vertex's image (vtkRenderer::WorldToDisplay) against the cursor's pixel, and its
// displacement against the cursor's motion carried onto the plane through it parallel
// to the view. Also a pull with Shift held, and pulls with the dock's Pull row on
// "Vertical only" and "Along the surface normal". Writes one view screenshot per pull, while it is
// held.
#include <QString>

#include <Eigen/Core>

class pqHapticsDockPanel;

class pqPullTestDriver
{
public:
  pqPullTestDriver(pqHapticsDockPanel* dock, const QString& output);
  // One step; true at the step that finishes the last pull.
  bool step();
  // key = value lines for the results file.
  const QString& results() const { return this->Results; }

private:
  struct Pull
  {
    const char* name;
    const char* source;
    int camera; // 0: perspective from the south-west, 1: parallel from the south-east
    bool shift;
    int constraint; // the Pull row's entry: 0 follow the cursor, 1 vertical, 2 normal
  };
  bool begin(const Pull& pull);
  void measure(const Pull& pull);

  pqHapticsDockPanel* Dock;
  QString Output;
  QString Results;
  int Index = 0;
  int Step = 0;
  int Press[2] = { 0, 0 };
  int Cursor[2] = { 0, 0 };
  Eigen::Vector3d Normal = Eigen::Vector3d::Zero(); // the view's, at the press
};
