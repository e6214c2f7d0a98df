#include "pqHapticsUndoChecks.h"

#include "pqHapticsDockPanel.h"
#include "pqHapticsProxies.h"

#include <pqActiveObjects.h>
#include <pqApplicationCore.h>
#include <pqCoreUtilities.h>
#include <pqLoadStateReaction.h>
#include <pqOutputPort.h>
#include <pqPipelineSource.h>
#include <pqRenderView.h>
#include <pqUndoStack.h>
#include <pqView.h>

#include <vtkAlgorithm.h>
#include <vtkCamera.h>
#include <vtkPVDataInformation.h>
#include <vtkPVRenderView.h>
#include <vtkPointSet.h>
#include <vtkPoints.h>
#include <vtkSMPropertyHelper.h>
#include <vtkSMProxy.h>
#include <vtkSMRenderViewProxy.h>
#include <vtkSMUndoStack.h>
#include <vtkSMUndoStackBuilder.h>

#include <QAction>
#include <QLabel>
#include <QPushButton>
#include <QStringList>
#include <QTextStream>
#include <QWidget>

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <vector>

namespace
{
struct Target
{
  pqPipelineSource* source = nullptr;
  vtkSMProxy* proxy = nullptr;
  vtkAlgorithm* filter = nullptr;
  vtkPointSet* input() const
  {
    return vtkPointSet::SafeDownCast(filter ? filter->GetInputDataObject(0, 0) : nullptr);
  }
  vtkPointSet* output() const
  {
    return vtkPointSet::SafeDownCast(filter ? filter->GetOutputDataObject(0) : nullptr);
  }
};

Target target()
{
  Target t;
  t.source = pqHapticsFindSource("ChainMailDeformation");
  t.proxy = t.source ? t.source->getProxy() : nullptr;
  t.filter = t.proxy ? vtkAlgorithm::SafeDownCast(t.proxy->GetClientSideObject()) : nullptr;
  return t;
}

std::vector<double> pointsOf(vtkPointSet* data)
{
  std::vector<double> xyz(data ? 3 * data->GetNumberOfPoints() : 0);
  for (vtkIdType i = 0; data && i < data->GetNumberOfPoints(); ++i)
  {
    data->GetPoint(i, &xyz[3 * i]);
  }
  return xyz;
}

// Bounds by a pass over the points (what they must be).
std::array<double, 6> exactBounds(vtkPointSet* data)
{
  std::array<double, 6> b{ { 1.0, -1.0, 1.0, -1.0, 1.0, -1.0 } };
  double x[3];
  for (vtkIdType i = 0; i < data->GetNumberOfPoints(); ++i)
  {
    data->GetPoint(i, x);
    for (int k = 0; k < 3; ++k)
    {
      b[2 * k] = i == 0 ? x[k] : std::min(b[2 * k], x[k]);
      b[2 * k + 1] = i == 0 ? x[k] : std::max(b[2 * k + 1], x[k]);
    }
  }
  return b;
}

QString text(const double* v, int n)
{
  QStringList parts;
  for (int i = 0; i < n; ++i)
  {
    parts << QString::number(v[i], 'g', 17);
  }
  return parts.join(' ');
}

// What the shape left: grasp, displacement, list, and the bounds the filter's output, the
// Information panel (data information) and Reset Camera see, against `expected`.
void writeSettled(
  QTextStream& out, const QString& prefix, const Target& t, const std::array<double, 6>& expected)
{
  out << prefix
      << "_grasp_point_id = " << vtkSMPropertyHelper(t.proxy, "GraspPointId").GetAsIdType() << "\n";
  double d[3];
  vtkSMPropertyHelper(t.proxy, "Displacement").Get(d, 3);
  out << prefix << "_displacement = " << text(d, 3) << "\n";
  out << prefix
      << "_edit_history = " << vtkSMPropertyHelper(t.proxy, "EditHistory").GetNumberOfElements()
      << "\n";
  double b[6];
  t.output()->GetBounds(b);
  out << prefix << "_bounds = " << text(b, 6) << "\n";
  out << prefix << "_expected_bounds = " << text(expected.data(), 6) << "\n";
  out << prefix << "_bounds_exact = " << int(std::equal(b, b + 6, expected.begin())) << "\n";
  t.source->getOutputPort(0)->getDataInformation()->GetBounds(b);
  out << prefix << "_information_bounds = " << text(b, 6) << "\n";
  out << prefix << "_information_bounds_exact = " << int(std::equal(b, b + 6, expected.begin()))
      << "\n";
  // Reset Camera, then put the camera back (other checks read it), neither recorded on
  // the undo stack these checks step through.
  SCOPED_UNDO_EXCLUDE();
  auto* view = qobject_cast<pqRenderView*>(pqActiveObjects::instance().activeView());
  vtkCamera* camera = view ? view->getRenderViewProxy()->GetActiveCamera() : nullptr;
  if (camera)
  {
    vtkNew<vtkCamera> saved;
    saved->DeepCopy(camera);
    view->resetCamera();
    const double* f = camera->GetFocalPoint();
    double error = 0.0, diagonal = 0.0;
    for (int k = 0; k < 3; ++k)
    {
      const double centre = 0.5 * (expected[2 * k] + expected[2 * k + 1]);
      error += (f[k] - centre) * (f[k] - centre);
      diagonal += std::pow(expected[2 * k + 1] - expected[2 * k], 2);
    }
    out << prefix << "_reset_camera_focal_point = " << text(f, 3) << "\n";
    out << prefix << "_reset_camera_offset = " << std::sqrt(error / diagonal) << "\n";
    camera->DeepCopy(saved);
    view->getRenderViewProxy()->SynchronizeCameraProperties();
    view->render();
  }
}

QString undoLabels()
{
  pqUndoStack* stack = pqApplicationCore::instance()->getUndoStack();
  vtkSMUndoStack* sm = stack ? stack->GetUndoStackBuilder()->GetUndoStack() : nullptr;
  QStringList labels;
  for (unsigned int i = 0; sm && i < sm->GetNumberOfUndoSets(); ++i)
  {
    labels << sm->GetUndoSetLabel(i);
  }
  return labels.join(" | ");
}

// Edit > Undo renders later (pqApplicationCore::render); what the user then sees is the
// rendered view.
void renderNow()
{
  if (pqView* view = pqActiveObjects::instance().activeView())
  {
    view->forceRender();
  }
}

QPushButton* dockButton(pqHapticsDockPanel* dock, const char* name)
{
  return dock->findChild<QPushButton*>(name);
}
} // namespace

