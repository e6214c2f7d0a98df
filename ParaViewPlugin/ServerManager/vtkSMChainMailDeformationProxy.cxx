#include "vtkSMChainMailDeformationProxy.h"

#include "edit_commands.h"
#include "geoshaping/deform/obstacle_loop.h"
#include "undo_step.h"
#include "vtkSMEditHistoryUndoElement.h"

#include "vtkClientServerStream.h"
#include "vtkCommand.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPVXMLElement.h"
#include "vtkSMInputProperty.h"
#include "vtkSMProperty.h"
#include "vtkSMPropertyHelper.h"
#include "vtkSMProxyListDomain.h"
#include "vtkSMProxyLocator.h"
#include "vtkSMProxyManager.h"
#include "vtkSMSessionProxyManager.h"

#include <cstring>
#include <string>
#include <utility>
#include <vector>

namespace interactor = geoshaping::interactor;

namespace
{
// EditProxy over a server-manager proxy.
class SMEditProxy : public interactor::EditProxy
{
public:
  explicit SMEditProxy(vtkSMProxy* proxy)
    : Proxy(proxy)
  {
  }
  void update_information() override { this->Proxy->UpdatePropertyInformation(); }
  std::string last_edit() override
  {
    const char* s = vtkSMPropertyHelper(this->Proxy, "LastEdit").GetAsString();
    return s ? s : "";
  }
  int number_of_edits() override
  {
    return vtkSMPropertyHelper(this->Proxy, "NumberOfEdits").GetAsInt();
  }
  int number_of_redoable_edits() override
  {
    return vtkSMPropertyHelper(this->Proxy, "NumberOfRedoableEdits").GetAsInt();
  }
  std::vector<std::string> history() override
  {
    vtkSMPropertyHelper helper(this->Proxy, "EditHistory");
    std::vector<std::string> records;
    for (unsigned int i = 0; i < helper.GetNumberOfElements(); ++i)
    {
      const char* s = helper.GetAsString(i);
      records.emplace_back(s ? s : "");
    }
    return records;
  }
  void set_history(const std::vector<std::string>& records) override
  {
    vtkSMPropertyHelper helper(this->Proxy, "EditHistory");
    helper.SetNumberOfElements(static_cast<unsigned int>(records.size()));
    for (std::size_t i = 0; i < records.size(); ++i)
    {
      helper.Set(static_cast<unsigned int>(i), records[i].c_str());
    }
  }
  void release() override
  {
    vtkSMPropertyHelper(this->Proxy, "GraspMode").Set(0); // Point Id
    vtkSMPropertyHelper(this->Proxy, "GraspPointId").Set(static_cast<vtkIdType>(-1));
    const double zero[3] = { 0.0, 0.0, 0.0 };
    vtkSMPropertyHelper(this->Proxy, "Displacement").Set(zero, 3);
  }
  void push() override { this->Proxy->UpdateVTKObjects(); }

private:
  vtkSMProxy* Proxy;
};
}

vtkStandardNewMacro(vtkSMChainMailDeformationProxy);

vtkSMChainMailDeformationProxy::vtkSMChainMailDeformationProxy()
{
  this->AddObserver(
    vtkCommand::UpdatePropertyEvent, this, &vtkSMChainMailDeformationProxy::PropertyPushed);
}

void vtkSMChainMailDeformationProxy::CreateVTKObjects()
{
  this->Superclass::CreateVTKObjects();
  vtkSMSessionProxyManager* proxies = this->GetSessionProxyManager();
  if (proxies && !this->Session)
  {
    this->Session = proxies;
    this->SessionObserver = proxies->AddObserver(vtkCommand::PropertyModifiedEvent, this,
      &vtkSMChainMailDeformationProxy::SessionPropertyModified);
  }
  if (vtkSMProperty* obstacles = this->GetProperty("Obstacles"))
  {
    obstacles->AddObserver(
      vtkCommand::ModifiedEvent, this, &vtkSMChainMailDeformationProxy::ObstaclesChanged);
  }
}

vtkSMChainMailDeformationProxy::~vtkSMChainMailDeformationProxy()
{
  if (this->Session)
  {
    this->Session->RemoveObserver(this->SessionObserver);
  }
}

namespace
{
// Whether `self` is `proxy` or one of its producers, transitively (every proxy property).
bool MadeFrom(vtkSMProxy* proxy, vtkSMProxy* self)
{
  return geoshaping::made_from(proxy, self,
    [](vtkSMProxy* p, auto add)
    {
      for (unsigned int i = 0; i < p->GetNumberOfProducers(); ++i)
        add(p->GetProducerProxy(i));
    });
}

// The name the Pipeline Browser shows, else the proxy's label.
std::string ShownName(vtkSMProxy* proxy)
{
  vtkSMSessionProxyManager* proxies = proxy ? proxy->GetSessionProxyManager() : nullptr;
  const char* name = proxies ? proxies->GetProxyName("sources", proxy) : nullptr;
  return name ? name : proxy && proxy->GetXMLLabel() ? proxy->GetXMLLabel() : "(unknown)";
}
} // namespace

