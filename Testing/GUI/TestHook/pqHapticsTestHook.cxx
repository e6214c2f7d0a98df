#include "pqHapticsTestHook.h"

#include "pqHapticsDockPanel.h"
#include "pqHapticsProxies.h"
#include "pqHapticsTestScript.h"
#include "pqHapticsUndoChecks.h"
#include "pqPullTestDriver.h"

#include "geoshaping/edit/edit_history.h"
#include "geoshaping/haptics/trace.h"

#include <pqActiveObjects.h>
#include <pqApplicationCore.h>
#include <pqCoreUtilities.h>
#include <pqDataRepresentation.h>
#include <pqObjectBuilder.h>
#include <pqPipelineSource.h>
#include <pqRenderView.h>
#include <pqServer.h>
#include <pqView.h>

#include <vtkAlgorithm.h>
#include <vtkCamera.h>
#include <vtkCommand.h>
#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkPointSet.h>
#include <vtkPoints.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkSMPropertyHelper.h>
#include <vtkSMProxy.h>
#include <vtkSMRenderViewProxy.h>

#include <QCoreApplication>
#include <QFile>
#include <QLabel>
#include <QPixmap>
#include <QPushButton>
#include <QStringList>
#include <QTextStream>
#include <QTimer>

#include <dlfcn.h>

#include <algorithm>
#include <thread>
#include <vector>

void pqHapticsTestHook::installIfRequested(pqHapticsDockPanel* dock)
{
  const QString trace = qEnvironmentVariable("GEOSHAPING_HAPTICS_REPLAY");
  if (!trace.isEmpty())
  {
    new pqHapticsTestHook(dock, trace, qEnvironmentVariable("GEOSHAPING_HAPTICS_TEST_OUTPUT"));
  }
}

pqHapticsTestHook::pqHapticsTestHook(
  pqHapticsDockPanel* dock, const QString& trace, const QString& output)
  : QObject(dock)
  , Dock(dock)
  , Trace(trace)
  , Trace2(qEnvironmentVariable("GEOSHAPING_HAPTICS_REPLAY2"))
  , Output(output)
{
  const QString script = qEnvironmentVariable("GEOSHAPING_HAPTICS_SCRIPT");
  if (!script.isEmpty())
  {
    this->Script = std::make_shared<pqHapticsTestScript>(dock, script, output);
  }
  // Counted as the dock sees them: until writeResults() checks undo and redo, every
  // such edit is a release's commit.
  QObject::connect(dock->interactor(), &pqHapticsInteractor::editsChanged, this,
    [this]() { this->Commits += this->Dock->interactor()->lastEditResult().changed ? 1 : 0; });
  // GEOSHAPING_HAPTICS_PATCH_BUDGET_MS: how long a server's contact patch may take before
  // the next frame keeps it (0: every one is late).
  if (qEnvironmentVariableIsSet("GEOSHAPING_HAPTICS_PATCH_BUDGET_MS"))
  {
    dock->interactor()->proxies().setPatchBudget(
      qEnvironmentVariable("GEOSHAPING_HAPTICS_PATCH_BUDGET_MS").toDouble());
  }
  const QStringList stall = qEnvironmentVariable("GEOSHAPING_HAPTICS_STALL").split(',');
  if (stall.size() == 2)
  {
    this->StallAt = stall[0].toDouble();
    this->StallFor = stall[1].toDouble();
  }
  auto* timer = new QTimer(this);
  QObject::connect(timer, &QTimer::timeout, this, &pqHapticsTestHook::poll);
  timer->start(100);
}

