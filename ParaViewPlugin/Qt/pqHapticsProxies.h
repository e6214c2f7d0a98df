#pragma once
// The proxies the haptic interactor drives, and the few things it reads back. All
// pipeline access of the interactor goes through here (vtkSMPropertyHelper ->
// UpdateVTKObjects, as ParaView's CAVEInteraction plugin does).
#include "BrushControl.h"
#include "EditControl.h"
#include "HapticsControl.h"
#include "edit_commands.h"

#include <pqPipelineSource.h>
#include <pqRenderView.h>

#include <QPointer>

#include <vtkSmartPointer.h>
#include <vtkStaticCellLocator.h>
#include <vtkStaticPointLocator.h>
#include <vtkType.h>
#include <vtkWeakPointer.h>

#include <array>
#include <string>
#include <vector>

class pqOutputPort;
class vtkDataSet;
class vtkPointSet;
class vtkSMProxy;
class vtkSMSourceProxy;

// The first pipeline source of the session whose proxy is `xmlName` and, given a view, the
// first of them shown in it (else the first); nullptr when there is none.
pqPipelineSource* pqHapticsFindSource(const char* xmlName, pqView* view = nullptr);

class pqHapticsProxies
{
public:
  // Finds the targets: the active source if it is a ChainMailDeformation, else the
  // first one shown in the active render view (else the first in the session); the
  // MalleabilityPaint upstream of it (or the first one); the active render view.
  void refresh();
  pqRenderView* view() const { return this->View; }
  bool hasDeformation() const { return this->Deformation != nullptr; }
  pqPipelineSource* deformation() const { return this->Deformation; }

  geoshaping::interactor::CameraPose camera() const;

  // Scene (world) <-> the coordinates of the displayed deformation's data: the
  // representation's Position/Orientation/Origin/Scale, as vtkProp3D composes them.
  Eigen::Matrix4d objectMatrix() const;
  void setObjectMatrix(const Eigen::Matrix4d& m);
  // The vertical exaggeration of the shaped surface: its representation's Scale z over x
  // (NaN when x and y differ, 1 without a target). Setting it gives the deformation's and
  // its obstacles' representations in the view the Scale (1, 1, s) (DisplayTransform.h)
  // as one step of ParaView's undo stack, and renders (pqHapticsDisplay.cxx).
  double verticalExaggeration() const;
  void setVerticalExaggeration(double s);

  // Grasps the vertex of the shown (deformed) surface drawn nearest to `position` (data
  // coordinates; through the display transform: DisplayTransform::nearest_drawn): in a builtin
  // session by GraspPointId from a locator on the deformation's client-side output,
  // otherwise GraspMode = Nearest To Position (the filter's nearest *input* vertex).
  void grasp(const Eigen::Vector3d& position);
  void setDisplacement(const Eigen::Vector3d& d);
  // Dabs `x y z radius value strength`. When the shown surface differs from the paint's
  // input (`onShown`: a drag is held or edits are committed) and the session is builtin,
  // each dab becomes PointDabs on the vertices within its radius on the deformation's
  // output (the surface the user sees); otherwise positional Dabs. A dab that reaches no
  // vertex is not stored; the outcome counts both (pqHapticsProxiesBrush.cxx).
  geoshaping::interactor::StrokeOutcome appendDabs(
    const std::vector<std::array<double, 6>>& dabs, bool onShown);

