#include "pqPullTestDriver.h"

#include "pqHapticsDockPanel.h"

#include <pqActiveObjects.h>
#include <pqApplicationCore.h>
#include <pqDataRepresentation.h>
#include <pqPipelineSource.h>
#include <pqRenderView.h>
#include <pqServerManagerModel.h>

#include <vtkAlgorithm.h>
#include <vtkCell.h>
#include <vtkCommand.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPointSet.h>
#include <vtkPolygon.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkRenderer.h>
#include <vtkSMPropertyHelper.h>
#include <vtkSMRenderViewProxy.h>

#include <QComboBox>
#include <QFormLayout>
#include <QLabel>
#include <QPixmap>
#include <QTextStream>

#include <cmath>

namespace
{
// Cursor motion of every pull, in 5 steps.
constexpr int MotionX = 60;
constexpr int MotionY = 40;
constexpr int Steps = 5;

pqRenderView* activeView()
{
  return qobject_cast<pqRenderView*>(pqActiveObjects::instance().activeView());
}

pqPipelineSource* findSource(const char* name)
{
  return pqApplicationCore::instance()->getServerManagerModel()->findItem<pqPipelineSource*>(
    QString(name));
}

vtkPointSet* data(pqPipelineSource* source, bool input)
{
  auto* filter = vtkAlgorithm::SafeDownCast(source->getProxy()->GetClientSideObject());
  return filter ? vtkPointSet::SafeDownCast(
                    input ? filter->GetInputDataObject(0, 0) : filter->GetOutputDataObject(0))
                : nullptr;
}

Eigen::Vector3d toDisplay(vtkRenderer* renderer, const Eigen::Vector3d& world)
{
  renderer->SetWorldPoint(world.x(), world.y(), world.z(), 1.0);
  renderer->WorldToDisplay();
  return Eigen::Map<const Eigen::Vector3d>(renderer->GetDisplayPoint());
}

Eigen::Vector3d toWorld(vtkRenderer* renderer, double x, double y, double depth)
{
  renderer->SetDisplayPoint(x, y, depth);
  renderer->DisplayToWorld();
  const double* w = renderer->GetWorldPoint();
  return Eigen::Vector3d(w[0], w[1], w[2]) / w[3];
}

QString text(const Eigen::Vector3d& v)
{
  return QString("%1 %2 %3").arg(v.x(), 0, 'g', 17).arg(v.y(), 0, 'g', 17).arg(v.z(), 0, 'g', 17);
}

const char* const Unit = "Pull unit";
const char* const Large = "Pull 1000 km";
}

pqPullTestDriver::pqPullTestDriver(pqHapticsDockPanel* dock, const QString& output)
  : Dock(dock)
  , Output(output)
{
}

bool pqPullTestDriver::begin(const Pull& pull)
{
  pqRenderView* view = activeView();
  pqPipelineSource* target = findSource(pull.source);
  vtkPointSet* rest = target ? data(target, true) : nullptr;
  if (!view || !rest)
  {
    return false;
  }
  for (const char* name : { Unit, Large })
  {
    pqPipelineSource* source = findSource(name);
    if (pqDataRepresentation* shown = source ? source->getRepresentation(view) : nullptr)
    {
      shown->setVisible(source == target);
    }
  }
  pqActiveObjects::instance().setActiveSource(target);
  auto* combo = this->Dock->findChild<QComboBox*>("PullConstraint");
  if (this->Index == 0)
  {
    this->Results += QString("pull_row = %1\n").arg(combo ? 1 : 0);
    // Every row label of the dock says what its control does, as the control does.
    QStringList bare;
    for (QFormLayout* form : this->Dock->findChildren<QFormLayout*>())
    {
      for (int row = 0; row < form->rowCount(); ++row)
      {
        QLayoutItem* item = form->itemAt(row, QFormLayout::LabelRole);
        auto* label = item ? qobject_cast<QLabel*>(item->widget()) : nullptr;
        if (label && label->toolTip().isEmpty())
        {
          bare << label->text();
        }
      }
    }
    this->Results += QString("labels_without_tooltip = %1\n").arg(bare.join(" | "));
  }
  if (combo)
  {
    combo->setCurrentIndex(pull.constraint);
  }
  // The cameras follow the data's bounds, so both scales are seen alike.
  double b[6];
  rest->GetBounds(b);
  const Eigen::Vector3d centre(0.5 * (b[0] + b[1]), 0.5 * (b[2] + b[3]), 0.5 * (b[4] + b[5]));
  const double size = Eigen::Vector3d(b[1] - b[0], b[3] - b[2], b[5] - b[4]).norm();
  const Eigen::Vector3d direction =
    pull.camera == 0 ? Eigen::Vector3d(-0.35, -1.0, 0.9) : Eigen::Vector3d(0.8, -0.7, 1.1);
  const Eigen::Vector3d position = centre + 1.5 * size * direction.normalized();
  vtkSMProxy* proxy = view->getProxy();
  vtkSMPropertyHelper(proxy, "CameraPosition").Set(position.data(), 3);
  vtkSMPropertyHelper(proxy, "CameraFocalPoint").Set(centre.data(), 3);
  const double up[3] = { 0.0, 0.0, 1.0 };
  vtkSMPropertyHelper(proxy, "CameraViewUp").Set(up, 3);
  vtkSMPropertyHelper(proxy, "CameraViewAngle").Set(30.0);
  vtkSMPropertyHelper(proxy, "CameraParallelProjection").Set(pull.camera == 1 ? 1 : 0);
  vtkSMPropertyHelper(proxy, "CameraParallelScale").Set(0.4 * size);
  proxy->UpdateVTKObjects();
  view->forceRender();
  return true;
}