void pqHapticsTestHook::poll()
{
  // A test must end: after 45 s (GEOSHAPING_HAPTICS_TEST_TIMEOUT seconds) write what
  // there is (started/timed_out tell) and quit.
  const int timeout = qEnvironmentVariableIsSet("GEOSHAPING_HAPTICS_TEST_TIMEOUT")
                        ? qEnvironmentVariableIntValue("GEOSHAPING_HAPTICS_TEST_TIMEOUT")
                        : 45;
  if (++this->Polls > 10 * timeout && !this->Output.isEmpty())
  {
    this->TimedOut = true;
    this->writeResults();
    return;
  }
  if (!this->Started)
  {
    if (!this->serverReady())
    {
      return;
    }
    if (this->StateLoad == LoadStage::NotAsked && qEnvironmentVariableIsSet("GEOSHAPING_GUI_STATE"))
    {
      // Not inside this slot: Qt does not fire a timer again while its slot runs, and
      // a load processes events, so the time-out above must stay alive meanwhile.
      this->StateLoad = LoadStage::Loading;
      QTimer::singleShot(0, this,
        [this]()
        {
          pqHapticsUndoChecks::loadStateIfRequested();
          this->StateLoad = LoadStage::Loaded;
        });
      return;
    }
    if (this->StateLoad == LoadStage::Loading)
    {
      return;
    }
    // Wait for the pipeline (the --script that builds it runs after the plugin loads).
    // The script's renders process events, so this timer fires mid-script: a test's
    // setup says when it is complete (gui_scene.py, GEOSHAPING_GUI_SCENE_READY) and a
    // loaded state is complete; a demo's own script is given one more second.
    // A setup whose script builds the deformation through the GUI (the hook's `apply`,
    // dem_ready) starts without one (GEOSHAPING_GUI_BUILDS_PIPELINE).
    const bool later = qEnvironmentVariableIsSet("GEOSHAPING_GUI_BUILDS_PIPELINE");
    if ((!later && !pqHapticsFindSource("ChainMailDeformation")) ||
        !pqActiveObjects::instance().activeView())
    {
      this->ReadyPolls = 0;
      return;
    }
    const bool ready = this->StateLoad == LoadStage::Loaded ||
                       qEnvironmentVariableIsSet("GEOSHAPING_GUI_SCENE_READY");
    if (!ready && (!this->Output.isEmpty() || ++this->ReadyPolls < 10))
    {
      return;
    }
    const bool mouse = this->Trace == "mouse" || this->Trace == "pull" || this->Trace == "state";
    const bool openHaptics = this->Trace == "openhaptics";
    this->Dock->setHand(0,
      openHaptics ? pqHapticsInteractor::OpenHaptics
                  : (mouse ? pqHapticsInteractor::Mouse : pqHapticsInteractor::ReplayFile),
      mouse || openHaptics ? QString() : this->Trace,
      qEnvironmentVariable("GEOSHAPING_HAPTICS_TOOL1") == "hold_and_turn"
        ? geoshaping::interactor::Tool::hold_and_turn
        : geoshaping::interactor::Tool::deform);
    if (this->Trace2.isEmpty())
    {
      this->Dock->setHand(
        1, pqHapticsInteractor::NoDevice, QString(), geoshaping::interactor::Tool::hold_and_turn);
    }
    else
    {
      this->Dock->setHand(
        1, pqHapticsInteractor::ReplayFile, this->Trace2, geoshaping::interactor::Tool::paint);
    }
    if (!this->Output.isEmpty())
    {
      this->Dock->setRecordPath(this->Output + ".recorded.trace");
    }
    this->Started = this->Dock->start();
    double duration = 0.0; // of the longest replayed trace (ReplayDevice::duration)
    for (const QString& path : { this->Trace, this->Trace2 })
    {
      const auto trace = path.isEmpty() || mouse || openHaptics
                           ? geoshaping::haptics::TraceParseResult()
                           : geoshaping::haptics::read_trace_file(path.toStdString());
      if (!trace.samples.empty())
      {
        duration = std::max(duration, trace.samples.back().t);
      }
    }
    this->ReplaysStart = std::chrono::steady_clock::now();
    this->ReplaysEnd =
      this->ReplaysStart + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                             std::chrono::duration<double>(duration));
    if (!this->Started && !this->Output.isEmpty())
    {
      this->writeResults();
    }
    return;
  }
  if (this->Script)
  {
    if (this->Script->step(this->ReplaysStart) && !this->Output.isEmpty())
    {
      this->writeResults();
    }
    return;
  }
  if (this->Trace == "mouse")
  {
    this->dragMouse();
    return;
  }
  if (this->Trace == "openhaptics")
  {
    this->faultOpenHaptics();
    return;
  }
  if (this->Trace == "pull")
  {
    this->Pull =
      this->Pull ? this->Pull : std::make_shared<pqPullTestDriver>(this->Dock, this->Output);
    if (this->Pull->step() && !this->Output.isEmpty())
    {
      this->writeResults();
    }
    return;
  }
  if (this->Trace == "state")
  {
    if (++this->FinishedPolls == 10 && !this->Output.isEmpty())
    {
      this->writeResults(); // a second after Start, nothing dragged
    }
    return;
  }
  if (this->StallAt >= 0.0 && std::chrono::steady_clock::now() - this->ReplaysStart >
                                std::chrono::duration<double>(this->StallAt))
  {
    // A GUI stall: this thread renders nothing and publishes no scene meanwhile.
    const auto before = std::chrono::steady_clock::now();
    std::this_thread::sleep_for(std::chrono::duration<double>(this->StallFor));
    this->Stalled =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - before).count();
    this->StallAt = -1.0;
  }
  // A few frames after the trace is over, so the last sample has been rendered.
  if (std::chrono::steady_clock::now() > this->ReplaysEnd && ++this->FinishedPolls >= 5)
  {
    if (!this->Output.isEmpty())
    {
      this->writeResults();
    }
  }
}

