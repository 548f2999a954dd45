// Curves of critical points inside a cell (exact ridges and valleys, curves of saddles), each
// certified as one node with its sectors instead of falling back to the PL stand-in
// (docs/ALGORITHM.md §3, "Critical curves").
//
// 1. Cover. Boxes over the reference triangle are examined with the cell's Taylor model at their
//    centre x (gradient, Hessian H = lambda n n' + mu t t', |lambda| >= |mu|) and a bound K3 on
//    its third derivatives. A zero z of the gradient in the box (Euclidean radius rho) satisfies
//    n.grad(x) + lambda n.(z - x) = O(R) and t.grad(x) + mu t.(z - x) = O(R), with
//    R = K3 rho^2 / 2 plus rounding: a box where either cannot hold has no zero; else every zero
//    lies in the slab |n.(z - x) - w0| <= eps (w0 = -n.grad(x) / lambda, eps = R / |lambda|), on
//    which |g - G| <= b with G = g(x) - lambda w0^2 / 2 and
//    b = rho |t.grad(x)| + |mu| rho^2 / 2 + |lambda| eps^2 / 2 + K3 rho^3 / 6 (plus rounding).
//    Boxes are split until each has no zero or a slab with b below the target; on a quadratic
//    ridge (K3 = 0, mu = 0) the first boxes already do.
// 2. Curves. Slabs that meet (on the common side of their boxes) are one curve: a connected set
//    on which |g - L| <= slack for one value L. It is one node; `anchors` are points of it.
// 3. Sectors. Q, the squares of a grid (8 to 64 per side) holding the curve's boxes and their
//    neighbours, holds no other zero. On the parts of Q's boundary inside the cell the roots of
//    g - L are exact and simple; each arc where g < L (g > L) gets a ray from an anchor, certified
//    below (above) L past its leading coefficients within the slack. A component of {g < L} in Q
//    whose closure meets the curve reaches Q's inner boundary (then its arc's ray joins it), or
//    has its lowest point on the curve (within the slack) or at an edge node or corner in Q,
//    which must then lie on the curve: so the node's connections are complete.
// Edge nodes and corners on the curve (where it crosses or touches the cell's boundary) are the
// same node: the caller joins them to it in both graphs. Anything not certified (an isolated
// zero next to the curve, a box budget run out, a root on Q's boundary that is not simple) fails,
// and the cell falls back as before.
#pragma once

#include "cell/degenerate_points.hpp"
#include "poly/bernstein_triangle.hpp"

#include <array>
#include <optional>
#include <span>
#include <vector>

namespace hoct {

struct CriticalCurve {
  Vec2 uv{0, 0};    // a point of it (one of its anchors)
  double value = 0; // L
  double slack = 0; // |g - L| <= slack on the whole node (certified, the data's noise added)
  std::vector<Vec2> anchors;       // points on it, where paths from other nodes may end
  SectorRays rays;                 // each sector's ray, from an anchor (lower_from, upper_from)
  std::vector<int> boundary_nodes; // the given boundary points on it (indices)
};

struct CurveResolution {
  bool resolved = false;
  std::vector<CriticalCurve> curves;
  double slack = 0; // the largest of the curves'
  int64_t boxes = 0;
  std::array<std::optional<SectorRays>, 3> corners; // critical corners on no curve
};

// The critical curves of g, if every zero of its gradient in the cell lies on one and each is
// classified; `boundary_points`: the cell's corners and edge nodes (reference coordinates), each
// either off every curve's region or on a curve. `value_noise`: Field::precision.
// `corners[k]`: corner k is critical for an edge (its derivative vanishes there,
// kEdgeRootAtVertex); if on no curve, its sectors are classified in its corner triangle, of size
// at most corner_reach[k] (in edge parameters), into `CurveResolution::corners`. `max_boxes`:
// the cover gives up (unresolved) past that many boxes.
inline constexpr int64_t kCurveCoverBoxes = 20000;
CurveResolution resolve_critical_curves(const BernsteinTriangle &g,
                                        std::span<const Vec2> boundary_points,
                                        double value_noise = 0,
                                        const std::array<bool, 3> &corners = {},
                                        const std::array<double, 3> &corner_reach = {},
                                        int64_t max_boxes = kCurveCoverBoxes);

} // namespace hoct