  // The brush fitted to the data (pqHapticsProxiesBrush.cxx, BrushControl.h).
  // MalleabilityPaint's BrushRadius, kept in the state (0: not set); setting it is left
  // out of ParaView's undo stack.
  double brushRadiusProperty() const;
  void setBrushRadiusProperty(double radius);
  // The radius a brush has when none is set: 3 % of the paint input's diagonal (0
  // without a paint or data).
  double defaultBrushRadius() const;
  // The scene's length unit from the paint input's field data ("" when unknown).
  std::string sceneUnit() const;
  // A stroke begins: the dabs it appends go after the lists the proxy holds now (an undo
  // through ParaView's stack may have changed them since the last stroke).
  void beginStroke();
  pqPipelineSource* paint() const { return this->Paint; }
  // Commit / undo / redo / reset, keeping the client's EditHistory in step
  // (docs/editing.md); pushes the proxy. Render afterwards.
  geoshaping::interactor::EditResult runEdit(geoshaping::interactor::EditCommand command);
  // Records in the client's EditHistory (0 without a deformation).
  int numberOfEdits() const;
  // The deformation's client-side output (builtin sessions), else nullptr.
  vtkPointSet* shownSurface() const;
  // Pushes the changed properties (UpdateVTKObjects) and renders the view.
  void render();

  // The grasped vertex's rest position and malleability (builtin sessions read the
  // filter's input; otherwise the press position and DefaultMalleability).
  bool graspedVertex(Eigen::Vector3d& position, double& malleability) const;
  // The grasped vertex (GraspPointId) as the view shows it, data coordinates: the
  // deformation's client-side output (builtin sessions); false otherwise.
  bool shownGraspedVertex(Eigen::Vector3d& position) const;

  // Contact triangles for the haptic force (docs/interactor.md, Forces): the triangles of
  // the surfaces shown in the view within the box of half-size `radius` around `world`
  // (both scene coordinates), appended to `out` in scene coordinates, 3 vertices each.
  // Every visible representation counts, each through its own Position/Orientation/
  // Scale, except the deformation's upstream (the same surface, undeformed) and, unless
  // `withShown`, the deformation's own output. The client's own data where it holds it
  // (builtin sessions; cell locators cached per dataset, rebuilt when its geometry
  // changes); against a server, whose client holds none, each surface's patch is asked of
  // the server's processes (a GeoShapingContactPatch proxy per surface, one round trip
  // each: docs/haptics.md, "The contact patch on a server"), the same triangles; of a
  // surface shown through a similarity (rotation, uniform scale: distances keep their
  // order) only the `nearest` nearest to `world` travel (0: all), those the caller's
  // keep_nearest would keep.
  void contactTriangles(const Eigen::Vector3d& world, double radius, bool withShown,
    std::size_t nearest, std::vector<Eigen::Vector3d>& out);
  // The server's patches of the last contactTriangles call (milliseconds < 0: none asked,
  // the client held the data); `message` says when a patch could not be had (no
  // GeoShapingContactPatch on the server) or came late (the last patch kept then).
  struct ServerPatchFigures
  {
    double milliseconds = -1.0; // the round trips of the call, summed
    long long bytes = 0;        // the triangles' payload pulled (8 bytes a coordinate)
    long long triangles = 0;
    std::string message;
  };
  const ServerPatchFigures& serverPatchFigures() const { return this->PatchFigures; }
  // A round trip longer than this keeps the last patch for the next frame instead of
  // asking again (the GUI thread waits for each round trip); setPatchBudget changes it
  // (0: every round trip counts as late).
  static constexpr double PatchBudgetMilliseconds = 100.0;
  void setPatchBudget(double milliseconds) { this->PatchBudget = milliseconds; }

  // The malleability the filter's last update used at the grasped vertex, read from
  // the server (works against a remote server); false while there is no grasp yet.
  bool lastGraspMalleability(double& malleability) const;
  // LastGraspObstacleFraction of the filter's last update, read from the server; false
  // while there is no grasp yet.
  bool lastGraspObstacleFraction(double& fraction) const;
  // LastGraspDisplacement of the filter's last update (where the grasp landed, minus its
  // rest position), read from the server; false while there is no grasp yet or when it
  // is not finite.
  bool lastGraspDisplacement(Eigen::Vector3d& landed) const;