bool pqHapticsTestHook::serverReady() const
{
  // GEOSHAPING_GUI_SERVER_PROCESSES=N: paraview connects to an N-process pvserver
  // (--url). The connection processes events, so this timer fires during it: nothing
  // is done before the client is connected to all N processes.
  const int processes = qEnvironmentVariableIntValue("GEOSHAPING_GUI_SERVER_PROCESSES");
  if (processes <= 0)
  {
    return true;
  }
  pqServer* server = pqActiveObjects::instance().activeServer();
  return server && server->isRemote() && server->getNumberOfPartitions() == processes &&
         !pqApplicationCore::instance()->getObjectBuilder()->waitingForConnection();
}

void pqHapticsTestHook::dragMouse()
{
  // Press at 30 % of the width, half the height (on the horizon's upper side in the GUI
  // test's camera), drag 60 pixels up in 6 steps, release; one step per poll.
  auto* view = qobject_cast<pqRenderView*>(pqActiveObjects::instance().activeView());
  vtkRenderWindowInteractor* interactor =
    view ? view->getRenderViewProxy()->GetInteractor() : nullptr;
  if (!interactor)
  {
    return;
  }
  const int step = this->MouseSteps++;
  const int* size = interactor->GetSize();
  const int x = static_cast<int>(0.3 * size[0]);
  const int y = size[1] / 2 + 10 * std::min(std::max(step - 1, 0), 6);
  interactor->SetEventInformation(x, y, 0, 0);
  if (step == 1)
  {
    interactor->InvokeEvent(vtkCommand::LeftButtonPressEvent);
  }
  else if (step > 1 && step <= 7)
  {
    interactor->InvokeEvent(vtkCommand::MouseMoveEvent);
  }
  else if (step == 10)
  {
    interactor->InvokeEvent(vtkCommand::LeftButtonReleaseEvent);
  }
  else if (step == 14 && !this->Output.isEmpty())
  {
    this->writeResults();
  }
}

