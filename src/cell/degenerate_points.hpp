// Degenerate isolated critical points of a cell's polynomial g (a singular Hessian: monkey
// saddles, flat extrema, inflection points), classified by their sectors instead of falling back
// to the PL stand-in (docs/ALGORITHM.md §3, "Degenerate critical points").
//
// The gradient-zero search cannot certify such a zero (Krawczyk needs a regular Hessian) and
// reports an unresolved box around it. For each such cluster centre c, with L = g(c):
//  1. The search runs again with a small square B around c excluded; it must then certify every
//     other zero of the cell: all zeros not certified lie in B.
//  2. On the boundary of a larger square Q around c (inside the cell, holding no other zero), the
//     roots of g - L are isolated side by side and must all be simple: the arcs where g < L
//     (lower sectors) and g > L (upper sectors) are exact.
//  3. Each arc gets a straight ray from c to a point of it, certified below (above) L: the
//     Bernstein coefficients of the ray's restriction, but its leading ones that are L up to
//     rounding (the zero's order), lie below L.
// Every component of {g < L} in Q whose closure meets B then reaches the boundary of Q (else it
// would hold a minimum, i.e. a zero, outside B, or one in B at most `slack` below L), so it holds
// an arc, whose ray joins it to c: the node's lower connections are complete. Extra rays into one
// component are harmless (the sweeps merge a component once). No arcs of one sign: an extremum;
// one of each: a regular point (no node); k of each (k >= 2): a saddle of multiplicity k - 1.
// The node stands for everything in B: its value is within `slack` of each point of B.
// Anything not certified (a zero too close to the cell's boundary or to another zero, a tangency
// on Q's boundary, a ray into a cusp) fails, and the cell falls back as before.
#pragma once

#include "poly/bernstein_triangle.hpp"
#include "poly/gradient_zeros.hpp"

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace hoct {

// A point of each lower and upper sector of a node, and how many leading Bernstein coefficients
// of the ray from the node to it are the node's value up to rounding (the first step's skip).
struct SectorRays {
  std::vector<Vec2> lower, upper;
  std::vector<int> lower_skip, upper_skip;
  // Where each ray starts, if not at the node's own position (a critical curve's rays start on
  // the curve: cell/critical_curves.hpp); empty: at the node.
  std::vector<Vec2> lower_from, upper_from;
};

struct DegenerateCritical {
  Vec2 uv{0, 0};
  double value = 0;
  SectorRays rays;
  double slack = 0;  // |g - value| <= slack on the excluded square B (certified)
  double radius = 0; // B's half-width
};

struct DegenerateResolution {
  bool resolved = false;
  // The cell's zeros outside the degenerate ones, all certified (near_boundary as found).
  std::vector<GradientZero> zeros;
  // The degenerate critical points that are nodes (extrema and saddles), and how many were
  // classified regular (no node).
  std::vector<DegenerateCritical> points;
  int64_t regular = 0;
  double slack = 0; // the largest slack of all classified points, regular ones included
};

// An arc of the boundary of a square where g < level (lower) or g > level (upper), and its
// point of largest |g - level| among samples.
struct SignArc {
  bool lower;
  Vec2 point;
};

// The sign arcs of g - level on the boundary of the square of half-width r around c (sides
// parallel to the axes of the reference triangle, turned by `angle` radians), from the exact roots
// of g - level on its four sides, in order around it (one arc for the whole boundary if there is no
// root); false if a root is not simple, lies on a corner, or an arc's samples are within tol of the
// level.
bool sign_arcs_on_square(const BernsteinTriangle &g, const Vec2 &c, double r, double level,
                         double tol, std::vector<SignArc> &arcs, double angle = 0);
// The same along a polyline through the points q (closed: back to q[0]), in order from q[0];
// on an open polyline the first arc starts at q[0] and the last ends at q.back().
bool sign_arcs_on_polyline(const BernsteinTriangle &g, std::span<const Vec2> q, bool closed,
                           double level, double tol, std::vector<SignArc> &arcs);

// Moves c towards a zero of the gradient by Newton steps with the Hessian's pseudo-inverse (its
// eigenvalues below null_ratio of the largest dropped), as long as the gradient shrinks and c
// stays within `reach` (max norm) of `around`: at a degenerate zero, or on a curve of zeros,
// Newton converges only linearly along the null direction, but the other coordinate (along which
// the zero is regular) comes out to full precision.
Vec2 polish_zero(const BernsteinTriangle &g, Vec2 c, const Vec2 &around, double reach,
                 double null_ratio = 1e-8);

// The number of leading Bernstein coefficients of g on the segment c -> p that equal `level`
// within `tol` (at least 1: the first is g(c)), if g is certified below `level` - margin on the
// rest of the segment; else -1. For rays above the level, pass -g and -level.
int certify_ray(const BernsteinTriangle &g, const Vec2 &c, const Vec2 &p, double level,
                double margin, double tol);

// Classifies the unresolved zeros of `first` (find_gradient_zeros of g with `options`), or says
// it cannot (resolved = false). `value_noise`: how far g's values may be off from the rounding of
// the input data (Field::precision); leading ray coefficients that close to the node's value are
// skipped too, and count in the slack.
DegenerateResolution resolve_degenerate_zeros(const BernsteinTriangle &g,
                                              const GradientZeros &first,
                                              const GradientZeroOptions &options,
                                              double value_noise = 0);
// The same around given points: zeros the search certified but whose sectors no path could
// connect (a degenerate point that the data's rounding split into nearby regular ones).
DegenerateResolution resolve_degenerate_zeros(const BernsteinTriangle &g,
                                              std::span<const Vec2> candidates,
                                              const GradientZeroOptions &options,
                                              double value_noise = 0);

// Critical points at the cell's corners: a vertex where the derivative of an edge through it
// vanishes (the gradient is zero there, or orthogonal to that edge), which the rule "a corner's
// lower part touches a descending edge" does not cover. In the corner triangle T = (v,
// v + r (next corner - v), v + r (previous corner - v)), r below half the distance to the first
// node on either edge (so each edge is strictly monotone on T's sides along it), the sign arcs
// of g - g(v) on the side opposite v are exact; the first and last continue along the edges,
// whose chains connect them; every other arc is a sector inside the cell and gets a certified
// ray from v. Completeness as for interior points: the search, run with a square B around each
// such corner excluded, certifies every other zero, and T holds none of them.
struct CornerResolution {
  bool resolved = false;
  std::vector<GradientZero> zeros;                  // the cell's other zeros (certified)
  std::array<std::optional<SectorRays>, 3> corners; // the interior sectors of critical corners
  double slack = 0;
};

// Corner k's sectors inside the cell from the sign arcs of g - g(v) on the side opposite v of
// the corner triangle of size r (r0, then a quarter and a sixteenth of it, down to min_r), which
// must hold no gradient zero (but at v, within the slack `tol`); `neg`: -g, for ascending rays.
std::optional<SectorRays> classify_corner(const BernsteinTriangle &g, const BernsteinTriangle &neg,
                                          int k, double r0, double min_r, double tol,
                                          double margin);

// `critical[k]`: corner k needs it; `reach[k]`: the largest r there (in edge parameters);
// `search`: the gradient may vanish in the cell (else it has no zero: no search).
CornerResolution resolve_critical_corners(const BernsteinTriangle &g,
                                          const std::array<bool, 3> &critical,
                                          const std::array<double, 3> &reach,
                                          const GradientZeroOptions &options, bool search,
                                          double value_noise = 0);

} // namespace hoct
