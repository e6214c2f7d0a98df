#pragma once
// The peer a user would pick instead of ChainMail: CGAL's Surface_mesh_deformation (ARAP)
// on the same mesh, handle and region of interest. Optional: without CGAL at configure
// time the peer is left out and the report says so.
#include "report_scenes.h"

#include <string>

namespace geoshaping::report
{

struct PeerResult
{
  bool ran = false;
  std::string scene;          // its title
  std::string note;           // what ran, or why it was left out
  std::size_t roi = 0;        // vertices in the region of interest
  double preprocess_ms = 0.0; // once per region of interest
  double frame_ms = 0.0;      // median per frame (target moved, deform)
  double chainmail_ms = 0.0;  // FIFO Priority on the same frame, same run
  int iterations = 0;         // ARAP iterations per frame
};

// `scene` must carry triangles.
PeerResult run_peer(const Scene& scene, bool smoke);

} // namespace geoshaping::report
