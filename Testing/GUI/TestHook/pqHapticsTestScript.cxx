#include "pqHapticsTestScript.h"

#include "pqHapticsTestDrawn.h"

#include "pqHapticsDockPanel.h"
#include "pqHapticsProxies.h"

#include <pqActiveObjects.h>
#include <pqApplicationCore.h>
#include <pqCoreUtilities.h>
#include <pqDataRepresentation.h>
#include <pqInputSelectorWidget.h>
#include <pqLoadDataReaction.h>
#include <pqObjectBuilder.h>
#include <pqOutputPort.h>
#include <pqPipelineBrowserWidget.h>
#include <pqPipelineSource.h>
#include <pqPropertiesPanel.h>
#include <pqRenderView.h>
#include <pqSaveStateReaction.h>
#include <pqServerManagerModel.h>
#include <pqUndoStack.h>
#include <pqView.h>

#include <vtkActor.h>
#include <vtkActorCollection.h>
#include <vtkAlgorithm.h>
#include <vtkCamera.h>
#include <vtkCellPicker.h>
#include <vtkCommand.h>
#include <vtkDataArray.h>
#include <vtkLineSource.h>
#include <vtkMapper.h>
#include <vtkMatrix4x4.h>
#include <vtkNew.h>
#include <vtkPVDataInformation.h>
#include <vtkPointData.h>
#include <vtkPointSet.h>
#include <vtkProperty.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkRenderer.h>
#include <vtkSMPropertyHelper.h>
#include <vtkSMProxy.h>
#include <vtkSMRenderViewProxy.h>
#include <vtkSMSourceProxy.h>
#include <vtkSMTransferFunctionProxy.h>
#include <vtkSphereSource.h>

#include <QVTKOpenGLNativeWidget.h>
#include <QVTKOpenGLStereoWidget.h>
#include <QVTKOpenGLWindow.h>

#include <QAbstractItemModel>
#include <QComboBox>
#include <QCoreApplication>
#include <QDoubleSpinBox>
#include <QFile>
#include <QKeyEvent>
#include <QLabel>
#include <QPixmap>
#include <QPushButton>
#include <QTest>
#include <QTextStream>
#include <QToolButton>
#include <QWidget>

pqHapticsTestScript::pqHapticsTestScript(
  pqHapticsDockPanel* dock, const QString& script, const QString& output)
  : Dock(dock)
  , Output(output)
{
  for (const QString& step : script.split(';', Qt::SkipEmptyParts))
  {
    if (!step.trimmed().isEmpty())
    {
      this->Steps << step.trimmed();
    }
  }
}

