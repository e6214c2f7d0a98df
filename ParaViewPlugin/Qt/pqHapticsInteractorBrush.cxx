// pqHapticsInteractor: the brush fitted to the data; a stroke is one step of ParaView's
// undo stack, which the dock's Undo and Redo step through as Edit > Undo does.
#include "pqHapticsInteractor.h"
#include "pqHapticsUndo.h"

#include <pqApplicationCore.h>
#include <pqPipelineSource.h>
#include <pqRenderView.h>
#include <pqUndoStack.h>

#include <vtkSMRemoteObjectUpdateUndoElement.h>
#include <vtkUndoSet.h>

#include <vtkRenderer.h>
#include <vtkSMRenderViewProxy.h>

#include <cmath>

namespace interactor = geoshaping::interactor;

using pqHapticsUndo::StrokeLabel;

void pqHapticsInteractor::refreshBrush()
{
  this->Proxies.refresh();
  const double kept = this->Proxies.brushRadiusProperty();
  const double radius = kept > 0.0 ? kept : this->Proxies.defaultBrushRadius();
  const std::string unit = this->Proxies.sceneUnit();
  const bool changed = (radius > 0.0 && radius != this->Brush.radius) ||
                       (kept <= 0.0) != this->BrushRadiusIsDefault || unit != this->SceneUnit ||
                       (radius > 0.0) != this->BrushFitsData;
  if (radius > 0.0)
  {
    this->Brush.radius = radius;
  }
  this->BrushFitsData = radius > 0.0;
  this->BrushRadiusIsDefault = kept <= 0.0;
  this->SceneUnit = unit;
  if (changed)
  {
    Q_EMIT this->brushChanged();
  }
}

void pqHapticsInteractor::setBrushRadius(double radius)
{
  this->Proxies.refresh();
  this->Proxies.setBrushRadiusProperty(radius);
  this->refreshBrush();
}

void pqHapticsInteractor::beginStroke()
{
  if (this->OpenStrokes++ > 0)
  {
    return; // the other hand's stroke is open: one stroke, one step
  }
  this->Proxies.beginStroke();
  this->Outcome = interactor::StrokeOutcome();
  // Tracked before the stroke pushes anything: Edit > Undo gives back this state.
  this->StrokeStep = std::make_unique<geoshaping::undo::Step>(StrokeLabel);
  pqPipelineSource* paint = this->Proxies.paint();
  this->StrokeStep->track(paint ? paint->getProxy() : nullptr);
  // Nothing else is a step until the stroke ends: what the paint sets off meanwhile (the
  // colour map growing to the painted range) would otherwise come before it on the stack.
  this->StrokeExclude = std::make_unique<geoshaping::undo::Exclude>();
}

void pqHapticsInteractor::endStroke()
{
  if (this->OpenStrokes == 0 || --this->OpenStrokes > 0)
  {
    return;
  }
  if (pqPipelineSource* paint = this->Outcome.stored > 0 ? this->Proxies.paint() : nullptr)
  {
    // The stroke's last dabs pushed (as a frame does: not a step), then the stroke is one.
    paint->getProxy()->UpdateVTKObjects();
  }
  this->StrokeExclude.reset();
  if (this->Outcome.stored > 0)
  {
    this->StrokeStep->finish();
  }
  this->StrokeStep.reset();
  this->BrushNote = QString::fromStdString(
    interactor::stroke_note(this->Outcome, this->Brush.radius, this->SceneUnit));
  Q_EMIT this->brushChanged();
}

bool pqHapticsInteractor::strokeEdit(interactor::EditCommand command)
{
  const bool undo = command == interactor::EditCommand::undo;
  if (!undo && command != interactor::EditCommand::redo)
  {
    return false;
  }
  if (this->OpenStrokes > 0)
  {
    // Its step begins with the paint as it was: it must not change under it.
    this->LastEdit.changed = false;
    this->LastEdit.message = "a stroke is being painted: release it first";
    return true;
  }
  pqUndoStack* stack = pqApplicationCore::instance()->getUndoStack();
  const bool next = stack && (undo ? stack->canUndo() : stack->canRedo());
  const QString label = next ? (undo ? stack->undoLabel() : stack->redoLabel()) : QString();
  vtkUndoSet* step = next ? geoshaping::undo::next_step(!undo) : nullptr;
  pqPipelineSource* paint = this->Proxies.paint();
  auto* element = step && step->GetNumberOfElements() == 1
                    ? vtkSMRemoteObjectUpdateUndoElement::SafeDownCast(step->GetElement(0))
                    : nullptr;
  if (label != StrokeLabel || !element || !paint ||
      element->GetGlobalId() != paint->getProxy()->GetGlobalID())
  {
    return false;
  }
  // Exactly Edit > Undo / Redo: the paint proxy's lists as they were before / after.
  if (undo)
  {
    stack->undo();
  }
  else
  {
    stack->redo();
  }
  this->LastEdit.changed = true;
  this->LastEdit.edits = static_cast<std::size_t>(this->Proxies.numberOfEdits());
  pqPipelineSource* deformation = this->Proxies.deformation();
  this->LastEdit.redoable =
    pqHapticsUndo::status(deformation ? deformation->getProxy() : nullptr).redoable;
  this->LastEdit.message = undo ? "paint stroke undone" : "paint stroke redone";
  return true;
}

double pqHapticsInteractor::brushCursorRadius(
  const Eigen::Vector3d& at, const interactor::CameraPose& camera) const
{
  pqRenderView* view = this->Proxies.view();
  vtkRenderer* renderer = view ? view->getRenderViewProxy()->GetRenderer() : nullptr;
  const int height = renderer ? renderer->GetSize()[1] : 0;
  double perPixel = 0.0;
  if (height > 0)
  {
    const Eigen::Vector3d toward = camera.focal_point - camera.position;
    const double depth =
      toward.norm() > 0.0 ? (at - camera.position).dot(toward.normalized()) : 0.0;
    const double half =
      camera.parallel
        ? camera.parallel_scale
        : std::abs(depth) * std::tan(0.5 * camera.view_angle_deg * 3.14159265358979323846 / 180.0);
    perPixel = 2.0 * half / height;
  }
  return interactor::cursor_radius(this->Brush.radius, perPixel);
}
