#pragma once
// The proxies the haptic interactor drives, and the few things it reads back. All
// pipeline access of the interactor goes through here (vtkSMPropertyHelper ->
// UpdateVTKObjects, as ParaView's CAVEInteraction plugin does).
#include "HapticsControl.h"

#include <pqPipelineSource.h>
#include <pqRenderView.h>

#include <QPointer>

#include <array>
#include <vector>

class vtkSMProxy;

// The first pipeline source of the session whose proxy is `xmlName`, or nullptr.
pqPipelineSource* pqHapticsFindSource(const char* xmlName);

class pqHapticsPipeline
{
public:
  // Finds the targets: the active source if it is a ChainMailDeformation, else the
  // first one in the session; the MalleabilityPaint upstream of it (or the first one);
  // the active render view.
  void refresh();
  pqRenderView* view() const { return this->View; }
  bool hasDeformation() const { return this->Deformation != nullptr; }
  bool hasPaint() const { return this->Paint != nullptr; }

  geoshaping::interactor::CameraFrame camera() const;

  // Scene (world) <-> the coordinates of the displayed deformation's data: the
  // representation's Position/Orientation/Origin/Scale, as vtkProp3D composes them.
  Eigen::Matrix4d objectMatrix() const;
  void setObjectMatrix(const Eigen::Matrix4d& m);

  void grasp(const Eigen::Vector3d& position);
  void setDisplacement(const Eigen::Vector3d& d);
  void appendDabs(const std::vector<std::array<double, 6>>& dabs);
  // Pushes the changed properties (UpdateVTKObjects) and renders the view.
  void render();

  // The grasped vertex's rest position and malleability (builtin sessions read the
  // filter's input; otherwise the press position and DefaultMalleability).
  bool graspedVertex(Eigen::Vector3d& position, double& malleability) const;

  double lastDeformationMilliseconds() const;
  long long numberOfDisplacedPoints() const;

private:
  vtkSMProxy* representation(pqPipelineSource* source) const;

  QPointer<pqRenderView> View;
  QPointer<pqPipelineSource> Deformation;
  QPointer<pqPipelineSource> Paint;
  std::vector<double> Dabs;
  bool DeformationModified = false;
  bool PaintModified = false;
  bool RepresentationModified = false;
};