bool pqHapticsTestScript::step(std::chrono::steady_clock::time_point since)
{
  // One interactor frame after each step that it must see (a mouse event, Undo): the
  // frame timer runs at its own pace, slower on a loaded machine than these polls.
  const int frames = this->Dock->interactor()->figures().frames;
  if (frames < this->AfterFrame)
  {
    return false;
  }
  if (this->Next >= this->Steps.size())
  {
    return true;
  }
  const QStringList words = this->Steps[this->Next].split(' ', Qt::SkipEmptyParts);
  const QString& verb = words[0];
  const double seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
  if (verb == "until" && seconds < words.value(1).toDouble())
  {
    return false;
  }
  ++this->Next;
  this->AfterFrame = frames + 1;
  if (verb == "press" || verb == "move" || verb == "release" || verb == "hover" || verb == "leave")
  {
    this->mouse(words);
  }
  else if (verb == "key" && words.size() > 1)
  {
    this->key(words[1]);
  }
  else if (verb == "ctrlup")
  {
    this->key("ctrlup");
  }
  else if (verb == "swatch" && words.size() > 1)
  {
    if (auto* swatch = this->Dock->findChild<QToolButton*>("Swatch" + words[1]))
    {
      swatch->click();
    }
  }
  else if (verb == "exaggeration" && words.size() > 1)
  {
    if (auto* spin = this->Dock->findChild<QDoubleSpinBox*>("VerticalExaggeration"))
    {
      spin->setValue(words[1].toDouble());
    }
  }
  else if (verb == "radius" && words.size() > 1)
  {
    if (auto* radius = this->Dock->findChild<QDoubleSpinBox*>("BrushRadius"))
    {
      radius->setValue(words[1].toDouble());
    }
  }
  else if (verb == "undo" || verb == "redo" || verb == "snap" || verb == "showmarkers")
  {
    const char* name = verb == "undo"   ? "UndoEdit"
                       : verb == "redo" ? "RedoEdit"
                       : verb == "snap" ? "SnapToMarkers"
                                        : "ShowMarkerMisfit";
    if (auto* button = this->Dock->findChild<QPushButton*>(name))
    {
      button->click();
    }
  }
  else if (verb == "editundo" || verb == "editredo")
  {
    // What Edit > Undo / Redo (Ctrl+Z / Ctrl+Y) do.
    if (pqUndoStack* stack = pqApplicationCore::instance()->getUndoStack())
    {
      verb == "editundo" ? stack->undo() : stack->redo();
    }
  }
  else if (verb == "open" && words.size() > 1)
  {
    // File > Open of GEOSHAPING_GUI_SURFACE with the reader READER, then Apply.
    QWidget* main = pqCoreUtilities::mainWidget();
    auto* panel = main ? main->findChild<pqPropertiesPanel*>() : nullptr;
    const QString file = qEnvironmentVariable("GEOSHAPING_GUI_SURFACE");
    if (panel && pqLoadDataReaction::loadData(QStringList{ file }, "sources", words[1]))
    {
      panel->apply();
    }
  }
  else if (verb == "apply" && words.size() > 1)
  {
    // As Filters > GeoShaping > NAME then Apply: on the active source, shown by Apply.
    pqPipelineSource* input = pqActiveObjects::instance().activeSource();
    QWidget* main = pqCoreUtilities::mainWidget();
    auto* panel = main ? main->findChild<pqPropertiesPanel*>() : nullptr;
    if (input && panel &&
        pqApplicationCore::instance()->getObjectBuilder()->createFilter("filters", words[1], input))
    {
      panel->apply();
    }
  }
  else if (verb == "elevation" && words.size() > 1)
  {
    // The user turns the camera DEGREES up about the focal point, as a mouse orbit does.
    if (auto* view = qobject_cast<pqRenderView*>(pqActiveObjects::instance().activeView()))
    {
      vtkCamera* camera = view->getRenderViewProxy()->GetActiveCamera();
      camera->Elevation(words[1].toDouble());
      camera->OrthogonalizeViewUp();
      view->getRenderViewProxy()->SynchronizeCameraProperties();
      view->render();
    }
  }
  else if (verb == "obstacle" && words.size() > 1)
  {
    this->chooseObstacle(words[1]);
  }
  else if (verb == "snapshot" && words.size() > 1)
  {
    this->snapshot(words[1]);
  }
  else if (verb == "dump" && words.size() > 1)
  {
    this->dump(words[1]);
  }
  else if (verb == "savestate")
  {
    pqSaveStateReaction::saveState(this->Output + ".pvsm");
  }
  return false;
}