void vtkSMChainMailDeformationProxy::SessionPropertyModified(vtkObject*, unsigned long, void* data)
{
  auto* info = static_cast<vtkSMProxyManager::ModifiedPropertyInformation*>(data);
  if (this->RefusingLoops || !info || !info->Proxy || !info->PropertyName ||
      !vtkSMProxyProperty::SafeDownCast(info->Proxy->GetProperty(info->PropertyName)))
  {
    return; // only a link between proxies can close a loop
  }
  this->RefuseInputLoops(info->Proxy, info->PropertyName);
}

void vtkSMChainMailDeformationProxy::RefuseInputLoops(vtkSMProxy* modified, const char* property)
{
  this->RefusingLoops = true;
  std::string refused; // the filter's words for the last input refused
  bool ours = false;   // the change was to the Obstacles, the Markers or one of theirs
  bool changed = false;
  for (const char* name : { "Obstacles", "Markers" })
  {
    auto* inputs = vtkSMInputProperty::SafeDownCast(this->GetProperty(name));
    if (!inputs)
    {
      continue;
    }
    auto* connections = inputs->FindDomain<vtkSMProxyListDomain>();
    std::string here;
    for (unsigned int k = inputs->GetNumberOfProxies(); k-- > 0;)
    {
      vtkSMProxy* input = inputs->GetProxy(k);
      ours = ours || input == modified;
      if (!input || !MadeFrom(input, this))
      {
        continue;
      }
      if (connections && connections->HasProxy(input))
      {
        // The panel's Pipeline Connection: its Input goes back to (none).
        here = ShownName(vtkSMPropertyHelper(input, "Input").GetAsProxy());
        vtkSMPropertyHelper(input, "Input").RemoveAllValues();
        input->UpdateVTKObjects();
      }
      else
      {
        here = ShownName(input);
        inputs->RemoveProxy(input);
      }
    }
    ours = ours || (modified == this && std::strcmp(property, name) == 0);
    if (here.empty())
    {
      continue;
    }
    if (inputs->GetNumberOfProxies() == 0 && connections && connections->GetNumberOfProxies())
    {
      inputs->AddInputConnection(connections->GetProxy(0), 0); // the panel's (none)
    }
    changed = true;
    const bool obstacles = std::strcmp(name, "Obstacles") == 0;
    refused = (obstacles ? "Obstacle " : "Markers input ") + here;
    vtkErrorMacro(<< name << ": " << here << " is made from " << ShownName(this)
                  << "'s own output, a pipeline loop; it was taken off the " << name
                  << ", and the output is the undeformed input until the " << name << " change.");
  }
  if (changed)
  {
    this->UpdateVTKObjects();
  }
  if (!refused.empty() || (ours && this->LoopRefused))
  {
    vtkClientServerStream stream;
    stream << vtkClientServerStream::Invoke << VTKOBJECT(this) << "RefuseObstacleLoop"
           << refused.c_str() << vtkClientServerStream::End;
    this->ExecuteStream(stream);
    this->LoopRefused = !refused.empty();
  }
  this->RefusingLoops = false;
}

void vtkSMChainMailDeformationProxy::PropertyPushed(vtkObject*, unsigned long, void* name)
{
  interactor::EditCommand command;
  // InvokeCommand (UpdateProperty) fires this after the server ran the command.
  // UpdateVTKObjects fires it before its push and never carries a user's command (the
  // panel's buttons, the dock and Python all invoke): it is left alone.
  if (!name || this->InUpdateVTKObjects || this->Following ||
      !interactor::is_edit_command(static_cast<const char*>(name), command))
  {
    return;
  }
  this->Following = true;
  SMEditProxy edits(this);
  const std::vector<std::string> before = edits.history();
  interactor::EditResult result;
  {
    // The bookkeeping push (list, release) is part of the command's step, not a step.
    geoshaping::undo::Exclude bookkeeping;
    result = interactor::follow_edit(command, edits);
  }
  this->Following = false;
  this->LastEditChanged = result.changed;
  this->LastEditRedoable = result.redoable;
  this->LastEditMessage = result.message;
  if (result.changed)
  {
    static const char* const labels[] = { "Commit Edit", "Undo Edit", "Redo Edit", "Reset Edits",
      "Snap to Markers" };
    geoshaping::undo::Step step(labels[static_cast<int>(command)]);
    vtkNew<vtkSMEditHistoryUndoElement> element;
    element->Set(this, before, edits.history());
    step.add(element);
    step.finish();
  }
}