  double lastDeformationMilliseconds() const;
  long long numberOfDisplacedPoints() const;
  // Whether the deformation has an obstacle chosen (a pipeline source on its Obstacles,
  // directly or through the panel's Pipeline Connection).
  bool hasObstacles() const { return !this->obstaclePorts().empty(); }
  // NumberOfObstacleBlockedPoints of the filter's last update, read from the server.
  long long numberOfObstacleBlockedPoints() const;
  // Pushes the changed properties and brings the deformation's output up to date, without
  // rendering: what the filter did with this frame's pull can then be read before the
  // frame is drawn (render() afterwards finds the pipeline up to date).
  void update();
  // Where the grasped vertex is in the filter's last update, data coordinates: the
  // deformation's client-side output (builtin sessions), else `rest` (where the grasp
  // was at the press) moved by LastGraspDisplacement; false while there is no grasp.
  bool graspedVertexNow(const Eigen::Vector3d& rest, Eigen::Vector3d& at) const;

private:
  // Pushes the properties changed since the last push (UpdateVTKObjects).
  void push();
  // A LastGrasp... information property `name` of the filter's last update, read from the
  // server; false without the property or while there is no grasp yet.
  bool lastGraspFigure(const char* name, double& value) const;
  // The filter's information properties from the server, once between two updates of
  // the filter (render, an edit command, a new target): a frame reads them at most once.
  void readInformation(vtkSMProxy* proxy) const;
  vtkSMProxy* representation(pqPipelineSource* source) const;
  // The pipeline outputs the deformation's Obstacles come from (pqHapticsDisplay.cxx).
  std::vector<pqOutputPort*> obstaclePorts() const;
  // The representations in the view of the deformation and of its Obstacles inputs.
  std::vector<vtkSMProxy*> shapedRepresentations() const;
  vtkStaticCellLocator* cellLocator(vtkDataSet* data);

  QPointer<pqRenderView> View;
  QPointer<pqPipelineSource> Deformation;
  QPointer<pqPipelineSource> Paint;
  // A locator on the shown surface, rebuilt when its points change.
  vtkStaticPointLocator* shownLocator();
  std::vector<double> Dabs;
  std::vector<double> PointDabs;
  // Whether a dab at `centre` reaches a vertex of the paint's input within `radius`;
  // `nearest` is then the distance to its nearest vertex (-1 when unknown).
  bool reachesInput(const double centre[3], double radius, double& nearest);
  // `locator` over `data`, rebuilt when `data` or its points changed since (`of`, `time`).
  static vtkStaticPointLocator* upToDate(vtkPointSet* data,
    vtkSmartPointer<vtkStaticPointLocator>& locator, vtkPointSet*& of, vtkMTimeType& time);
  vtkSmartPointer<vtkStaticPointLocator> InputLocator;
  vtkMTimeType InputLocatorTime = 0;
  vtkPointSet* InputLocatorData = nullptr;
  vtkSmartPointer<vtkStaticPointLocator> Locator;
  vtkMTimeType LocatorTime = 0;
  vtkPointSet* LocatorData = nullptr;
  struct CellLocatorEntry
  {
    vtkWeakPointer<vtkDataSet> data;
    vtkSmartPointer<vtkStaticCellLocator> locator;
    vtkMTimeType time = 0;
  };
  std::vector<CellLocatorEntry> CellLocators;
  // The contact patch of `input`'s output `port` asked of the server's processes
  // (vtkGeoShapingContactPatch), appended to `xyz` in its data coordinates; false when
  // the server has no such proxy.
  bool serverPatch(vtkSMProxy* input, int port, const double centre[3], double radius,
    std::size_t nearest, std::vector<double>& xyz);
  struct ServerPatchEntry
  {
    vtkWeakPointer<vtkSMProxy> input;
    int port = 0;
    vtkSmartPointer<vtkSMSourceProxy> patch;
    std::vector<double> last; // the last patch, kept when the next round trip is skipped
    bool late = false;        // the last round trip took more than PatchBudgetMilliseconds
  };
  std::vector<ServerPatchEntry> ServerPatches;
  ServerPatchFigures PatchFigures;
  double PatchBudget = PatchBudgetMilliseconds;
  bool DeformationModified = false;
  mutable bool InformationRead = false; // since the filter's last possible update
  bool PaintModified = false;
  bool RepresentationModified = false;
};