void pqHapticsTestHook::faultOpenHaptics()
{
  // Hand 1 runs on the fake HD library (GEOSHAPING_LIBHD): one second healthy, then a
  // device fault through the fake's test control, then one second for the dock to say so.
  void* fake = dlopen(qgetenv("GEOSHAPING_LIBHD").constData(), RTLD_NOW | RTLD_NOLOAD);
  const int step = this->FaultSteps++;
  if (step == 10 && fake)
  {
    reinterpret_cast<void (*)()>(dlsym(fake, "fakehd_inject_fault"))();
  }
  else if (step == 20 && fake)
  {
    double f[3];
    reinterpret_cast<void (*)(double*)>(dlsym(fake, "fakehd_last_force"))(f);
    this->FakeForce = QString("%1 %2 %3").arg(f[0]).arg(f[1]).arg(f[2]);
    this->writeResults();
  }
  if (fake)
  {
    dlclose(fake);
  }
}

namespace
{
std::vector<double> pointsOf(vtkPointSet* data)
{
  std::vector<double> xyz(3 * data->GetNumberOfPoints());
  for (vtkIdType i = 0; i < data->GetNumberOfPoints(); ++i)
  {
    data->GetPoint(i, &xyz[3 * i]);
  }
  return xyz;
}
}

void pqHapticsTestHook::checkEdits(QTextStream& out, vtkPointSet* input, vtkPointSet* output)
{
  // The release committed (docs/editing.md): one record in the client's EditHistory,
  // the proxy released, and the output stays deformed. Then the dock's Undo button must
  // give back the input bit for bit, and Redo the released shape bit for bit.
  pqPipelineSource* source = pqHapticsFindSource("ChainMailDeformation");
  vtkSMProxy* proxy = source->getProxy();
  auto* filter = vtkAlgorithm::SafeDownCast(proxy->GetClientSideObject());
  auto shown = [filter, output]()
  {
    auto* now = filter ? vtkPointSet::SafeDownCast(filter->GetOutputDataObject(0)) : nullptr;
    return now ? now : output;
  };
  out << "edit_history = " << vtkSMPropertyHelper(proxy, "EditHistory").GetNumberOfElements()
      << "\n";
  out << "grasp_point_id_after_release = "
      << vtkSMPropertyHelper(proxy, "GraspPointId").GetAsIdType() << "\n";
  const std::vector<double> rest = pointsOf(input);
  const std::vector<double> released = pointsOf(output);
  out << "released_differs_from_rest = " << int(released != rest) << "\n";
  auto* undo = this->Dock->findChild<QPushButton*>("UndoEdit");
  auto* redo = this->Dock->findChild<QPushButton*>("RedoEdit");
  if (!undo || !redo)
  {
    out << "edit_buttons = 0\n";
    return;
  }
  out << "edit_buttons = 1\n";
  undo->click();
  out << "edit_history_after_undo = "
      << vtkSMPropertyHelper(proxy, "EditHistory").GetNumberOfElements() << "\n";
  out << "undo_equals_rest = " << int(pointsOf(shown()) == rest) << "\n";
  redo->click();
  out << "edit_history_after_redo = "
      << vtkSMPropertyHelper(proxy, "EditHistory").GetNumberOfElements() << "\n";
  out << "redo_equals_released = " << int(pointsOf(shown()) == released) << "\n";
}

// The Displacement the last committed edit was made with (its record's recipe: the
// Displacement the interactor last sent before the release).
void pqHapticsTestHook::writeCommittedDisplacement(QTextStream& out)
{
  pqPipelineSource* source = pqHapticsFindSource("ChainMailDeformation");
  if (!source)
  {
    return;
  }
  vtkSMPropertyHelper history(source->getProxy(), "EditHistory");
  const unsigned int n = history.GetNumberOfElements();
  geoshaping::Edit edit;
  std::string error;
  if (n > 0 && geoshaping::decode_edit(history.GetAsString(n - 1), edit, error))
  {
    const Eigen::Vector3d& d = edit.recipe.displacement;
    out << "last_displacement = " << d.x() << " " << d.y() << " " << d.z() << "\n";
  }
}

