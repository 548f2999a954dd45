// Each cell's geometry map phi: reference triangle -> R^3, a Bernstein polynomial map through its
// Lagrange nodes, of the cell's own (input) degree or lower where the nodes lie on a map of lower
// degree (linear: the flat triangle; 2 or 3 where that degree divides the input's). Used to report
// positions and to build refinements; the algorithms themselves work in the reference triangle
// (docs/ALGORITHM.md §1).
#pragma once

#include "mesh/mesh_input.hpp"
#include "poly/bernstein_triangle.hpp"
#include "util/uninitialized_vector.hpp"

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

namespace hoct {

class Geometry {
public:
  // `threads` work on the cells at once (the result does not depend on their number).
  // `box`: the input points' bounding box when the caller has it (else it is computed here).
  static Geometry build(const MeshInput &input, int threads = 1,
                        const std::array<Vec3, 2> *box = nullptr);

  int64_t num_cells() const { return maps_ ? static_cast<int64_t>(maps_->degree.size()) : 0; }
  // Degree of the map (1 for a flat, straight-sided cell even if its input degree is higher; 2 for
  // half a straight quadrilateral).
  int degree(int64_t c) const { return maps_->degree[c]; }
  bool is_linear(int64_t c) const { return maps_->degree[c] == 1; }
  // Component i (0 = x, 1 = y, 2 = z) of the map as a Bernstein polynomial.
  BernsteinTriangle component(int64_t c, int i) const;
  Vec3 position(int64_t c, double u, double v) const;
  // The control points of cell c's map (lattice_size(degree(c)) of them, canonical lattice
  // order).
  const Vec3 *control_points(int64_t c) const { return &maps_->coef[maps_->offset[c]]; }
  // d phi / du and d phi / dv.
  std::array<Vec3, 2> jacobian(int64_t c, double u, double v) const;
  // The control points of d phi / du and d phi / dv (degree(c) - 1, canonical lattice order,
  // lattice_size(degree(c) - 1) of each) into du and dv.
  void derivative_points(int64_t c, Vec3 *du, Vec3 *dv) const;
  // The cell's shape as a 2x2 upper-triangular T with |T (du, dv)| = |J (du, dv)|, J the
  // Jacobian at the centroid (T is the R factor of J = Q R): reference steps measured as lengths
  // in the cell.
  Mat2 frame(int64_t c) const;

  // All points lie in the plane z = const (to 1e-12 of the extent).
  bool planar() const { return planar_; }
  int64_t curved_cells() const { return curved_cells_; }
  // Axis-aligned bounding box of the input points: {min, max}.
  const std::array<Vec3, 2> &bounds() const { return bounds_; }
  double extent() const; // length of the bounding-box diagonal

private:
  // The maps, shared by the copies of a Geometry (they do not change after build): a copy costs
  // nothing, and what holds one (a tree's geometric graph, to draw its arcs) outlives the mesh.
  struct Maps {
    UninitializedVector<uint8_t> degree; // these three filled completely by parallel loops
    UninitializedVector<int64_t> offset; // into coef, in units of control points
    UninitializedVector<Vec3> coef;      // control points, canonical lattice order
  };
  std::shared_ptr<const Maps> maps_;
  bool planar_ = true;
  int64_t curved_cells_ = 0;
  std::array<Vec3, 2> bounds_{};
};

} // namespace hoct
