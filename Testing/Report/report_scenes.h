#pragma once
// The scenes of the error-against-time report (docs/report.md): each a mesh, its
// painted malleability, a grasp and the pull applied to it.
#include "geoshaping/mesh/adjacency.h"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace geoshaping::report
{

struct Scene
{
  std::string key;   // file-name friendly
  std::string title; // for tables and plots
  std::string note;  // how it was made
  std::vector<double> xyz;
  Adjacency adjacency;
  std::vector<index_t> triangles; // 3 ids each, for triangle scenes (the ARAP peer)
  std::vector<float> malleability;
  index_t grasp = 0;
  Eigen::Vector3d pull = Eigen::Vector3d::Zero();
};

// `scale` < 1 shrinks the scenes (a smoke run); 1 is the report.
Scene fault_step_scene(double scale);
Scene equal_malleability_scene(double scale);
Scene tet_slab_scene(double scale);
// A CRESCENT CFM fault surface read with vtkGocadTSurfReader; empty `xyz` (and the
// reason in `note`) when the file cannot be read.
Scene cfm_scene(const std::string& path);

// The vertex nearest `p` (brute force).
index_t nearest_vertex(const std::vector<double>& xyz, const Eigen::Vector3d& p);

} // namespace geoshaping::report
