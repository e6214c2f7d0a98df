#include "edit_commands.h"

namespace geoshaping::interactor
{

namespace
{
constexpr EditCommand all_commands[] = { EditCommand::commit, EditCommand::undo, EditCommand::redo,
  EditCommand::reset, EditCommand::snap };
}

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
    case EditCommand::snap:
      return "SnapToMarkers";
  }
  return "";
}

bool is_edit_command(const std::string& property, EditCommand& command)
{
  for (EditCommand c : all_commands)
  {
    if (property == command_property(c))
    {
      command = c;
      return true;
    }
  }
  return false;
}

namespace
{
// The end every command shares: the list stored when it changed, the grasp released,
// the proxy pushed and its information read back into the result.
EditResult settle(const std::vector<std::string>& records, EditResult result, EditProxy& proxy)
{
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
} // namespace

EditResult follow_edit(EditCommand command, EditProxy& proxy)
{
  EditResult result;
  std::vector<std::string> records = proxy.history();
  proxy.update_information();
  const int server = proxy.number_of_edits();
  switch (command)
  {
    case EditCommand::commit:
    case EditCommand::redo:
    case EditCommand::snap:
    {
      const std::string record = proxy.last_edit();
      if (server == static_cast<int>(records.size()) + 1 && !record.empty())
      {
        records.push_back(record);
        result.changed = true;
      }
      else
      {
        result.message = command == EditCommand::commit ? "nothing to commit"
                         : command == EditCommand::snap ? "no marker snapped"
                                                        : "nothing to redo";
      }
      break;
    }
    case EditCommand::undo:
      if (records.empty())
      {
        result.message = "nothing to undo";
      }
      else
      {
        records.pop_back();
        result.changed = true;
      }
      break;
    case EditCommand::reset:
      result.changed = !records.empty();
      records.clear();
      break;
  }
  return settle(records, result, proxy);
}

EditResult restore_edits(const std::vector<std::string>& records, EditProxy& proxy)
{
  EditResult result;
  result.changed = proxy.history() != records;
  return settle(records, result, proxy);
}

} // namespace geoshaping::interactor