void pqHapticsTestScript::mouse(const QStringList& words)
{
  auto* view = qobject_cast<pqRenderView*>(pqActiveObjects::instance().activeView());
  vtkSMRenderViewProxy* proxy = view ? view->getRenderViewProxy() : nullptr;
  vtkRenderWindowInteractor* interactor = proxy ? proxy->GetInteractor() : nullptr;
  if (!interactor)
  {
    return;
  }
  if (words[0] == "release" || words[0] == "leave")
  {
    interactor->InvokeEvent(
      words[0] == "release" ? vtkCommand::LeftButtonReleaseEvent : vtkCommand::LeaveEvent);
    return;
  }
  const int* size = interactor->GetSize();
  int display[2] = { static_cast<int>(words.value(1).toDouble() * size[0]),
    static_cast<int>(words.value(2).toDouble() * size[1]) };
  const bool ctrl = words.value(3) == "ctrl";
  interactor->SetEventInformation(display[0], display[1], ctrl ? 1 : 0, 0);
  interactor->InvokeEvent(
    words[0] == "press" ? vtkCommand::LeftButtonPressEvent : vtkCommand::MouseMoveEvent);
  // The point the mouse hand took (the same pick, in the same render, as pqHapticsMouse),
  // then the point drawn there as VTK's own picker finds it on the geometry the client
  // draws (through each actor's matrix: a display Scale included), or nan.
  double p[3], normal[3];
  const pqScopedUndoExclude pick; // the test's pick is no step of the undo stack
  QFile file(this->Output + ".picks");
  if (proxy->ConvertDisplayToPointOnSurface(display, p, normal) &&
      file.open(QIODevice::Append | QIODevice::Text))
  {
    QTextStream line(&file);
    line << words[0];
    for (double v : p)
    {
      line << " " << QString::number(v, 'g', 17);
    }
    vtkNew<vtkCellPicker> picker;
    picker->SetTolerance(0.0);
    const bool drawn = picker->Pick(display[0], display[1], 0.0, proxy->GetRenderer()) != 0;
    const double* q = picker->GetPickPosition();
    for (int k = 0; k < 3; ++k)
    {
      line << " " << (drawn ? QString::number(q[k], 'g', 17) : QString("nan"));
    }
    line << "\n";
  }
}

void pqHapticsTestScript::key(const QString& key)
{
  // To the widget (or window) that shows the view, where a user's key goes once the view
  // is clicked, with Qt's shortcut override first: a ParaView shortcut on the key would
  // take it, as it would from the user.
  pqView* view = pqActiveObjects::instance().activeView();
  QWidget* widget = view ? view->widget() : nullptr;
  const QKeySequence sequence(key);
  if (key == "ctrlup")
  {
    // Ctrl let go while the keyboard focus is outside the view (hovering does not give it
    // the focus): the key goes to the focused widget, here the dock, with the modifiers
    // as X11 reports them, Ctrl still on.
    QKeyEvent release(QEvent::KeyRelease, Qt::Key_Control, Qt::ControlModifier);
    QCoreApplication::sendEvent(this->Dock, &release);
    return;
  }
  if (!widget || sequence.count() != 1)
  {
    return;
  }
  const auto code = Qt::Key(sequence[0] & ~Qt::KeyboardModifierMask);
  const auto modifiers = Qt::KeyboardModifiers(sequence[0] & Qt::KeyboardModifierMask);
  if (auto* native = widget->findChild<QVTKOpenGLNativeWidget*>())
  {
    QTest::keyClick(native, code, modifiers);
  }
  else if (auto* stereo = widget->findChild<QVTKOpenGLStereoWidget*>())
  {
    QTest::keyClick(stereo->embeddedOpenGLWindow(), code, modifiers);
  }
}

namespace
{
vtkPointSet* output(pqPipelineSource* source, bool input)
{
  auto* algorithm =
    source ? vtkAlgorithm::SafeDownCast(source->getProxy()->GetClientSideObject()) : nullptr;
  if (!algorithm)
  {
    return nullptr;
  }
  return vtkPointSet::SafeDownCast(
    input ? algorithm->GetInputDataObject(0, 0) : algorithm->GetOutputDataObject(0));
}

QString text(QWidget* dock, const char* name)
{
  if (auto* label = dock->findChild<QLabel*>(name))
  {
    return label->text().replace('\n', " / ");
  }
  if (auto* spin = dock->findChild<QDoubleSpinBox*>(name))
  {
    return spin->text();
  }
  return "(missing)";
}
}

void pqHapticsTestScript::chooseObstacle(const QString& name)
{
  // As a user does: in the Properties panel of the active ChainMailDeformation, the
  // Obstacles' Pipeline Connection Input set to `name`, then Apply.
  QWidget* main = pqCoreUtilities::mainWidget();
  auto* panel = main ? main->findChild<pqPropertiesPanel*>() : nullptr;
  auto* selector = panel ? panel->findChild<pqInputSelectorWidget*>() : nullptr;
  auto* combo = selector ? selector->findChild<QComboBox*>() : nullptr;
  const int index = combo ? combo->findText(name) : -1;
  if (index >= 0)
  {
    combo->setCurrentIndex(index);
    panel->apply();
  }
}