bool pqPullTestDriver::step()
{
  static const Pull pulls[] = {
    { "unit_perspective", Unit, 0, false, 0 },
    { "unit_parallel", Unit, 1, false, 0 },
    { "km_perspective", Large, 0, false, 0 },
    { "km_parallel", Large, 1, false, 0 },
    { "km_perspective_shift", Large, 0, true, 0 },
    { "km_parallel_vertical", Large, 1, false, 1 },
    { "unit_parallel_normal", Unit, 1, false, 2 },
  };
  const int count = int(sizeof(pulls) / sizeof(pulls[0]));
  if (this->Index >= count)
  {
    return false;
  }
  const Pull& pull = pulls[this->Index];
  pqRenderView* view = activeView();
  vtkSMRenderViewProxy* viewProxy = view ? view->getRenderViewProxy() : nullptr;
  vtkRenderWindowInteractor* interactor = viewProxy ? viewProxy->GetInteractor() : nullptr;
  pqPipelineSource* source = findSource(pull.source);
  vtkPointSet* rest = source ? data(source, true) : nullptr;
  if (!interactor || !rest)
  {
    return false;
  }
  const int step = this->Step++;
  if (step == 0)
  {
    this->begin(pull);
  }
  else if (step == 1)
  {
    // Press where a vertex of the surface shows, near the middle of the view: the vertex
    // nearest to the surface point under (45 %, 50 %) of the view.
    const int* size = interactor->GetSize();
    const int probe[2] = { int(0.45 * size[0]), size[1] / 2 };
    double p[3], n[3];
    vtkIdType id = -1;
    if (viewProxy->ConvertDisplayToPointOnSurface(probe, p, n))
    {
      id = rest->FindPoint(p);
    }
    Eigen::Vector3d vertex = Eigen::Vector3d::Zero();
    if (id >= 0)
    {
      rest->GetPoint(id, vertex.data());
    }
    const Eigen::Vector3d pixel = toDisplay(viewProxy->GetRenderer(), vertex);
    this->Press[0] = this->Cursor[0] = int(std::lround(pixel.x()));
    this->Press[1] = this->Cursor[1] = int(std::lround(pixel.y()));
    this->Normal.setZero();
    if (viewProxy->ConvertDisplayToPointOnSurface(this->Press, p, n))
    {
      this->Normal = Eigen::Vector3d(n[0], n[1], n[2]);
    }
    interactor->SetEventInformation(this->Press[0], this->Press[1], 0, pull.shift ? 1 : 0);
    interactor->InvokeEvent(vtkCommand::LeftButtonPressEvent);
  }
  if (step >= 1 && step <= Steps)
  {
    // The first motion comes with the press, before the interactor's next frame, as a
    // quick hand does it on a slow view.
    const int k = step;
    this->Cursor[0] = this->Press[0] + MotionX * k / Steps;
    this->Cursor[1] = this->Press[1] + MotionY * k / Steps;
    interactor->SetEventInformation(this->Cursor[0], this->Cursor[1], 0, pull.shift ? 1 : 0);
    interactor->InvokeEvent(vtkCommand::MouseMoveEvent);
  }
  else if (step == 3 + Steps)
  {
    this->measure(pull);
  }
  else if (step == 4 + Steps)
  {
    interactor->SetEventInformation(this->Cursor[0], this->Cursor[1], 0, 0);
    interactor->InvokeEvent(vtkCommand::LeftButtonReleaseEvent);
  }
  else if (step == 5 + Steps)
  {
    this->Dock->interactor()->runEdit(geoshaping::interactor::EditCommand::reset);
  }
  else if (step == 7 + Steps)
  {
    this->Step = 0;
    return ++this->Index == count;
  }
  return false;
}

