// All roots in [0, 1] of a univariate polynomial in Bernstein form, isolated by subdivision with
// Descartes' rule of signs in the Bernstein basis (the number of roots in the open interval is at
// most the number of sign changes of the coefficients, and of the same parity: none means no
// root, one means exactly one simple root), then refined by safeguarded Newton (bisection
// fallback) to full precision. Roots that stay clustered down to the resolution (multiple or
// near-multiple roots, or roots closer than cluster_distance) are reported as one non-simple
// root, never dropped. Exact zeros at the
// interval ends and at subdivision points are found exactly.
#pragma once

#include "poly/bernstein_univariate.hpp"

#include <span>
#include <vector>

namespace hoct {

struct Root {
  double t;         // the root (the midpoint of a cluster)
  double lo, hi;    // an interval containing it; for a simple root it contains no other root
  bool simple;      // certified simple (one sign change, or an exact zero with p' != 0)
  int multiplicity; // 1 if simple; else an upper bound from the sign changes of the cluster
};

struct RootOptions {
  // Intervals narrower than this that still have >= 2 sign changes are reported as a cluster.
  double resolution = 1e-12;
  // Roots (simple or not) closer than this are one non-simple cluster: in floating point they
  // cannot be told from a multiple root (docs/ALGORITHM.md §2: roots closer than 1e-7).
  double cluster_distance = 1e-7;
  // Tangencies: a critical point s of p with |p(s)| <= near_zero * max|coefficient| is reported
  // as a non-simple root even where rounding left no sign change (a double root whose two
  // roots rounding has pushed apart into the complex plane). 0 disables the check.
  double near_zero = 1e-12;
};

// Roots in the closed interval [0, 1], ascending. The zero polynomial has no isolated roots:
// it returns none and sets *identically_zero (if given).
std::vector<Root> find_roots(const BernsteinPoly &p, const RootOptions &options = {},
                             bool *identically_zero = nullptr);
// The same for the polynomial with Bernstein coefficients c, into `roots`
// (cleared first): no allocation once `roots` and the thread's scratch buffers have grown.
void find_roots(std::span<const double> c, std::vector<Root> &roots,
                const RootOptions &options = {}, bool *identically_zero = nullptr);

// True if the Bernstein coefficients c (degree >= 0) keep |p| above the tangency threshold on
// [0, 1]: all above near_zero * max|c|, or all below its negative. find_roots then returns no
// root; callers use it to skip building a polynomial.
bool certainly_rootless(std::span<const double> c, const RootOptions &options = {});
// The same from the coefficients' smallest and largest value and largest magnitude (for callers
// that have them from a pass of their own).
bool certainly_rootless(double lo, double hi, double scale, const RootOptions &options = {});

} // namespace hoct
