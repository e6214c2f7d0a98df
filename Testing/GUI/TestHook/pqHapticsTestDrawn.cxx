#include "pqHapticsTestDrawn.h"

#include <pqActiveObjects.h>
#include <pqApplicationCore.h>
#include <pqDataRepresentation.h>
#include <pqOutputPort.h>
#include <pqPipelineSource.h>
#include <pqRenderView.h>
#include <pqServerManagerModel.h>

#include <vtkPointSet.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkRenderer.h>
#include <vtkSMPropertyHelper.h>
#include <vtkSMRenderViewProxy.h>

#include <QString>
#include <QTextStream>

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
