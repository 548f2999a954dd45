// Planar triangulations the generators start from: a jittered grid of a rectangle with squares
// left out (for plates such as the conductor's), and a jittered disk of concentric rings. All
// triangles counter-clockwise; boundary vertices stay on the boundary, interior vertices are moved
// by a seeded jitter that keeps every triangle well shaped.
#pragma once

#include "datasets/linear_mesh.hpp"

#include <cstdint>
#include <functional>

namespace hoct {

struct GridSpec {
  int nx = 1, ny = 1;    // number of rectangles along x and y
  double x0 = 0, y0 = 0; // lower-left corner
  double hx = 1, hy = 1; // rectangle size
  double jitter = 0;     // interior vertices move by up to jitter * min(hx, hy) per axis
  uint64_t seed = 0;     // for the jitter
  // Rectangles (i, j) for which keep(i, j) is false are left out (a hole or a notch).
  std::function<bool(int, int)> keep;
};

// Each kept rectangle is split into two triangles along a diagonal chosen per rectangle by a hash
// of (i, j) and the seed, so the pattern looks unstructured. A vertex is interior (jittered) when
// all four rectangles around it are kept. Vertices used by no triangle are dropped.
LinearMesh grid_triangulation(const GridSpec &spec);

// The disk of radius `radius` centred at `centre` (z = 0): `rings` concentric rings, ring k with
// 6k equally spaced vertices at radius k/rings, between consecutive rings 6(2k-1) triangles;
// 6 rings^2 triangles in all, nearly equilateral. Interior vertices jittered by up to
// jitter * radius / rings per axis.
LinearMesh ring_disk(int rings, double radius, const Vec3 &centre, double jitter, uint64_t seed);

} // namespace hoct