// What the paint filter did: its PointDabs (dabs on the shown surface), and the vertices
// whose malleability it changed (its output against its input's array).
void pqHapticsTestHook::writePaint(QTextStream& out)
{
  pqPipelineSource* paint = pqHapticsFindSource("MalleabilityPaint");
  vtkSMProxy* proxy = paint ? paint->getProxy() : nullptr;
  auto* filter = proxy ? vtkAlgorithm::SafeDownCast(proxy->GetClientSideObject()) : nullptr;
  if (!filter)
  {
    return;
  }
  out << "point_dab_values = " << vtkSMPropertyHelper(proxy, "PointDabs").GetNumberOfElements()
      << "\n";
  out << "dab_values = " << vtkSMPropertyHelper(proxy, "Dabs").GetNumberOfElements() << "\n";
  auto* input = vtkPointSet::SafeDownCast(filter->GetInputDataObject(0, 0));
  auto* output = vtkPointSet::SafeDownCast(filter->GetOutputDataObject(0));
  vtkDataArray* before = input ? input->GetPointData()->GetArray("Malleability") : nullptr;
  vtkDataArray* after = output ? output->GetPointData()->GetArray("Malleability") : nullptr;
  if (before && after && before->GetNumberOfTuples() == after->GetNumberOfTuples())
  {
    vtkIdType changed = 0;
    double lowest = 1.0;
    for (vtkIdType i = 0; i < after->GetNumberOfTuples(); ++i)
    {
      if (after->GetTuple1(i) != before->GetTuple1(i))
      {
        ++changed;
        lowest = std::min(lowest, after->GetTuple1(i) - before->GetTuple1(i));
      }
    }
    out << "painted_vertices = " << changed << "\n";
    out << "smallest_paint_increase = " << lowest << "\n";
  }
}

