// pqHapticsInteractor: the brush fitted to the data, strokes as undo steps.
#include "pqHapticsInteractor.h"

#include <pqRenderView.h>

#include <vtkRenderer.h>
#include <vtkSMRenderViewProxy.h>

#include <cmath>

namespace interactor = geoshaping::interactor;

void pqHapticsInteractor::refreshBrush()
{
  this->Proxies.refresh();
  const double kept = this->Proxies.brushRadiusProperty();
  const double radius = kept > 0.0 ? kept : this->Proxies.defaultBrushRadius();
  const std::string unit = this->Proxies.sceneUnit();
  const bool changed = (radius > 0.0 && radius != this->Brush.radius) ||
                       (kept <= 0.0) != this->BrushRadiusIsDefault || unit != this->SceneUnit;
  if (radius > 0.0)
  {
    this->Brush.radius = radius;
  }
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
  if (this->OpenStrokes++ == 0)
  {
    this->Proxies.beginStroke();
    this->Outcome = interactor::StrokeOutcome();
    Q_EMIT this->strokeBegun();
  }
}

void pqHapticsInteractor::endStroke()
{
  if (this->OpenStrokes == 0 || --this->OpenStrokes > 0)
  {
    return;
  }
  const interactor::Stroke stroke = this->Proxies.endStroke();
  if (!stroke.empty())
  {
    this->History.push_stroke(stroke);
  }
  this->BrushNote = QString::fromStdString(
    interactor::stroke_note(this->Outcome, this->Brush.radius, this->SceneUnit));
  Q_EMIT this->strokeEnded(stroke);
  Q_EMIT this->brushChanged();
}

bool pqHapticsInteractor::strokeEdit(interactor::EditCommand command)
{
  const bool undo = command == interactor::EditCommand::undo;
  const interactor::Stroke* stroke = nullptr;
  const interactor::ActionHistory::Kind next = undo ? this->History.next_undo(&stroke)
                                               : command == interactor::EditCommand::redo
                                                 ? this->History.next_redo(&stroke)
                                                 : interactor::ActionHistory::Kind::edit;
  if (this->OpenStrokes > 0 && command != interactor::EditCommand::commit)
  {
    // Its record begins with the lists as they were: they must not change under it.
    this->LastEdit.changed = false;
    this->LastEdit.message = "a stroke is being painted: release it first";
    return true;
  }
  if (next != interactor::ActionHistory::Kind::stroke)
  {
    return false;
  }
  const bool done =
    undo ? this->Proxies.removeStroke(*stroke) : this->Proxies.restoreStroke(*stroke);
  if (undo)
  {
    this->History.undone(done);
  }
  else
  {
    this->History.redone(done);
  }
  this->LastEdit.changed = done;
  this->LastEdit.edits = static_cast<std::size_t>(this->Proxies.numberOfEdits());
  this->LastEdit.message =
    std::string(done ? "paint stroke " : "the paint changed since the stroke, not ") +
    (undo ? "undone" : "redone");
  return true;
}

double pqHapticsInteractor::brushCursorRadius(
  const Eigen::Vector3d& at, const interactor::CameraFrame& camera) const
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
