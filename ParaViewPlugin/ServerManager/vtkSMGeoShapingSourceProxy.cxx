#include "vtkSMGeoShapingSourceProxy.h"

#include "vtkCommand.h"
#include "vtkObjectFactory.h"
#include "vtkSMVectorProperty.h"

vtkStandardNewMacro(vtkSMGeoShapingSourceProxy);

vtkSMGeoShapingSourceProxy::vtkSMGeoShapingSourceProxy()
{
  this->AddObserver(
    vtkCommand::UpdatePropertyEvent, this, &vtkSMGeoShapingSourceProxy::CheckEntries);
}

vtkSMGeoShapingSourceProxy::~vtkSMGeoShapingSourceProxy() = default;

int vtkSMGeoShapingSourceProxy::GetIncompleteTail(const char* name)
{
  auto* property = vtkSMVectorProperty::SafeDownCast(name ? this->GetProperty(name) : nullptr);
  const int per =
    property && property->GetRepeatCommand() ? property->GetNumberOfElementsPerCommand() : 1;
  return per > 1 ? static_cast<int>(property->GetNumberOfElements() % per) : 0;
}

void vtkSMGeoShapingSourceProxy::CheckEntries(vtkObject*, unsigned long, void* name)
{
  const char* property = static_cast<const char*>(name);
  const int tail = this->GetIncompleteTail(property);
  if (tail > 0)
  {
    auto* values = vtkSMVectorProperty::SafeDownCast(this->GetProperty(property));
    vtkWarningMacro(<< this->GetXMLName() << "." << property << " has "
                    << values->GetNumberOfElements() << " values, not a whole number of "
                    << values->GetNumberOfElementsPerCommand() << "-value entries: the last "
                    << tail << (tail == 1 ? " is" : " are") << " ignored.");
  }
}

void vtkSMGeoShapingSourceProxy::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