namespace
{
// The names the Pipeline Browser shows, every row of its tree, separated by ','.
QString pipelineRows()
{
  QWidget* main = pqCoreUtilities::mainWidget();
  auto* browser = main ? main->findChild<pqPipelineBrowserWidget*>() : nullptr;
  QAbstractItemModel* model = browser ? browser->getModel() : nullptr;
  QStringList rows;
  std::vector<QModelIndex> todo{ QModelIndex() };
  while (model && !todo.empty())
  {
    const QModelIndex parent = todo.back();
    todo.pop_back();
    for (int r = 0; r < model->rowCount(parent); ++r)
    {
      const QModelIndex row = model->index(r, 0, parent);
      rows << model->data(row, Qt::DisplayRole).toString();
      todo.push_back(row);
    }
  }
  return rows.join(",");
}
}

void pqHapticsTestScript::snapshot(const QString& name)
{
  const QString prefix = this->Output + "-" + name;
  pqPipelineSource* paint = pqHapticsFindSource("MalleabilityPaint");
  pqPipelineSource* deformation = pqHapticsFindSource("ChainMailDeformation");
  vtkPointSet* rest = output(paint, true);
  vtkPointSet* painted = output(paint, false);
  vtkPointSet* shown = output(deformation, false);
  vtkDataArray* m = painted ? painted->GetPointData()->GetArray("Malleability") : nullptr;
  vtkDataArray* e = shown ? shown->GetPointData()->GetArray("Elevation") : nullptr;
  vtkDataArray* re = shown ? shown->GetPointData()->GetArray("RestElevation") : nullptr;
  QFile csv(prefix + ".csv");
  if (rest && shown && m && rest->GetNumberOfPoints() == shown->GetNumberOfPoints() &&
      csv.open(QIODevice::WriteOnly | QIODevice::Text))
  {
    QTextStream out(&csv);
    out << "x y z sx sy sz m" << (e && re ? " e re" : "") << "\n";
    for (vtkIdType i = 0; i < rest->GetNumberOfPoints(); ++i)
    {
      double p[3], s[3];
      rest->GetPoint(i, p);
      shown->GetPoint(i, s);
      for (double v : { p[0], p[1], p[2], s[0], s[1], s[2] })
      {
        out << QString::number(v, 'g', 17) << " ";
      }
      out << QString::number(m->GetTuple1(i), 'g', 9);
      if (e && re)
      {
        out << " " << QString::number(e->GetTuple1(i), 'g', 17) << " "
            << QString::number(re->GetTuple1(i), 'g', 17);
      }
      out << "\n";
    }
  }
  auto* view = qobject_cast<pqRenderView*>(pqActiveObjects::instance().activeView());
  QFile file(prefix + ".txt");
  if (file.open(QIODevice::WriteOnly | QIODevice::Text))
  {
    QTextStream out(&file);
    const pqHapticsInteractor* interactor = this->Dock->interactor();
    out << "brush_radius = " << QString::number(interactor->brush().radius, 'g', 17) << "\n";
    out << "brush_value = " << interactor->brush().value << "\n";
    out << "brush_strength = " << interactor->brush().strength << "\n";
    if (vtkSMProxy* proxy = paint ? paint->getProxy() : nullptr)
    {
      out << "BrushRadius = " << vtkSMPropertyHelper(proxy, "BrushRadius").GetAsDouble() << "\n";
      out << "Falloff = " << vtkSMPropertyHelper(proxy, "Falloff").GetAsInt() << "\n";
      out << "dab_values = " << vtkSMPropertyHelper(proxy, "Dabs").GetNumberOfElements() << "\n";
      out << "point_dab_values = " << vtkSMPropertyHelper(proxy, "PointDabs").GetNumberOfElements()
          << "\n";
    }
    if (vtkSMProxy* proxy = deformation ? deformation->getProxy() : nullptr)
    {
      out << "edit_history = " << vtkSMPropertyHelper(proxy, "EditHistory").GetNumberOfElements()
          << "\n";
      double d[3];
      vtkSMPropertyHelper(proxy, "Displacement").Get(d, 3);
      out << "Displacement = " << QString::number(d[0], 'g', 17) << " "
          << QString::number(d[1], 'g', 17) << " " << QString::number(d[2], 'g', 17) << "\n";
      out << "GraspPointId = " << vtkSMPropertyHelper(proxy, "GraspPointId").GetAsIdType() << "\n";
      proxy->UpdatePropertyInformation();
      out << "NumberOfObstacleBlockedPoints = "
          << vtkSMPropertyHelper(proxy, "NumberOfObstacleBlockedPoints").GetAsIdType() << "\n";
    }
    out << "pipeline = " << pipelineRows() << "\n";
    if (pqPipelineSource* misfit = pqHapticsFindSource("MarkerMisfit"))
    {
      // How the markers are drawn (pqHapticsMarkers.h) and their Misfit range.
      pqDataRepresentation* repr = view ? misfit->getRepresentation(0, view) : nullptr;
      vtkSMProxy* r = repr ? repr->getProxy() : nullptr;
      out << "marker_misfit_representation = "
          << (r ? vtkSMPropertyHelper(r, "Representation").GetAsString() : "(none)") << "\n";
      out << "marker_misfit_color = "
          << (r ? vtkSMPropertyHelper(r, "ColorArrayName").GetAsString(4) : "(none)") << "\n";
      out << "marker_misfit_visible = " << (r ? vtkSMPropertyHelper(r, "Visibility").GetAsInt() : 0)
          << "\n";
      vtkSMProxy* lut = r ? vtkSMPropertyHelper(r, "LookupTable", true).GetAsProxy() : nullptr;
      double range[2] = { 0.0, 0.0 };
      if (lut)
      {
        vtkSMTransferFunctionProxy::GetRange(lut, range);
      }
      out << "marker_misfit_range = " << range[0] << " " << range[1] << "\n";
      out << "marker_misfit_points = "
          << misfit->getOutputPort(0)->getDataInformation()->GetNumberOfPoints() << "\n";
    }
    pqHapticsWriteShown(out);
    pqHapticsWriteDrawnGrasp(out, deformation, shown);
    // The cursors shown (the view's visible sphere actors other than the data) and the
    // lines shown from a grasp marker to its cursor.
    int cursors = 0;
    QStringList tethers;
    vtkRenderer* renderer = view ? view->getRenderViewProxy()->GetRenderer() : nullptr;
    vtkActorCollection* actors = renderer ? renderer->GetActors() : nullptr;
    vtkCollectionSimpleIterator it;
    if (actors)
    {
      actors->InitTraversal(it);
    }
    while (vtkActor* actor = actors ? actors->GetNextActor(it) : nullptr)
    {
      vtkAlgorithm* source = actor->GetMapper() ? actor->GetMapper()->GetInputAlgorithm() : nullptr;
      auto* sphere = vtkSphereSource::SafeDownCast(source);
      auto* line = vtkLineSource::SafeDownCast(source);
      if (sphere && actor->GetVisibility())
      {
        const double* c = sphere->GetCenter();
        out << "cursor_" << cursors++ << " = " << QString::number(c[0], 'g', 17) << " "
            << QString::number(c[1], 'g', 17) << " " << QString::number(c[2], 'g', 17) << " "
            << QString::number(sphere->GetRadius(), 'g', 17) << " "
            << actor->GetProperty()->GetRepresentation() << " "
            << QString::number(actor->GetMatrix()->GetElement(2, 2), 'g', 17) << "\n";
      }
      if (line && actor->GetVisibility())
      {
        QStringList ends;
        for (const double* p : { line->GetPoint1(), line->GetPoint2() })
        {
          for (int k = 0; k < 3; ++k)
          {
            ends << QString::number(p[k], 'g', 17);
          }
        }
        out << "tether_" << tethers.size() << " = " << ends.join(" ") << "\n";
        tethers << ends.join(" ");
      }
    }
    out << "cursors = " << cursors << "\n";
    out << "tethers = " << tethers.size() << "\n";
    if (auto* pull = this->Dock->findChild<QComboBox*>("PullConstraint"))
    {
      out << "pull_constraint = " << pull->currentData().toInt() << "\n";
    }
    for (const char* label :
      { "BrushRadius", "BrushRadiusAbout", "BrushNote", "Edits", "PullMode", "Figures" })
    {
      out << "label_" << label << " = " << text(this->Dock, label) << "\n";
    }
  }
  if (view)
  {
    view->widget()->grab().save(prefix + ".png");
  }
}

