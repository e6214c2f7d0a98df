// pqHapticsProxies: the brush fitted to the data.
#include "pqHapticsProxies.h"
#include "undo_step.h"

#include <pqOutputPort.h>

#include <vtkAlgorithm.h>
#include <vtkFieldData.h>
#include <vtkMath.h>
#include <vtkPVDataInformation.h>
#include <vtkPVDataSetAttributesInformation.h>
#include <vtkPointSet.h>
#include <vtkPoints.h>
#include <vtkSMPropertyHelper.h>
#include <vtkSMProxy.h>
#include <vtkStringArray.h>

#include <algorithm>
#include <cmath>

namespace interactor = geoshaping::interactor;

namespace
{
vtkPointSet* clientInput(pqPipelineSource* source)
{
  vtkSMProxy* proxy = source ? source->getProxy() : nullptr;
  auto* algorithm = proxy ? vtkAlgorithm::SafeDownCast(proxy->GetClientSideObject()) : nullptr;
  return algorithm && algorithm->GetNumberOfInputPorts() > 0
           ? vtkPointSet::SafeDownCast(algorithm->GetInputDataObject(0, 0))
           : nullptr;
}

// The paint's output bounds (its input's points), from the data information: also
// against a remote server.
bool paintBounds(pqPipelineSource* paint, double bounds[6])
{
  pqOutputPort* port = paint ? paint->getOutputPort(0) : nullptr;
  vtkPVDataInformation* info = port ? port->getDataInformation() : nullptr;
  if (!info || info->GetNumberOfPoints() == 0)
  {
    return false;
  }
  info->GetBounds(bounds);
  return true;
}
}

double pqHapticsProxies::brushRadiusProperty() const
{
  vtkSMProxy* proxy = this->Paint ? this->Paint->getProxy() : nullptr;
  return proxy && proxy->GetProperty("BrushRadius")
           ? vtkSMPropertyHelper(proxy, "BrushRadius").GetAsDouble()
           : 0.0;
}

void pqHapticsProxies::setBrushRadiusProperty(double radius)
{
  vtkSMProxy* proxy = this->Paint ? this->Paint->getProxy() : nullptr;
  if (proxy && proxy->GetProperty("BrushRadius") && std::isfinite(radius) && radius >= 0.0)
  {
    // A setting of the tool, not an edit of the data: Ctrl+Z does not undo it.
    const geoshaping::undo::Exclude setting;
    vtkSMPropertyHelper(proxy, "BrushRadius").Set(radius);
  }
}

double pqHapticsProxies::defaultBrushRadius() const
{
  double bounds[6];
  return paintBounds(this->Paint, bounds) ? interactor::default_brush_radius(bounds) : 0.0;
}

std::string pqHapticsProxies::sceneUnit() const
{
  std::vector<std::string> axes;
  bool projection = false;
  if (vtkPointSet* input = clientInput(this->Paint))
  {
    vtkFieldData* fd = input->GetFieldData();
    if (auto* units = vtkStringArray::SafeDownCast(fd->GetAbstractArray("AxisUnit")))
    {
      for (vtkIdType i = 0; i < units->GetNumberOfValues(); ++i)
      {
        axes.push_back(units->GetValue(i));
      }
    }
    projection = fd->GetAbstractArray("Projection") != nullptr;
  }
  else if (pqOutputPort* port = this->Paint ? this->Paint->getOutputPort(0) : nullptr)
  {
    // Against a remote server only the arrays' names are known here.
    vtkPVDataSetAttributesInformation* fields =
      port->getDataInformation()->GetFieldDataInformation();
    projection = fields && fields->GetArrayInformation("Projection");
  }
  return interactor::scene_unit(axes, projection);
}

bool pqHapticsProxies::reachesInput(const double centre[3], double radius, double& nearest)
{
  nearest = -1.0;
  vtkPointSet* input = clientInput(this->Paint);
  if (!input || !input->GetPoints() || input->GetNumberOfPoints() == 0)
  {
    // No client copy (a remote server): a dab whose sphere misses the bounding box reaches
    // nothing.
    double b[6];
    if (!paintBounds(this->Paint, b))
    {
      return true;
    }
    double squared = 0.0;
    for (int axis = 0; axis < 3; ++axis)
    {
      const double out =
        std::max({ b[2 * axis] - centre[axis], centre[axis] - b[2 * axis + 1], 0.0 });
      squared += out * out;
    }
    return squared <= radius * radius;
  }
  const vtkIdType id =
    upToDate(input, this->InputLocator, this->InputLocatorData, this->InputLocatorTime)
      ->FindClosestPoint(centre);
  if (id < 0)
  {
    return false;
  }
  double p[3];
  input->GetPoint(id, p);
  nearest = std::sqrt(vtkMath::Distance2BetweenPoints(p, centre));
  return nearest <= radius;
}

void pqHapticsProxies::beginStroke()
{
  vtkSMProxy* proxy = this->Paint ? this->Paint->getProxy() : nullptr;
  if (!proxy)
  {
    return;
  }
  this->Dabs = vtkSMPropertyHelper(proxy, "Dabs").GetDoubleArray();
  if (proxy->GetProperty("PointDabs"))
  {
    this->PointDabs = vtkSMPropertyHelper(proxy, "PointDabs").GetDoubleArray();
  }
}
