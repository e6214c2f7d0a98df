// The re-examination rule, stated directly (chainmail_deformer.h, docs/deformer.md): a
// candidate found inside its box is NOT marked, so a neighbour that moves later examines
// it again and may move it.
#include "geoshaping/deform/chainmail_deformer.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

using namespace geoshaping;

TEST(ChainMailDeformer, ACandidateFoundInsideItsBoxIsExaminedAgainWhenAnotherNeighbourMoves)
{
  // Five vertices, grasp 0 pulled up by 1 (z). Two paths reach vertex 2:
  //   0 -> 1 -> 2      soft 1 and 2 (t 2, k 0.5, h 0.5): 1 lags to z = 0.5, and 2, at
  //                    offset (1, 0, 0) from 1, is inside its box z in [0, 1]: not moved;
  //   0 -> 4 -> 3 -> 2 rigid 4 and 3 translate by the full pull (z = 1); 2, at offset
  //                    (0, -1, 0) from 3, must lie within z in [1 - 0.5, 1 + 0.5].
  // Plain FIFO examines (2 by 1) before (3 by 4) has moved 3, then (2 by 3): only if the
  // first examination left 2 unmarked does 2 move, to z = 0.5. Marking it would leave
  // 2 at rest, outside its valid region w.r.t. 3 (E_link 0.5).
  geoshaping::testing::Mesh mesh;
  mesh.xyz = { 0, 0, 0, /*1*/ 1, 0, 0, /*2*/ 2, 0, 0, /*3*/ 2, 1, 0, /*4*/ 0, 1, 0 };
  AdjacencyBuilder b(5);
  for (auto [p, q] :
    { std::pair<index_t, index_t>{ 0, 1 }, { 1, 2 }, { 0, 4 }, { 4, 3 }, { 3, 2 } })
  {
    b.add_edge(p, q);
  }
  mesh.adjacency = b.build();
  ChainMailDeformer d;
  d.set_mesh(mesh.xyz.data(), mesh.size(), mesh.adjacency);
  const float malleability[5] = { 1.0f, 1.0f, 1.0f, 0.0f, 0.0f };
  d.set_malleability(malleability);
  d.set_queue(QueueKind::fifo);
  ASSERT_TRUE(d.deform(0, { 0.0, 0.0, 1.0 }).ok);

  EXPECT_EQ(d.displacement(4), Eigen::Vector3d(0, 0, 1));
  EXPECT_EQ(d.displacement(3), Eigen::Vector3d(0, 0, 1));
  EXPECT_EQ(d.displacement(1), Eigen::Vector3d(0, 0, 0.5));
  // Re-examined through 3: moved to the bottom of its box, x and y untouched.
  EXPECT_EQ(d.displacement(2), Eigen::Vector3d(0, 0, 0.5));
}
