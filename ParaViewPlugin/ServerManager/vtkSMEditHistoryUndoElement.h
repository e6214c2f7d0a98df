#pragma once
/**
 * @class vtkSMEditHistoryUndoElement
 * @brief One step of ParaView's undo stack for an edit command on a ChainMailDeformation.
 *
 * Holds the proxy's `EditHistory` list before and after the command (a commit, an undo, a
 * redo, a reset of edits). Undo restores the list before, Redo the list after, through
 * vtkSMChainMailDeformationProxy::RestoreEdits: the proxy releases its grasp and pushes,
 * and the filter undoes or re-applies what differs, so Edit > Undo after a drag gives the
 * points of the command UndoEdit, bit for bit, and leaves no grasp (docs/editing.md).
 * Records, not commands: the step stays right whatever order the stack replays it in.
 */
#include "GeoShapingServerManagerModule.h"
#include "vtkSMUndoElement.h"

#include <string>
#include <vector>

class vtkSMChainMailDeformationProxy;

class GEOSHAPINGSERVERMANAGER_EXPORT vtkSMEditHistoryUndoElement : public vtkSMUndoElement
{
public:
  static vtkSMEditHistoryUndoElement* New();
  vtkTypeMacro(vtkSMEditHistoryUndoElement, vtkSMUndoElement);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// The proxy and its list before and after the command.
  void Set(vtkSMChainMailDeformationProxy* proxy, const std::vector<std::string>& before,
    const std::vector<std::string>& after);
  /// The global id of the proxy this step edits.
  vtkTypeUInt32 GetProxyGlobalId() const { return this->ProxyId; }

  int Undo() override;
  int Redo() override;

protected:
  vtkSMEditHistoryUndoElement() = default;
  ~vtkSMEditHistoryUndoElement() override = default;

private:
  vtkSMEditHistoryUndoElement(const vtkSMEditHistoryUndoElement&) = delete;
  void operator=(const vtkSMEditHistoryUndoElement&) = delete;

  int Restore(const std::vector<std::string>& records);

  vtkTypeUInt32 ProxyId = 0;
  std::vector<std::string> Before;
  std::vector<std::string> After;
};
