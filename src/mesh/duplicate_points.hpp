// Points at the same position under different ids: a mesh written cell by cell, or two parts
// glued without merging their nodes, has cracks there (the cells do not share the vertex, so the
// topology sees a boundary, a hole or separate components). Found by sorting points into a grid
// of cells of the tolerance's size and comparing neighbours only: O(n log n).
#pragma once

#include "mesh/mesh_input.hpp"

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace hoct {

// For each of `points[candidates[i]]`, the smallest candidate point id within `tolerance`
// (Euclidean) of it, transitively (chains of close points form one group); itself if none.
// `threads`: the grid keys and their sort run in parallel (the result does not depend on it).
std::vector<int64_t> coincident_points(std::span<const Vec3> points,
                                       const std::vector<int64_t> &candidates, double tolerance,
                                       int threads = 1);

// The points' bounding box, lowest and highest corner (both 0 for no points), on `threads`
// threads (the same box for any count: minima and maxima do not depend on the order).
std::array<Vec3, 2> bounding_box(std::span<const Vec3> points, int threads = 1);

// Length of the bounding-box diagonal of the points (0 for none).
double bounding_box_diagonal(std::span<const Vec3> points, int threads = 1);

struct MergeReport {
  int64_t merged_points = 0; // points replaced by another at the same position
};

// Makes every cell refer to the lowest-id point of each group of points closer than
// relative_tolerance x the bounding-box diagonal. Throws hoct::Error naming the points if two
// merged points carry values that differ by more than 1e-9 of the value scale (the field would
// be discontinuous there: merging would hide it).
MergeReport merge_duplicate_points(MeshInput &input, double relative_tolerance, int threads = 1);

} // namespace hoct
