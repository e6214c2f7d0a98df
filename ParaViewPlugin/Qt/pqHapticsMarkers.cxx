#include "pqHapticsMarkers.h"

#include <pqApplicationCore.h>
#include <pqDataRepresentation.h>
#include <pqObjectBuilder.h>
#include <pqOutputPort.h>
#include <pqPipelineSource.h>
#include <pqServerManagerModel.h>
#include <pqUndoStack.h>
#include <pqView.h>

#include <vtkBoundingBox.h>
#include <vtkDataObject.h>
#include <vtkPVDataInformation.h>
#include <vtkSMInputProperty.h>
#include <vtkSMPVRepresentationProxy.h>
#include <vtkSMPropertyHelper.h>
#include <vtkSMSourceProxy.h>
#include <vtkSMTransferFunctionProxy.h>

#include <QList>
#include <QMap>

#include <algorithm>
#include <cmath>

namespace
{
// The pipeline source (and port) behind the deformation's first Markers connection: the
// source itself, or the Input of the panel's Pipeline Connection.
pqOutputPort* markersPort(vtkSMProxy* deformation)
{
  auto* markers = vtkSMInputProperty::SafeDownCast(deformation->GetProperty("Markers"));
  if (!markers || markers->GetNumberOfProxies() == 0)
  {
    return nullptr;
  }
  vtkSMProxy* proxy = markers->GetProxy(0);
  unsigned int port = markers->GetOutputPortForConnection(0);
  pqServerManagerModel* model = pqApplicationCore::instance()->getServerManagerModel();
  auto* source = model->findItem<pqPipelineSource*>(proxy);
  if (!source && proxy && proxy->GetProperty("Input"))
  {
    auto* input = vtkSMInputProperty::SafeDownCast(proxy->GetProperty("Input"));
    if (input && input->GetNumberOfProxies() > 0)
    {
      source = model->findItem<pqPipelineSource*>(input->GetProxy(0));
      port = input->GetOutputPortForConnection(0);
    }
  }
  return source ? source->getOutputPort(int(port)) : nullptr;
}
}

pqPipelineSource* pqHapticsMarkers::show(pqPipelineSource* deformation, pqView* view, QString& why)
{
  if (!deformation || !view)
  {
    why = "no ChainMailDeformation shown";
    return nullptr;
  }
  pqOutputPort* markers = markersPort(deformation->getProxy());
  if (!markers)
  {
    why = "no markers: connect well markers to the deformation's Markers input";
    return nullptr;
  }
  pqApplicationCore* core = pqApplicationCore::instance();
  pqUndoStack* stack = core->getUndoStack();
  if (stack)
  {
    stack->beginUndoSet("Show Marker Misfit");
  }
  QMap<QString, QList<pqOutputPort*>> inputs;
  inputs["Input"].push_back(deformation->getOutputPort(0));
  inputs["Markers"].push_back(markers);
  pqObjectBuilder* builder = core->getObjectBuilder();
  pqPipelineSource* misfit =
    builder->createFilter("filters", "MarkerMisfit", inputs, deformation->getServer());
  pqDataRepresentation* shown =
    misfit ? builder->createDataRepresentation(misfit->getOutputPort(0), view) : nullptr;
  if (shown)
  {
    vtkSMProxy* repr = shown->getProxy();
    vtkSMPropertyHelper(repr, "Representation").Set("Point Gaussian");
    double bounds[6];
    deformation->getOutputPort(0)->getDataInformation()->GetBounds(bounds);
    const double size = vtkBoundingBox(bounds).GetDiagonalLength();
    if (repr->GetProperty("GaussianRadius") && size > 0.0)
    {
      vtkSMPropertyHelper(repr, "GaussianRadius").Set(0.01 * size);
    }
    if (vtkSMPVRepresentationProxy::SetScalarColoring(repr, "Misfit", vtkDataObject::POINT))
    {
      // A diverging map centred on 0: above and below the surface read apart.
      if (vtkSMProxy* lut = vtkSMPropertyHelper(repr, "LookupTable", true).GetAsProxy())
      {
        vtkSMTransferFunctionProxy::ApplyPreset(lut, "Cool to Warm", false);
        double range[2] = { 0.0, 0.0 };
        vtkSMPVRepresentationProxy::RescaleTransferFunctionToDataRange(repr);
        vtkSMTransferFunctionProxy::GetRange(lut, range);
        const double reach = std::max(std::abs(range[0]), std::abs(range[1]));
        const double symmetric[2] = { -(reach > 0.0 ? reach : 1.0), reach > 0.0 ? reach : 1.0 };
        vtkSMTransferFunctionProxy::RescaleTransferFunction(lut, symmetric);
      }
    }
    repr->UpdateVTKObjects();
  }
  if (stack)
  {
    stack->endUndoSet();
  }
  view->render();
  if (!shown)
  {
    why = "Marker Misfit could not be created";
  }
  return misfit;
}
