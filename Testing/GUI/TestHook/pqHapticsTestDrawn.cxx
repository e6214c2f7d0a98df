#include "pqHapticsTestDrawn.h"

#include <pqActiveObjects.h>
#include <pqApplicationCore.h>
#include <pqDataRepresentation.h>
#include <pqOutputPort.h>
#include <pqPipelineSource.h>
#include <pqRenderView.h>
#include <pqServerManagerModel.h>

#include <vtkCamera.h>
#include <vtkPVDataInformation.h>
#include <vtkPointSet.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkRenderer.h>
#include <vtkSMPropertyHelper.h>
#include <vtkSMRenderViewProxy.h>

#include <QString>

#include <QTextStream>
#include <algorithm>

void pqHapticsWriteDrawnGrasp(QTextStream& out, pqPipelineSource* deformation, vtkPointSet* shown)
{
  auto* view = qobject_cast<pqRenderView*>(pqActiveObjects::instance().activeView());
  pqDataRepresentation* repr = view && deformation ? deformation->getRepresentation(view) : nullptr;
  if (!repr || !shown)
  {
    return;
  }
  double scale[3];
  vtkSMPropertyHelper(repr->getProxy(), "Scale").Get(scale, 3);
  out << "Scale = " << scale[0] << " " << scale[1] << " " << scale[2] << "\n";
  auto* model = pqApplicationCore::instance()->getServerManagerModel();
  vtkSMPropertyHelper obstacles(deformation->getProxy(), "Obstacles");
  for (unsigned int i = 0; i < obstacles.GetNumberOfElements(); ++i)
  {
    auto* source = model->findItem<pqPipelineSource*>(obstacles.GetAsProxy(i));
    pqOutputPort* port = source ? source->getOutputPort(obstacles.GetOutputPort(i)) : nullptr;
    if (pqDataRepresentation* shownObstacle = port ? port->getRepresentation(view) : nullptr)
    {
      vtkSMPropertyHelper(shownObstacle->getProxy(), "Scale").Get(scale, 3);
      out << "obstacle_scale_" << i << " = " << scale[0] << " " << scale[1] << " " << scale[2]
          << "\n";
    }
  }
  vtkRenderer* renderer = view->getRenderViewProxy()->GetRenderer();
  const int* mouse = view->getRenderViewProxy()->GetInteractor()->GetEventPosition();
  out << "mouse_px = " << mouse[0] << " " << mouse[1] << "\n";
  const vtkIdType id = vtkSMPropertyHelper(deformation->getProxy(), "GraspPointId").GetAsIdType();
  if (id >= 0 && id < shown->GetNumberOfPoints())
  {
    double p[3];
    shown->GetPoint(id, p);
    renderer->SetWorldPoint(p[0] * scale[0], p[1] * scale[1], p[2] * scale[2], 1.0);
    renderer->WorldToDisplay();
    const double* d = renderer->GetDisplayPoint();
    out << "grasp_px = " << QString::number(d[0], 'g', 17) << " " << QString::number(d[1], 'g', 17)
        << "\n";
  }
}

void pqHapticsWriteShown(QTextStream& out)
{
  auto* view = qobject_cast<pqRenderView*>(pqActiveObjects::instance().activeView());
  if (!view)
  {
    return;
  }
  vtkSMProxy* viewProxy = view->getProxy();
  out << "interaction_mode = " << vtkSMPropertyHelper(viewProxy, "InteractionMode").GetAsInt()
      << "\n";
  vtkRenderer* renderer = view->getRenderViewProxy()->GetRenderer();
  const int* size = renderer->GetSize();
  out << "view_px = " << size[0] << " " << size[1] << "\n";
  const double* look = renderer->GetActiveCamera()->GetDirectionOfProjection();
  out << "view_direction = " << look[0] << " " << look[1] << " " << look[2] << "\n";
  const double* eye = renderer->GetActiveCamera()->GetPosition();
  out << "view_position = " << QString::number(eye[0], 'g', 17) << " "
      << QString::number(eye[1], 'g', 17) << " " << QString::number(eye[2], 'g', 17) << "\n";
  auto* model = pqApplicationCore::instance()->getServerManagerModel();
  for (pqPipelineSource* source : model->findItems<pqPipelineSource*>())
  {
    pqDataRepresentation* repr = source->getRepresentation(view);
    if (!repr)
    {
      continue;
    }
    const char* colour = vtkSMPropertyHelper(repr->getProxy(), "ColorArrayName").GetAsString(4);
    double b[6];
    source->getOutputPort(0)->getDataInformation()->GetBounds(b);
    double px[4] = { 1e300, -1e300, 1e300, -1e300 };
    for (int corner = 0; corner < 8; ++corner)
    {
      renderer->SetWorldPoint(b[corner & 1], b[2 + ((corner >> 1) & 1)], b[4 + (corner >> 2)], 1.0);
      renderer->WorldToDisplay();
      const double* d = renderer->GetDisplayPoint();
      px[0] = std::min(px[0], d[0]);
      px[1] = std::max(px[1], d[0]);
      px[2] = std::min(px[2], d[1]);
      px[3] = std::max(px[3], d[1]);
    }
    out << "shown_" << source->getSMName() << " = " << int(repr->isVisible()) << " "
        << (colour && *colour ? colour : "(solid)") << " " << px[0] << " " << px[1] << " " << px[2]
        << " " << px[3] << "\n";
  }
}