void pqHapticsTestScript::dump(const QString& name)
{
  // The server writes every rank's points: the ProgrammableFilter after the deformation
  // (in the test's scene, gui_pvserver.py) runs again with `name` on its first line. The
  // client writes what its proxy says (the edits, the grasp) beside them.
  pqPipelineSource* dumper = pqHapticsFindSource("ProgrammableFilter");
  pqPipelineSource* deformation = pqHapticsFindSource("ChainMailDeformation");
  if (!dumper || !deformation)
  {
    return;
  }
  const pqScopedUndoExclude dumping; // the test's dump is no step of the undo stack
  vtkSMProxy* proxy = dumper->getProxy();
  QStringList script = QString(vtkSMPropertyHelper(proxy, "Script").GetAsString()).split('\n');
  script[0] = "name = '" + name + "'";
  vtkSMPropertyHelper(proxy, "Script").Set(script.join('\n').toUtf8().constData());
  proxy->UpdateVTKObjects();
  vtkSMSourceProxy::SafeDownCast(proxy)->UpdatePipeline();
  QFile file(this->Output + "-" + name + ".txt");
  if (!file.open(QIODevice::WriteOnly | QIODevice::Text))
  {
    return;
  }
  QTextStream out(&file);
  vtkSMProxy* chain = deformation->getProxy();
  chain->UpdatePropertyInformation();
  out << "grasp_mode = " << vtkSMPropertyHelper(chain, "GraspMode").GetAsInt() << "\n";
  out << "grasp_point_id = " << vtkSMPropertyHelper(chain, "GraspPointId").GetAsIdType() << "\n";
  out << "last_grasp_point_id = " << vtkSMPropertyHelper(chain, "LastGraspPointId").GetAsIdType()
      << "\n";
  out << "last_grasp_malleability = "
      << QString::number(vtkSMPropertyHelper(chain, "LastGraspMalleability").GetAsDouble(), 'g', 17)
      << "\n";
  for (const char* vector : { "GraspPosition", "Displacement" })
  {
    out << vector << " =";
    for (int k = 0; k < 3; ++k)
    {
      out << " " << QString::number(vtkSMPropertyHelper(chain, vector).GetAsDouble(k), 'g', 17);
    }
    out << "\n";
  }
  vtkSMPropertyHelper edits(chain, "EditHistory");
  out << "edit_history = " << edits.GetNumberOfElements() << "\n";
  for (unsigned int i = 0; i < edits.GetNumberOfElements(); ++i)
  {
    out << "edit_" << i << " = " << edits.GetAsString(i) << "\n";
  }
  if (pqPipelineSource* paint = pqHapticsFindSource("MalleabilityPaint"))
  {
    for (const char* list : { "Dabs", "PointDabs" })
    {
      vtkSMPropertyHelper values(paint->getProxy(), list);
      out << list << " =";
      for (unsigned int i = 0; i < values.GetNumberOfElements(); ++i)
      {
        out << " " << QString::number(values.GetAsDouble(i), 'g', 17);
      }
      out << "\n";
    }
  }
  pqHapticsTestScript::writeForce(out, this->Dock->interactor()->figures().force[0]);
  // What the dock's figures say (the server patch's round trip among them), on one line.
  const QLabel* label = this->Dock->findChild<QLabel*>("Figures");
  out << "label_Figures = " << (label ? label->text().replace('\n', " / ") : QString("(missing)"))
      << "\n";
}

void pqHapticsTestScript::writeForce(
  QTextStream& out, const geoshaping::haptics::ForceResult& force)
{
  out << "force_from_last_scene = " << QString::number(force.force.x(), 'g', 17) << " "
      << QString::number(force.force.y(), 'g', 17) << " "
      << QString::number(force.force.z(), 'g', 17) << "\n";
  out << "force_status = " << geoshaping::haptics::to_string(force.status) << "\n";
  out << "in_contact_last_scene = " << int(force.in_contact) << "\n";
}