void vtkSMChainMailDeformationProxy::RestoreEdits(const std::vector<std::string>& records)
{
  this->Following = true;
  SMEditProxy edits(this);
  interactor::EditResult result;
  {
    geoshaping::undo::Exclude restoring;
    result = interactor::restore_edits(records, edits);
  }
  this->Following = false;
  this->LastEditChanged = result.changed;
  this->LastEditRedoable = result.redoable;
  this->LastEditMessage = result.message;
}

int vtkSMChainMailDeformationProxy::LoadXMLState(
  vtkPVXMLElement* element, vtkSMProxyLocator* locator)
{
  // The Obstacles as the state lists them, when it predates the Pipeline Connection.
  std::vector<std::pair<int, int>> legacy; // (proxy id, output port)
  bool hasDomain = false;
  for (unsigned int i = 0; element && i < element->GetNumberOfNestedElements(); ++i)
  {
    vtkPVXMLElement* property = element->GetNestedElement(i);
    const char* name = property->GetAttribute("name");
    if (!name || std::strcmp(name, "Obstacles") != 0 || !property->GetName() ||
        std::strcmp(property->GetName(), "Property") != 0)
    {
      continue;
    }
    for (unsigned int j = 0; j < property->GetNumberOfNestedElements(); ++j)
    {
      vtkPVXMLElement* child = property->GetNestedElement(j);
      const char* childName = child->GetAttribute("name");
      int id = 0, port = 0;
      if (std::strcmp(child->GetName(), "Domain") == 0 && childName &&
          std::strcmp(childName, "proxy_list") == 0)
      {
        hasDomain = true;
      }
      else if (std::strcmp(child->GetName(), "Proxy") == 0 &&
               child->GetScalarAttribute("value", &id))
      {
        child->GetScalarAttribute("output_port", &port);
        legacy.emplace_back(id, port);
      }
    }
  }
  const int loaded = this->Superclass::LoadXMLState(element, locator);
  this->LegacyObstacles.clear();
  this->LegacyPorts.clear();
  if (!loaded || hasDomain || !locator)
  {
    return loaded;
  }
  for (const auto& [id, port] : legacy)
  {
    if (vtkSMProxy* source = locator->LocateProxy(id))
    {
      this->LegacyObstacles.emplace_back(source);
      this->LegacyPorts.push_back(static_cast<unsigned int>(port));
    }
  }
  // The domain's Pipeline Connection may be made (and chosen as the property's default)
  // only after this proxy is loaded: then ObstaclesChanged finishes the move.
  this->MoveLegacyObstacles();
  return loaded;
}

void vtkSMChainMailDeformationProxy::ObstaclesChanged(vtkObject*, unsigned long, void*)
{
  if (!this->LegacyObstacles.empty() && !this->MovingObstacles)
  {
    this->MoveLegacyObstacles();
    this->LegacyObstacles.clear(); // one try: a later change is the user's
    this->LegacyPorts.clear();
  }
}

void vtkSMChainMailDeformationProxy::MoveLegacyObstacles()
{
  auto* obstacles = vtkSMInputProperty::SafeDownCast(this->GetProperty("Obstacles"));
  auto* connections = obstacles ? obstacles->FindDomain<vtkSMProxyListDomain>() : nullptr;
  vtkSMProxy* connection =
    connections && connections->GetNumberOfProxies() > 0 ? connections->GetProxy(0) : nullptr;
  if (!obstacles || this->LegacyObstacles.empty())
  {
    return;
  }
  this->MovingObstacles = true;
  std::vector<vtkSMProxy*> sources;
  std::vector<unsigned int> ports = this->LegacyPorts;
  for (const auto& source : this->LegacyObstacles)
  {
    sources.push_back(source);
  }
  const bool moved = sources.size() == 1 && connection && connection->GetProperty("Input");
  if (moved)
  {
    vtkSMPropertyHelper(connection, "Input").Set(sources[0], ports[0]);
    connection->UpdateVTKObjects();
    sources[0] = connection;
    ports[0] = 0;
  }
  obstacles->SetProxies(static_cast<unsigned int>(sources.size()), sources.data(), ports.data());
  this->UpdateVTKObjects();
  if (moved || sources.size() > 1)
  {
    this->LegacyObstacles.clear(); // done: nothing left to move
    this->LegacyPorts.clear();
  }
  this->MovingObstacles = false;
}

void vtkSMChainMailDeformationProxy::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "LastEditChanged: " << this->LastEditChanged << "\n";
  os << indent << "LastEditRedoable: " << this->LastEditRedoable << "\n";
  os << indent << "LastEditMessage: " << this->LastEditMessage << "\n";
}