void pqPullTestDriver::measure(const Pull& pull)
{
  // While the pull is held: the grasped vertex of the shown surface against the cursor.
  pqRenderView* view = activeView();
  vtkRenderer* renderer = view->getRenderViewProxy()->GetRenderer();
  pqPipelineSource* source = findSource(pull.source);
  vtkPointSet* rest = data(source, true);
  vtkPointSet* shown = data(source, false);
  const vtkIdType id = vtkSMPropertyHelper(source->getProxy(), "GraspPointId").GetAsIdType();
  const QString key = QString("pull_%1_").arg(pull.name);
  if (!shown || id < 0 || id >= rest->GetNumberOfPoints() ||
      shown->GetNumberOfPoints() != rest->GetNumberOfPoints())
  {
    this->Results += key + "grasp = none\n";
    return;
  }
  Eigen::Vector3d before, after;
  rest->GetPoint(id, before.data());
  shown->GetPoint(id, after.data());
  const Eigen::Vector3d image0 = toDisplay(renderer, before);
  const Eigen::Vector3d image = toDisplay(renderer, after);
  const Eigen::Vector2d cursor(this->Cursor[0], this->Cursor[1]);
  // The cursor's motion on the plane through the vertex parallel to the view.
  const double depth = image0.z();
  const Eigen::Vector3d motion = toWorld(renderer, this->Cursor[0], this->Cursor[1], depth) -
                                 toWorld(renderer, this->Press[0], this->Press[1], depth);
  double b[6];
  rest->GetBounds(b);
  QTextStream out(&this->Results);
  out << key << "grasp = " << id << "\n";
  out << key << "press_px = " << this->Press[0] << " " << this->Press[1] << "\n";
  out << key << "cursor_px = " << this->Cursor[0] << " " << this->Cursor[1] << "\n";
  out << key << "vertex_px_at_press = " << image0.x() << " " << image0.y() << "\n";
  out << key << "vertex_px = " << image.x() << " " << image.y() << "\n";
  out << key << "error_px = " << (image.head<2>() - cursor).norm() << "\n";
  out << key << "displacement = " << text(after - before) << "\n";
  out << key << "cursor_motion = " << text(motion) << "\n";
  out << key << "data_size = " << Eigen::Vector3d(b[1] - b[0], b[3] - b[2], b[5] - b[4]).norm()
      << "\n";
  if (pull.constraint == 2)
  {
    // The view's normal at the press against the surface's: the mean of the normals of
    // the cells around the grasped vertex.
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    vtkNew<vtkIdList> cells;
    rest->GetPointCells(id, cells);
    for (vtkIdType c = 0; c < cells->GetNumberOfIds(); ++c)
    {
      vtkCell* cell = rest->GetCell(cells->GetId(c));
      Eigen::Vector3d normal;
      vtkPolygon::ComputeNormal(cell->GetPoints(), normal.data());
      mean += normal.dot(this->Normal) < 0.0 ? -normal : normal;
    }
    out << key << "view_normal = " << text(this->Normal) << "\n";
    out << key << "surface_normal = " << text(mean.normalized()) << "\n";
  }
  if (pull.constraint == 1)
  {
    // The cursor's foot on the image of the vertical through the vertex.
    const Eigen::Vector2d g = image0.head<2>();
    const Eigen::Vector2d e =
      (toDisplay(renderer, before + 1e-3 * (b[5] - b[4]) * Eigen::Vector3d::UnitZ()).head<2>() - g)
        .normalized();
    const Eigen::Vector2d foot = g + (cursor - g).dot(e) * e;
    out << key << "error_to_vertical_px = " << (image.head<2>() - foot).norm() << "\n";
  }
  out.flush();
  view->widget()->grab().save(QString("%1-%2.png").arg(this->Output, pull.name));
}
