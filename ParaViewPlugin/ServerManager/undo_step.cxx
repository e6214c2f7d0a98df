#include "undo_step.h"

#include "vtkSMProxy.h"
#include "vtkSMProxyManager.h"
#include "vtkSMRemoteObjectUpdateUndoElement.h"
#include "vtkSMSession.h"
#include "vtkSMUndoElement.h"
#include "vtkSMUndoStack.h"
#include "vtkSMUndoStackBuilder.h"
#include "vtkSmartPointer.h"
#include "vtkUndoSet.h"

#include <vector>

namespace geoshaping::undo
{

namespace
{
vtkSMUndoStackBuilder* builder()
{
  vtkSMProxyManager* manager =
    vtkSMProxyManager::IsInitialized() ? vtkSMProxyManager::GetProxyManager() : nullptr;
  vtkSMUndoStackBuilder* b = manager ? manager->GetUndoStackBuilder() : nullptr;
  return b && b->GetUndoStack() ? b : nullptr;
}
}

vtkSMUndoStackBuilder* recording_builder()
{
  vtkSMUndoStackBuilder* b = builder();
  if (!b || b->GetIgnoreAllChanges() || b->GetUndoStack()->GetInUndo() ||
      b->GetUndoStack()->GetInRedo())
  {
    return nullptr;
  }
  return b;
}

Exclude::Exclude()
  : Builder(builder())
{
  if (this->Builder)
  {
    this->Was = this->Builder->GetIgnoreAllChanges();
    this->Builder->SetIgnoreAllChanges(true);
  }
}

Exclude::~Exclude()
{
  if (this->Builder)
  {
    this->Builder->SetIgnoreAllChanges(this->Was);
  }
}

struct Step::Internals
{
  std::string Label;
  // Per tracked proxy: ParaView's element holding its state at track() (before = after).
  std::vector<
    std::pair<vtkSmartPointer<vtkSMProxy>, vtkSmartPointer<vtkSMRemoteObjectUpdateUndoElement>>>
    Tracked;
  std::vector<vtkSmartPointer<vtkSMUndoElement>> Elements;
  bool Finished = false;
};

Step::Step(std::string label)
  : Internal(new Internals)
{
  this->Internal->Label = std::move(label);
}

Step::~Step() = default;

void Step::track(vtkSMProxy* proxy)
{
  const vtkSMMessage* state = proxy ? proxy->GetFullState() : nullptr;
  if (!state || !builder())
  {
    return;
  }
  auto before = vtkSmartPointer<vtkSMRemoteObjectUpdateUndoElement>::New();
  before->SetSession(proxy->GetSession());
  before->SetUndoRedoState(state, state);
  this->Internal->Tracked.emplace_back(proxy, before);
}

void Step::add(vtkSMUndoElement* element)
{
  if (element)
  {
    this->Internal->Elements.emplace_back(element);
  }
}

bool Step::finish()
{
  vtkSMUndoStackBuilder* b = recording_builder();
  if (this->Internal->Finished || !b)
  {
    return false;
  }
  this->Internal->Finished = true;
  std::vector<vtkSmartPointer<vtkSMUndoElement>> elements;
  for (const auto& tracked : this->Internal->Tracked)
  {
    const vtkSMMessage* now = tracked.first->GetFullState();
    if (now)
    {
      auto change = vtkSmartPointer<vtkSMRemoteObjectUpdateUndoElement>::New();
      change->SetSession(tracked.first->GetSession());
      change->SetUndoRedoState(tracked.second->BeforeState, now);
      elements.emplace_back(change);
    }
  }
  elements.insert(elements.end(), this->Internal->Elements.begin(), this->Internal->Elements.end());
  if (elements.empty())
  {
    return false;
  }
  b->Begin(this->Internal->Label.c_str());
  for (const auto& element : elements)
  {
    b->Add(element);
  }
  b->End();
  b->PushToStack(); // inside an enclosing Begin()/End(), that one pushes
  return true;
}

vtkUndoSet* next_step(bool redo)
{
  vtkSMUndoStackBuilder* b = builder();
  vtkSMUndoStack* stack = b ? b->GetUndoStack() : nullptr;
  if (!stack)
  {
    return nullptr;
  }
  return redo ? (stack->CanRedo() ? stack->GetNextRedoSet() : nullptr)
              : (stack->CanUndo() ? stack->GetNextUndoSet() : nullptr);
}

} // namespace geoshaping::undo
