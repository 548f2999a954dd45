// Pictures of a field: the surface coloured with a perceptual colour map, isolines computed from
// the exact polynomial (crossing points found by root isolation on fine sub-edges, so every drawn
// vertex lies on the level set), and critical points as glyphs (maxima red, minima blue, saddles
// green). Planar meshes are seen from above, surfaces along a chosen view direction (painter's
// algorithm on sub-triangles). PNG or SVG through Cairo; written atomically.
#pragma once

#include "mesh/mesh.hpp"
#include "tree/tree_result.hpp"

#include <string>
#include <vector>

namespace hoct {

struct RenderOptions {
  int width = 1000, height = 800;
  int isolines = 12;   // evenly spaced levels inside the value range
  Vec3 view{0, 0, 1};  // direction from the object towards the viewer
  int subdivision = 0; // sub-triangles per cell edge (0: automatic)
  std::string title;
};

// `nodes` may be empty (no glyphs). The format follows the extension of `path` (.png or .svg).
void render_field(const std::string &path, const Mesh &mesh, const std::vector<TreeNode> &nodes,
                  const RenderOptions &options);

} // namespace hoct
