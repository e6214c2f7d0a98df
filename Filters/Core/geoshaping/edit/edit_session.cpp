#include "geoshaping/edit/edit_session.h"

namespace geoshaping
{

void EditSession::add(std::string record)
{
  records_.push_back(std::move(record));
  pending_ = true;
}

void EditSession::clear()
{
  records_.clear();
  pending_ = true;
}

bool EditSession::commit(ChainMailDeformer& deformer, const EditRecipe& recipe,
  const std::vector<index_t>& vertices, const std::vector<Eigen::Vector3d>& displacements,
  const EditPlace& place)
{
  if (pending_)
    return false;
  history_.commit(deformer, recipe, vertices, displacements, place);
  last_ = history_.record(history_.applied() - 1);
  records_.push_back(last_); // already applied: nothing pending
  return true;
}

bool EditSession::undo()
{
  if (records_.empty())
    return false;
  records_.pop_back();
  pending_ = true;
  return true;
}

bool EditSession::redo()
{
  if (history_.size() <= records_.size())
    return false;
  last_ = history_.record(records_.size());
  records_.push_back(last_);
  pending_ = true;
  return true;
}

bool EditSession::reset()
{
  if (records_.empty())
    return false;
  records_.clear();
  pending_ = true;
  return true;
}

int EditSession::redoable() const
{
  return history_.size() > records_.size() ? int(history_.size() - records_.size()) : 0;
}

void EditSession::forget_applied()
{
  history_.clear();
  pending_ = true;
}

bool EditSession::synchronize(ChainMailDeformer& deformer, std::string& error,
  const std::function<bool(index_t)>& fits, const EditPlace& place)
{
  if (!pending_)
    return true;
  pending_ = false;
  return history_.synchronize(deformer, records_, error, fits, place);
}

} // namespace geoshaping