void pqHapticsTestHook::writeResults()
{
  QFile file(this->Output + ".txt");
  if (!file.open(QIODevice::WriteOnly | QIODevice::Text))
  {
    qCritical("GeoShaping test hook: cannot write %s", qPrintable(file.fileName()));
    QCoreApplication::exit(1);
    return;
  }
  QTextStream out(&file);
  const pqHapticsInteractor* interactor = this->Dock->interactor();
  const pqHapticsInteractor::Figures& f = interactor->figures();
  out << "started = " << int(this->Started) << "\n";
  out << "timed_out = " << int(this->TimedOut) << "\n";
  if (pqServer* server = pqActiveObjects::instance().activeServer())
  {
    out << "server_remote = " << int(server->isRemote()) << "\n";
    out << "server_processes = " << server->getNumberOfPartitions() << "\n";
  }
  out << "dock_visible = " << int(this->Dock->isVisible()) << "\n";
  out << "dock_title = " << this->Dock->windowTitle() << "\n";
  out << "frames = " << f.frames << "\n";
  out << "frames_per_second = " << f.framesPerSecond << "\n";
  out << "servo_hz = " << f.servoHz[0] << "\n";
  for (const char* name : { "Figures", "Help", "Edits" })
  {
    // What the dock's labels say, on one line; whether long text wraps.
    const QLabel* label = this->Dock->findChild<QLabel*>(name);
    out << "label_" << name << " = "
        << (label ? label->text().replace('\n', " / ") : QString("(missing)")) << "\n";
    out << "label_" << name << "_wraps = " << int(label && label->wordWrap()) << "\n";
  }
  out << "scene_units_per_metre = " << f.sceneUnitsPerMetre << "\n";
  out << "deformation_ms = " << f.deformationMilliseconds << "\n";
  out << "displaced_points = " << f.displacedPoints << "\n";
  out << "displaced_at_release = " << f.displacedAtRelease << "\n";
  out << "max_contact_triangles = " << f.maxContactTriangles << "\n";
  out << "contact_ticks = " << f.contactTicks << "\n";
  out << "gui_stall_seconds = " << this->Stalled << "\n";
  out << "recorded_samples = " << f.recordedSamples[0] << "\n";
  if (!this->FakeForce.isEmpty())
  {
    out << "fake_last_force = " << this->FakeForce << "\n"; // N, after the fault
  }
  out << "brush_value = " << interactor->brush().value << "\n";
  out << "brush_radius = " << interactor->brush().radius << "\n";
  {
    const Eigen::Matrix4d m = this->Dock->interactor()->proxies().objectMatrix();
    out << "object_matrix =";
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j)
        out << " " << QString::number(m(i, j), 'g', 17);
    out << "\n";
  }
  this->writePaint(out);
  if (this->Pull)
  {
    out << this->Pull->results();
  }
  pqHapticsTestScript::writeForce(out, f.force[0]);
  auto* view = qobject_cast<pqRenderView*>(pqActiveObjects::instance().activeView());
  if (vtkCamera* camera = view ? view->getRenderViewProxy()->GetActiveCamera() : nullptr)
  {
    const double* p = camera->GetPosition();
    out << "camera_position = " << p[0] << " " << p[1] << " " << p[2] << "\n";
  }
  this->writeCommittedDisplacement(out);

  // The deformed output against its input (builtin session: the filter itself).
  pqPipelineSource* source = pqHapticsFindSource("ChainMailDeformation");
  auto* filter =
    source ? vtkAlgorithm::SafeDownCast(source->getProxy()->GetClientSideObject()) : nullptr;
  auto* input = filter ? vtkPointSet::SafeDownCast(filter->GetInputDataObject(0, 0)) : nullptr;
  auto* output = filter ? vtkPointSet::SafeDownCast(filter->GetOutputDataObject(0)) : nullptr;
  if (input && output && input->GetNumberOfPoints() == output->GetNumberOfPoints())
  {
    long long moved = 0;
    Eigen::Vector3d largest = Eigen::Vector3d::Zero();
    for (vtkIdType i = 0; i < input->GetNumberOfPoints(); ++i)
    {
      Eigen::Vector3d a, b;
      input->GetPoint(i, a.data());
      output->GetPoint(i, b.data());
      const Eigen::Vector3d delta = b - a;
      moved += delta.norm() > 1e-9 ? 1 : 0;
      largest = delta.norm() > largest.norm() ? delta : largest;
    }
    out << "output_points = " << output->GetNumberOfPoints() << "\n";
    out << "moved_points = " << moved << "\n";
    out << "max_displacement = " << largest.x() << " " << largest.y() << " " << largest.z() << "\n";
  }
  // How the deformation was drawn (docs/rendering.md): its representation type and the
  // GeoShaping Surface representation's counters of sparse and full updates and uploads.
  pqView* shownIn = pqActiveObjects::instance().activeView();
  if (pqDataRepresentation* shown = source ? source->getRepresentation(shownIn) : nullptr)
  {
    vtkSMProxy* display = shown->getProxy();
    display->UpdatePropertyInformation();
    out << "representation = " << vtkSMPropertyHelper(display, "Representation").GetAsString()
        << "\n";
    for (const char* counter : { "NumberOfSparseUpdates", "NumberOfFullUpdates",
           "NumberOfSparseBuilds", "NumberOfFullBuilds" })
    {
      if (display->GetProperty(counter))
      {
        out << counter << " = " << vtkSMPropertyHelper(display, counter).GetAsInt() << "\n";
      }
    }
  }
  // Before the checks below, whose undo and redo the dock is told of too.
  out << "release_commits = " << this->Commits << "\n";
  if (!this->TimedOut && this->Started && input && output)
  {
    if (this->Trace == "state")
    {
      pqHapticsUndoChecks::writeLoadedState(out, this->Dock);
    }
    else if (this->Commits > 0)
    {
      pqHapticsUndoChecks::writeEditMenu(out, this->Dock);
    }
    this->checkEdits(out, input, output);
  }
  out.flush();
  pqCoreUtilities::mainWidget()->grab().save(this->Output + ".png");
  if (pqView* view = pqActiveObjects::instance().activeView())
  {
    view->widget()->grab().save(this->Output + "-view.png");
  }
  this->Dock->stop();
  QTimer::singleShot(0, qApp, []() { QCoreApplication::exit(0); });
  this->deleteLater();
}
