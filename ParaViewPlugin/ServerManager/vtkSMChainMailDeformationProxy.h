#pragma once
/**
 * @class vtkSMChainMailDeformationProxy
 * @brief The client-side proxy of ChainMailDeformation: every edit command keeps the
 *        `EditHistory` property in step with the filter.
 *
 * The filter keeps the committed edits on the server; the client owns the `EditHistory`
 * list that SaveState and Python traces write. Whoever invokes CommitEdit, UndoEdit,
 * RedoEdit or ResetEdits on this proxy — the properties panel's buttons, the Haptics
 * dock and its shortcuts, `proxy.SMProxy.InvokeCommand(...)` from Python — this class
 * then copies the change into `EditHistory` (geoshaping::interactor::follow_edit), so
 * there is one path for every edit and a saved state holds what the view shows
 * (docs/editing.md). In the GUI each command that changes the list is one step of
 * ParaView's undo stack (vtkSMEditHistoryUndoElement: Edit > Undo restores the list
 * before it), and its own bookkeeping push is not another. It also says when a transfer-curve list
 * is incomplete (vtkSMGeoShapingSourceProxy), and refuses an obstacle made from its own
 * output (a pipeline loop). ParaView instantiates it from the XML element
 * `<ChainMailDeformationProxy>`.
 */
#include "GeoShapingServerManagerModule.h"
#include "vtkSMGeoShapingSourceProxy.h"

#include "vtkSmartPointer.h"
#include "vtkWeakPointer.h"

#include <string>
#include <vector>

class GEOSHAPINGSERVERMANAGER_EXPORT vtkSMChainMailDeformationProxy
  : public vtkSMGeoShapingSourceProxy
{
public:
  static vtkSMChainMailDeformationProxy* New();
  vtkTypeMacro(vtkSMChainMailDeformationProxy, vtkSMGeoShapingSourceProxy);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * What the last edit command did: whether `EditHistory` changed, its length after,
   * how many edits RedoEdit can still re-apply, and why nothing changed (empty when
   * something did). The Haptics dock shows these.
   */
  vtkGetMacro(LastEditChanged, bool);
  vtkGetMacro(LastEditRedoable, int);
  const char* GetLastEditMessage() const { return this->LastEditMessage.c_str(); }
  ///@}

#ifndef __VTK_WRAP__
  /**
   * Sets `EditHistory` to `records`, releases the grasp and pushes (an undo step of
   * ParaView's Edit menu, geoshaping::interactor::restore_edits); the LastEdit* values
   * then describe it. Not recorded as a step itself.
   */
  void RestoreEdits(const std::vector<std::string>& records);
#endif

  /**
   * Loads a state. A state written before the Obstacles property chose its surface
   * through a Pipeline Connection (no `proxy_list` domain in it) connected the obstacle
   * sources directly: one such source becomes the Input of this proxy's Pipeline
   * Connection (so the panel shows it), several stay connected directly.
   */
  int LoadXMLState(vtkPVXMLElement* element, vtkSMProxyLocator* locator) override;

protected:
  vtkSMChainMailDeformationProxy();
  ~vtkSMChainMailDeformationProxy() override;
  void CreateVTKObjects() override;

private:
  vtkSMChainMailDeformationProxy(const vtkSMChainMailDeformationProxy&) = delete;
  void operator=(const vtkSMChainMailDeformationProxy&) = delete;

  // vtkCommand::UpdatePropertyEvent: a property was pushed to the server.
  void PropertyPushed(vtkObject*, unsigned long, void* name);
  // The Obstacles of a state from before the Pipeline Connection (LoadXMLState): moved
  // into the connection once it exists; Obstacles' ModifiedEvent retries.
  void ObstaclesChanged(vtkObject*, unsigned long, void*);
  void MoveLegacyObstacles();
  std::vector<vtkSmartPointer<vtkSMProxy>> LegacyObstacles;
  std::vector<unsigned int> LegacyPorts;
  bool MovingObstacles = false;

  // An obstacle or markers input made from this filter's output is a pipeline loop,
  // which ParaView's own proxy graph does not survive (its updates recurse over producers
  // without end). Any proxy property changed in the session (PropertyModifiedEvent of the
  // session's proxy manager: Obstacles or Markers set from Python, the Pipeline
  // Connection's Input picked in the panel, an upstream Change Input) is checked at once:
  // such an input is taken off (the connection's Input back to (none), a direct one
  // removed), with an error, and the filter refuses (RefuseObstacleLoop: output = input)
  // until the Obstacles or Markers change.
  void SessionPropertyModified(vtkObject*, unsigned long, void* info);
  void RefuseInputLoops(vtkSMProxy* modified, const char* property);
  vtkWeakPointer<vtkObject> Session;
  unsigned long SessionObserver = 0;
  bool RefusingLoops = false;
  bool LoopRefused = false;

  bool LastEditChanged = false;
  int LastEditRedoable = 0;
  std::string LastEditMessage;
  bool Following = false;
};
