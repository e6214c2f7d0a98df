#pragma once
// An obstacle made from the deformation's own output is a pipeline loop
// (docs/obstacles.md): the filter (VTK algorithms) and its ParaView proxy (server-manager
// proxies) both refuse it by this walk, each over its own graph.
#include <set>
#include <vector>

namespace geoshaping
{

// Whether `self` is `start` or upstream of it: depth first over `producers(node, add)`,
// which calls `add(p)` for each node `p` feeding `node` (null ones are skipped); each
// node is visited once, so a loop elsewhere in the graph ends the walk too.
template<class Node, class Producers>
bool made_from(Node* start, const Node* self, Producers&& producers)
{
  std::set<Node*> seen;
  std::vector<Node*> open{ start };
  auto add = [&open](Node* p) { open.push_back(p); };
  while (!open.empty())
  {
    Node* node = open.back();
    open.pop_back();
    if (node == self)
      return true;
    if (node && seen.insert(node).second)
      producers(node, add);
  }
  return false;
}

} // namespace geoshaping
