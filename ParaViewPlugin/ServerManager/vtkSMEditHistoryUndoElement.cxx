#include "vtkSMEditHistoryUndoElement.h"

#include "vtkObjectFactory.h"
#include "vtkSMChainMailDeformationProxy.h"
#include "vtkSMSession.h"

vtkStandardNewMacro(vtkSMEditHistoryUndoElement);

void vtkSMEditHistoryUndoElement::Set(vtkSMChainMailDeformationProxy* proxy,
  const std::vector<std::string>& before, const std::vector<std::string>& after)
{
  this->SetSession(proxy ? proxy->GetSession() : nullptr);
  this->ProxyId = proxy ? proxy->GetGlobalID() : 0;
  this->Before = before;
  this->After = after;
}

int vtkSMEditHistoryUndoElement::Undo()
{
  return this->Restore(this->Before);
}

int vtkSMEditHistoryUndoElement::Redo()
{
  return this->Restore(this->After);
}

int vtkSMEditHistoryUndoElement::Restore(const std::vector<std::string>& records)
{
  vtkSMSession* session = this->GetSession();
  auto* proxy = vtkSMChainMailDeformationProxy::SafeDownCast(
    session ? session->GetRemoteObject(this->ProxyId) : nullptr);
  if (!proxy)
  {
    vtkWarningMacro("The ChainMailDeformation of this edit no longer exists.");
    return 0;
  }
  proxy->RestoreEdits(records);
  return 1;
}

void vtkSMEditHistoryUndoElement::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ProxyId: " << this->ProxyId << "\n";
  os << indent << "Edits before: " << this->Before.size() << ", after: " << this->After.size()
     << "\n";
}
