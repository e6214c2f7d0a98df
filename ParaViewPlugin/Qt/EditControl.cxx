#include "EditControl.h"

#include <algorithm>
#include <cmath>

namespace geoshaping::interactor
{

const char* command_property(EditCommand command)
{
  switch (command)
  {
    case EditCommand::commit:
      return "CommitEdit";
    case EditCommand::undo:
      return "UndoEdit";
    case EditCommand::redo:
      return "RedoEdit";
    case EditCommand::reset:
      return "ResetEdits";
  }
  return "";
}

EditResult run_edit(EditCommand command, EditProxy& proxy)
{
  EditResult result;
  std::vector<std::string> records = proxy.history();
  const std::size_t before = records.size();
  proxy.update_information();
  const int server_before = proxy.number_of_edits();
  if (server_before != static_cast<int>(before))
  {
    result.message = "the server had " + std::to_string(server_before) +
                     " edits, the client's EditHistory " + std::to_string(before) +
                     " (kept the client's); ";
  }
  if (command == EditCommand::undo && records.empty())
  {
    result.message += "nothing to undo";
  }
  else
  {
    proxy.invoke(command_property(command));
    proxy.update_information();
    const int server_after = proxy.number_of_edits();
    switch (command)
    {
      case EditCommand::commit:
      case EditCommand::redo:
      {
        const std::string record = proxy.last_edit();
        if (server_after == server_before + 1 && !record.empty())
        {
          records.push_back(record);
          result.changed = true;
        }
        else
        {
          result.message +=
            command == EditCommand::commit ? "nothing to commit" : "nothing to redo";
        }
        break;
      }
      case EditCommand::undo:
        records.pop_back();
        result.changed = true;
        break;
      case EditCommand::reset:
        result.changed = !records.empty();
        records.clear();
        break;
    }
  }
  if (result.changed)
  {
    proxy.set_history(records);
  }
  proxy.release();
  proxy.push();
  proxy.update_information();
  result.edits = records.size();
  result.redoable = proxy.number_of_redoable_edits();
  return result;
}

double falloff_weight(int falloff, double r)
{
  if (!(r >= 0.0))
    r = 0.0;
  if (r > 1.0)
    return 0.0;
  switch (falloff)
  {
    case 0:
      return 1.0;
    case 1:
      return 1.0 - r;
    case 2:
      return 1.0 - r * r * (3.0 - 2.0 * r);
    case 3:
    {
      const double a = 4.5; // 1 / (2 s^2), s = 1/3
      const double rim = std::exp(-a);
      return (std::exp(-a * r * r) - rim) / (1.0 - rim);
    }
    default:
      return 0.0;
  }
}

void append_point_dabs(const std::vector<long long>& ids, const std::vector<double>& distances,
  double radius, double value, double strength, int falloff, std::vector<double>& triples)
{
  if (!(radius > 0.0) || ids.size() != distances.size())
  {
    return;
  }
  value = std::isfinite(value) ? std::clamp(value, 0.0, 1.0) : 0.0;
  strength = std::isfinite(strength) ? std::clamp(strength, 0.0, 1.0) : 0.0;
  for (std::size_t i = 0; i < ids.size(); ++i)
  {
    const double w = strength * falloff_weight(falloff, distances[i] / radius);
    if (ids[i] >= 0 && w > 0.0)
    {
      triples.insert(triples.end(), { double(ids[i]), value, w });
    }
  }
}

} // namespace geoshaping::interactor
