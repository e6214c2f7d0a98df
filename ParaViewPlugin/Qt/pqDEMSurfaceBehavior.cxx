#include "pqDEMSurfaceBehavior.h"

#include <pqApplicationCore.h>
#include <pqDataRepresentation.h>
#include <pqPipelineSource.h>
#include <pqRenderView.h>
#include <pqServerManagerModel.h>
#include <pqUndoStack.h>

#include <vtkCamera.h>
#include <vtkDataObject.h>
#include <vtkPVRenderView.h>
#include <vtkSMPVRepresentationProxy.h>
#include <vtkSMPropertyHelper.h>
#include <vtkSMProxy.h>
#include <vtkSMRenderViewProxy.h>

#include <QPointer>
#include <QTimer>
#include <QVariant>

#include <cstring>

namespace
{
// The first view of a relief: from the south, looking north and down at 35 degrees above
// the horizon (the camera turned 55 degrees from straight down about the east axis).
constexpr double ObliqueFromStraightDown = 55.0;
// A dynamic property of the pqRenderView whose camera this behaviour has set once.
constexpr const char* CameraSet = "GeoShapingDEMCameraSet";

void ObliqueCamera(pqRenderView* view)
{
  vtkSMRenderViewProxy* proxy = view->getRenderViewProxy();
  vtkCamera* camera = proxy->GetActiveCamera();
  camera->SetFocalPoint(0.0, 0.0, 0.0);
  camera->SetPosition(0.0, 0.0, 1.0);
  camera->SetViewUp(0.0, 1.0, 0.0);
  camera->Elevation(-ObliqueFromStraightDown);
  camera->OrthogonalizeViewUp();
  proxy->SynchronizeCameraProperties();
  view->resetCamera();
}
} // namespace

pqDEMSurfaceBehavior::pqDEMSurfaceBehavior(QObject* parent)
  : QObject(parent)
{
  QObject::connect(pqApplicationCore::instance()->getServerManagerModel(),
    &pqServerManagerModel::sourceAdded, this, &pqDEMSurfaceBehavior::onSourceAdded);
}

void pqDEMSurfaceBehavior::onSourceAdded(pqPipelineSource* source)
{
  const char* name = source && source->getProxy() ? source->getProxy()->GetXMLName() : nullptr;
  if (name && std::strcmp(name, "DEMSurface") == 0)
  {
    QObject::connect(source, &pqPipelineSource::representationAdded, this,
      &pqDEMSurfaceBehavior::onRepresentationAdded);
  }
}

void pqDEMSurfaceBehavior::onRepresentationAdded(
  pqPipelineSource* source, pqDataRepresentation* repr, int)
{
  pqApplicationCore* core = pqApplicationCore::instance();
  pqUndoStack* stack = core->getUndoStack();
  if (!repr || core->isLoadingState() || (stack && stack->getInUndo()))
  {
    return;
  }
  // The representation joins its view after this signal, and Apply then shows it (and
  // hides the raster): done once the event loop is back, in the view it was shown in.
  QPointer<pqPipelineSource> surface(source);
  QPointer<pqDataRepresentation> shown(repr);
  QTimer::singleShot(0, this,
    [this, surface, shown]()
    {
      auto* view = shown ? qobject_cast<pqRenderView*>(shown->getView()) : nullptr;
      if (!surface || !view)
      {
        return;
      }
      QObject::disconnect(surface, &pqPipelineSource::representationAdded, this,
        &pqDEMSurfaceBehavior::onRepresentationAdded);
      vtkSMProxy* viewProxy = view->getProxy();
      vtkSMPropertyHelper(viewProxy, "InteractionMode").Set(vtkPVRenderView::INTERACTION_MODE_3D);
      viewProxy->UpdateVTKObjects();
      vtkSMProxy* reprProxy = shown->getProxy();
      if (!vtkSMPVRepresentationProxy::GetUsingScalarColoring(reprProxy) &&
          vtkSMPVRepresentationProxy::SetScalarColoring(
            reprProxy, "Elevation", vtkDataObject::POINT))
      {
        vtkSMPVRepresentationProxy::RescaleTransferFunctionToDataRange(reprProxy);
        reprProxy->UpdateVTKObjects();
      }
      // The camera only the first time a DEM Surface is shown in this view: after that
      // it is the user's.
      if (!view->property(CameraSet).toBool())
      {
        view->setProperty(CameraSet, true);
        ObliqueCamera(view);
      }
      view->render();
    });
}
