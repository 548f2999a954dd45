// The thesis' case studies (section 5.5): the exact tree against the PL trees of uniform
// refinements of the same field. Per refinement level: critical points by type, the bottleneck
// distance between the diagrams, how far each exact critical point is from the nearest PL
// critical point of the same type, the features (extrema with persistence above a threshold)
// the PL tree misses or invents, and the time. Flat regions are contracted in every tree (one
// node per plateau), as `hoct tree` reports them.
#pragma once

#include "mesh/mesh.hpp"
#include "tree/tree_result.hpp"

#include <array>
#include <vector>

namespace hoct {

struct StudyRow {
  int k = 0;                                  // 0 for the exact tree
  int64_t triangles = 0;                      // PL triangles (the exact tree: cells)
  std::array<int64_t, 3> counts{};            // minima, maxima, saddles
  double bottleneck = 0;                      // max over join, split and global diagrams
  double mean_distance = 0, max_distance = 0; // exact critical point -> nearest PL one
  int64_t missed = 0, spurious = 0;           // features above the threshold
  double seconds = 0;                         // refinement + tree (the exact tree: the tree)
};

struct StudyOptions {
  std::vector<int> levels = {1, 2, 4, 8, 16};
  double feature_threshold = 0; // absolute persistence; features are extrema above it
  double match_radius = 0;      // 0: 5% of the bounding-box diagonal
  int threads = 0;
};

// Row 0 is the exact tree, then one row per level.
std::vector<StudyRow> case_study(const Mesh &mesh, const StudyOptions &options);

} // namespace hoct
