// geoshaping::made_from (geoshaping/deform/obstacle_loop.h): the walk the filter and its
// proxy use to find an obstacle made from the deformation's own output.
#include "geoshaping/deform/obstacle_loop.h"

#include <gtest/gtest.h>

#include <map>
#include <vector>

namespace
{
// A pipeline as "node -> the nodes feeding it"; 0 is the deformation.
bool MadeFrom(const std::map<int, std::vector<int>>& inputs, int start)
{
  std::vector<int> nodes(8);
  for (int i = 0; i < 8; ++i)
    nodes[std::size_t(i)] = i;
  return geoshaping::made_from(&nodes[std::size_t(start)], &nodes[0],
    [&](int* node, auto add)
    {
      auto it = inputs.find(*node);
      if (it != inputs.end())
        for (int p : it->second)
          add(p < 0 ? nullptr : &nodes[std::size_t(p)]);
    });
}
} // namespace

TEST(ObstacleLoop, AnObstacleFedByTheDeformationAnywhereUpstreamIsALoop)
{
  // 1 = horizon -> 0 = deformation -> 2 = transform -> 3 = connection; 4 = a plane.
  // 5 merges the plane and a null input; 6 and 7 feed each other (a loop elsewhere).
  const std::map<int, std::vector<int>> inputs = { { 0, { 1 } }, { 2, { 0 } }, { 3, { 2 } },
    { 5, { 4, -1 } }, { 6, { 7, 4 } }, { 7, { 6 } } };
  EXPECT_TRUE(MadeFrom(inputs, 0)); // the deformation's own output
  EXPECT_TRUE(MadeFrom(inputs, 2));
  EXPECT_TRUE(MadeFrom(inputs, 3));  // through the Pipeline Connection
  EXPECT_FALSE(MadeFrom(inputs, 1)); // upstream of it: no loop
  EXPECT_FALSE(MadeFrom(inputs, 4));
  EXPECT_FALSE(MadeFrom(inputs, 5));
  EXPECT_FALSE(MadeFrom(inputs, 6)); // a loop not through the deformation ends the walk
  auto withMerge = inputs;
  withMerge[5] = { 4, 3 }; // the plane merged with the transform
  EXPECT_TRUE(MadeFrom(withMerge, 5));
}