namespace pqHapticsUndoChecks
{

void writeEditMenu(QTextStream& out, pqHapticsDockPanel* dock)
{
  const Target t = target();
  QWidget* window = pqCoreUtilities::mainWidget();
  auto* undo = window ? window->findChild<QAction*>("actionEditUndo") : nullptr;
  auto* redo = window ? window->findChild<QAction*>("actionEditRedo") : nullptr;
  if (!t.input() || !t.output() || !undo || !redo)
  {
    out << "edit_menu = 0\n";
    return;
  }
  out << "edit_menu = 1\n";
  out << "undo_steps = " << undoLabels() << "\n";
  out << "edit_menu_undo_text = " << undo->text() << "\n";
  const std::vector<double> rest = pointsOf(t.input());
  const std::vector<double> released = pointsOf(t.output());
  const std::array<double, 6> restBounds = exactBounds(t.input());
  const std::array<double, 6> releasedBounds = exactBounds(t.output());
  writeSettled(out, "released", t, releasedBounds);

  out << "edit_menu_undo_enabled = " << int(undo->isEnabled()) << "\n";
  undo->trigger(); // Edit > Undo, as Ctrl+Z
  renderNow();
  out << "undo_steps_after_edit_menu_undo = " << undoLabels() << "\n";
  const std::vector<double> undone = pointsOf(t.output());
  out << "edit_menu_undo_equals_rest = " << int(undone == rest) << "\n";
  writeSettled(out, "edit_menu_undo", t, restBounds);
  redo->trigger();
  renderNow();
  out << "edit_menu_redo_equals_released = " << int(pointsOf(t.output()) == released) << "\n";
  writeSettled(out, "edit_menu_redo", t, releasedBounds);

  QPushButton* dockUndo = dockButton(dock, "UndoEdit");
  QPushButton* dockRedo = dockButton(dock, "RedoEdit");
  if (dockUndo && dockRedo)
  {
    dockUndo->click();
    renderNow();
    out << "dock_undo_equals_edit_menu_undo = " << int(pointsOf(t.output()) == undone) << "\n";
    writeSettled(out, "dock_undo", t, restBounds);
    dockRedo->click();
    renderNow();
    out << "dock_redo_equals_released = " << int(pointsOf(t.output()) == released) << "\n";
  }
}

bool loadStateIfRequested()
{
  const QString state = qEnvironmentVariable("GEOSHAPING_GUI_STATE");
  if (state.isEmpty())
  {
    return false;
  }
  pqLoadStateReaction::loadState(state, true);
  // Remote rendering forced (GEOSHAPING_GUI_REMOTE_RENDER): the view's Remote Render
  // Threshold 0, and whether the view then renders on the server, for the test to check.
  auto* view = qobject_cast<pqRenderView*>(pqActiveObjects::instance().activeView());
  if (view && qEnvironmentVariableIsSet("GEOSHAPING_GUI_REMOTE_RENDER"))
  {
    vtkSMPropertyHelper(view->getProxy(), "RemoteRenderThreshold").Set(0.0);
    view->getProxy()->UpdateVTKObjects();
    view->forceRender();
    auto* pv = vtkPVRenderView::SafeDownCast(view->getProxy()->GetClientSideObject());
    std::cout << "GeoShaping test: remote rendering = "
              << int(pv && pv->GetUseDistributedRenderingForRender()) << std::endl;
  }
  return true;
}

void writeLoadedState(QTextStream& out, pqHapticsDockPanel* dock)
{
  const Target t = target();
  const auto* edits = dock->findChild<QLabel*>("Edits");
  out << "loaded_edits_label = " << (edits ? edits->text() : QString("(missing)")) << "\n";
  if (!t.input() || !t.output())
  {
    return;
  }
  out << "loaded_edit_history = "
      << vtkSMPropertyHelper(t.proxy, "EditHistory").GetNumberOfElements() << "\n";
  double b[6];
  t.output()->GetBounds(b);
  out << "loaded_bounds = " << text(b, 6) << "\n";
  const std::vector<double> rest = pointsOf(t.input());
  if (QPushButton* dockUndo = dockButton(dock, "UndoEdit"))
  {
    dockUndo->click();
    renderNow();
    out << "loaded_undo_label = " << (edits ? edits->text() : QString()) << "\n";
    out << "loaded_undo_equals_rest = " << int(pointsOf(t.output()) == rest) << "\n";
    writeSettled(out, "loaded_undo", t, exactBounds(t.input()));
  }
}

} // namespace pqHapticsUndoChecks
