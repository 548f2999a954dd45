#include "cell/degenerate_points.hpp"

#include "cell/certified_path.hpp"
#include "poly/interpolation_error.hpp"
#include "poly/lagrange_to_bernstein.hpp"
#include "poly/lattice.hpp"
#include "poly/root_isolation.hpp"
#include "poly/symmetric_eigen2.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace hoct {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

// Half-widths of the excluded square B, tried in turn: the smallest gives the tightest slack;
// larger ones where the gradient around a high-order zero is below the search's resolution.
constexpr double kExclusions[] = {1e-6, 1e-5, 1e-4, 1e-3};
// Classification squares Q: at most this half-width, and each retry a quarter of the last.
constexpr double kLargestSquare = 0.05;
constexpr int kSquareTries = 3;
// The squares' turns (radians), tried in order where a corner lies on the level.
constexpr double kSquareAngles[] = {0.0, 0.3, 0.7};
// More degenerate points than this in one cell: a curve of critical points, not isolated ones.
constexpr std::size_t kMaxClusters = 4;

struct Cluster {
  Vec2 c;
};

double linf(const Vec2 &a, const Vec2 &b) {
  return std::max(std::abs(a[0] - b[0]), std::abs(a[1] - b[1]));
}

// True if g is constant to `tol` along the segment of half-length 1e-2 through c in the
// direction of the Hessian's eigenvalue of least magnitude, with a gradient within 1e3 tol at
// its ends: the tangent of a straight ridge or valley, where g stays at its value. At an isolated
// degenerate zero g varies along every line (at third order or higher). A cheap look before any
// further search (ridges are common).
bool flat_along_null_direction(const BernsteinTriangle &g, const Vec2 &c, double tol) {
  const Mat2 h = g.jet(c[0], c[1]).hessian;
  const double a = h[0][0], b = h[0][1], d = h[1][1];
  if (!(std::abs(a) + std::abs(b) + std::abs(d) > 0))
    return false; // no direction stands out (a monkey saddle); a plane would be constant
  // The eigenvector of the eigenvalue nearer zero: of mean - r if mean >= 0, else of mean + r.
  const SymmetricEigen2 eh = symmetric_eigen2(h);
  const Vec2 e = 0.5 * (a + d) >= 0 ? eh.v_lo : eh.v_hi;
  constexpr double kHalf = 1e-2;
  const BernsteinPoly r = g.restrict_to_segment({c[0] - kHalf * e[0], c[1] - kHalf * e[1]},
                                                {c[0] + kHalf * e[0], c[1] + kHalf * e[1]});
  const double level = g(c[0], c[1]);
  for (double x : r.coefficients())
    if (!(std::abs(x - level) <= tol))
      return false;
  // Constant along the line, and critical along it too (not a zero line of a saddle, where
  // the gradient crosses the line).
  for (double s : {-kHalf, kHalf}) {
    const Vec2 grad = g.jet(c[0] + s * e[0], c[1] + s * e[1]).gradient;
    if (!(std::hypot(grad[0], grad[1]) <= 1e3 * tol))
      return false;
  }
  return true;
}

// A certified bound on |g - level| over the square of half-width rho around c: the largest
// Bernstein coefficient of g - level on a triangle holding the square (from g's values at the
// triangle's lattice points), plus the rounding of those values through the conversion.
double slack_on_square(const BernsteinTriangle &g, const Vec2 &c, double rho, double level,
                       double rounding) {
  const int d = g.degree();
  const Vec2 a = {c[0] - rho, c[1] - rho};
  const double side = 4 * rho; // the hypotenuse passes through the square's corner (rho, rho)
  std::vector<double> values(static_cast<std::size_t>(lattice_size(d))), coef(values.size());
  for (int b = 0; b <= d; ++b)
    for (int i = 0; i + b <= d; ++i)
      values[static_cast<std::size_t>(lattice_index(d, i, b))] =
          g(a[0] + side * i / d, a[1] + side * b / d) - level;
  bernstein_from_lattice_values(values.data(), d, coef.data());
  double m = 0;
  for (double x : coef)
    m = std::max(m, std::abs(x));
  return m + (lagrange_to_bernstein_norm(d) + 1) * rounding;
}

} // namespace

Vec2 polish_zero(const BernsteinTriangle &g, Vec2 c, const Vec2 &around, double reach,
                 double null_ratio) {
  BernsteinTriangle::Jet j = g.jet(c[0], c[1]);
  double gn = std::hypot(j.gradient[0], j.gradient[1]);
  for (int it = 0; it < 100 && gn > 0; ++it) {
    const SymmetricEigen2 eh = symmetric_eigen2(j.hessian);
    const double l[2] = {eh.lo, eh.hi};
    const Vec2 e[2] = {eh.v_lo, eh.v_hi};
    const double lmax = std::max(std::abs(l[0]), std::abs(l[1]));
    Vec2 step{0, 0};
    for (int k = 0; k < 2; ++k)
      if (std::abs(l[k]) > null_ratio * lmax) {
        const double s = (e[k][0] * j.gradient[0] + e[k][1] * j.gradient[1]) / l[k];
        step[0] -= s * e[k][0];
        step[1] -= s * e[k][1];
      }
    const Vec2 next = {c[0] + step[0], c[1] + step[1]};
    if (linf(next, around) > reach)
      break;
    const BernsteinTriangle::Jet jn = g.jet(next[0], next[1]);
    const double nn = std::hypot(jn.gradient[0], jn.gradient[1]);
    if (!(nn < gn))
      break;
    c = next;
    j = jn;
    gn = nn;
  }
  return c;
}

int certify_ray(const BernsteinTriangle &g, const Vec2 &c, const Vec2 &p, double level,
                double margin, double tol) {
  const BernsteinPoly r = g.restrict_to_segment(c, p);
  const int d = r.degree();
  int m = 1;
  while (m <= d && std::abs(r[m] - level) <= tol)
    ++m;
  if (m > d)
    return -1;
  const double thr = level - margin;
  for (double tau = 1; tau >= 1.0 / 256; tau *= 0.5) {
    const Vec2 x = {c[0] + tau * (p[0] - c[0]), c[1] + tau * (p[1] - c[1])};
    if (certify_below(g, c, x, thr, m) && (tau == 1 || certify_below(g, x, p, thr, 0)))
      return m;
  }
  return -1;
}

namespace {

// What the classifications need of g: its coefficient scale, the paths' margin (as
// PathField's), the rounding level of its values, and -g for ascending rays.
struct Classifier {
  explicit Classifier(const BernsteinTriangle &g) : neg(g.degree(), g.coefficients()) {
    for (double &x : neg.coefficients()) {
      scale = std::max(scale, std::abs(x));
      x = -x;
    }
    margin = 1e-12 * scale;
    rounding = 64 * (g.degree() + 1) * kEps * scale;
  }
  double scale = 0, margin = 0, rounding = 0;
  BernsteinTriangle neg;
};

// Removes the zeros inside the squares (centre u, v and half-width): the clusters' own.
void drop_inside(GradientZeros &z, const std::vector<std::array<double, 3>> &squares) {
  std::erase_if(z.zeros, [&](const GradientZero &p) {
    for (const auto &sq : squares)
      if (std::abs(p.u - sq[0]) <= sq[2] && std::abs(p.v - sq[1]) <= sq[2])
        return true;
    return false;
  });
}

// Each sign arc's ray, certified below (above) the level: the node's sectors, or false.
bool classify_on_square(const BernsteinTriangle &g, const BernsteinTriangle &neg, const Vec2 &c,
                        double level, double r, double angle, double margin, double tol,
                        SectorRays &out) {
  out = {};
  thread_local std::vector<SignArc> arcs;
  if (!sign_arcs_on_square(g, c, r, level, tol, arcs, angle))
    return false;
  for (const SignArc &a : arcs) {
    const int skip = a.lower ? certify_ray(g, c, a.point, level, margin, tol)
                             : certify_ray(neg, c, a.point, -level, margin, tol);
    if (skip < 0)
      return false;
    (a.lower ? out.lower : out.upper).push_back(a.point);
    (a.lower ? out.lower_skip : out.upper_skip).push_back(skip);
  }
  return true;
}

} // namespace

bool sign_arcs_on_polyline(const BernsteinTriangle &g, std::span<const Vec2> q, bool closed,
                           double level, double tol, std::vector<SignArc> &arcs) {
  arcs.clear();
  const int sides = static_cast<int>(q.size()) - (closed ? 0 : 1);
  if (sides < 1)
    return false;
  auto at = [&](double s) { // parameter s in [0, sides]: side floor(s), from its first point
    const int k = std::clamp(static_cast<int>(s), 0, sides - 1);
    const double t = s - k;
    const Vec2 &a = q[k], &b = q[(k + 1) % q.size()];
    return Vec2{a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])};
  };
  std::vector<double> roots; // polyline parameters, ascending
  thread_local std::vector<Root> side_roots;
  for (int k = 0; k < sides; ++k) {
    BernsteinPoly side = g.restrict_to_segment(q[k], q[(k + 1) % q.size()]);
    for (double &x : side.coefficients())
      x -= level;
    if (!(std::abs(side[0]) > tol) || !(std::abs(side[side.degree()]) > tol))
      return false; // a corner on (or too near) the level
    bool zero = false;
    find_roots(side.coefficients(), side_roots, RootOptions{}, &zero);
    if (zero)
      return false;
    for (const Root &root : side_roots) {
      if (!root.simple || root.t <= 0 || root.t >= 1)
        return false;
      roots.push_back(k + root.t);
    }
  }
  // The arcs between consecutive roots (cyclically on a closed polyline); with no root, the
  // whole polyline.
  const std::size_t n = roots.size();
  if (closed && n % 2 != 0)
    return false; // simple roots alternate the sign: an odd count means a miscount
  const std::size_t count = closed ? std::max<std::size_t>(n, 1) : n + 1;
  for (std::size_t i = 0; i < count; ++i) {
    double a, b;
    if (closed) {
      a = n ? roots[i] : 0.0;
      b = n ? (i + 1 < n ? roots[i + 1] : roots[0] + sides) : sides;
    } else {
      a = i == 0 ? 0.0 : roots[i - 1];
      b = i == n ? sides : roots[i];
    }
    constexpr int kSamples = 24;
    Vec2 best{};
    double best_h = 0;
    for (int k = 1; k < kSamples; ++k) {
      double x = a + (b - a) * k / kSamples;
      if (closed && x >= sides)
        x -= sides;
      const Vec2 p = at(x);
      const double h = g(p[0], p[1]) - level;
      if (std::abs(h) > std::abs(best_h))
        best_h = h, best = p;
    }
    if (!(std::abs(best_h) > tol))
      return false;
    arcs.push_back({best_h < 0, best});
  }
  return true;
}

bool sign_arcs_on_square(const BernsteinTriangle &g, const Vec2 &c, double r, double level,
                         double tol, std::vector<SignArc> &arcs, double angle) {
  const double co = std::cos(angle), si = std::sin(angle);
  std::array<Vec2, 4> q;
  const double corner[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  for (int k = 0; k < 4; ++k)
    q[k] = {c[0] + r * (co * corner[k][0] - si * corner[k][1]),
            c[1] + r * (si * corner[k][0] + co * corner[k][1])};
  return sign_arcs_on_polyline(g, q, true, level, tol, arcs);
}

static std::vector<Vec2> degenerate_candidates(const GradientZeros &z) {
  std::vector<Vec2> c;
  for (const GradientZero &p : z.zeros)
    if (!p.certified)
      c.push_back({p.u, p.v});
  if (c.empty() && z.stopped_at)
    c.push_back(*z.stopped_at);
  return c;
}

DegenerateResolution resolve_degenerate_zeros(const BernsteinTriangle &g,
                                              const GradientZeros &first,
                                              const GradientZeroOptions &options,
                                              double value_noise) {
  if (first.constant)
    return {};
  return resolve_degenerate_zeros(g, degenerate_candidates(first), options, value_noise);
}

DegenerateResolution resolve_degenerate_zeros(const BernsteinTriangle &g,
                                              std::span<const Vec2> candidates,
                                              const GradientZeroOptions &options,
                                              double value_noise) {
  DegenerateResolution out;
  std::vector<Cluster> clusters;
  for (const Vec2 &c : candidates)
    clusters.push_back({c});
  auto add_unresolved = [&](const GradientZeros &z, double apart) {
    for (const GradientZero &p : z.zeros)
      if (!p.certified) {
        const Vec2 c{p.u, p.v};
        bool known = false;
        for (const Cluster &k : clusters)
          known = known || linf(k.c, c) <= apart;
        if (!known)
          clusters.push_back({c});
      }
  };
  if (clusters.empty())
    return out;
  const Classifier f(g);
  if (!(f.scale > 0))
    return out;
  const double margin = f.margin, rounding = f.rounding;
  const BernsteinTriangle &neg = f.neg;
  for (Cluster &k : clusters) {
    k.c = polish_zero(g, k.c, k.c, 1e-4);
    if (flat_along_null_direction(g, k.c, rounding + value_noise))
      return out; // a ridge or valley (a curve of critical points): not isolated
  }

  // The search with a square of half-width rho excluded around each cluster.
  auto search = [&](double rho, GradientZeros &z) {
    GradientZeroOptions opt = options;
    opt.excluded.clear();
    // Outside squares of 1e-3 an isolated zero's neighbourhood resolves with boxes far wider
    // than deep_width: a few deep boxes already mean a curve, found without going on.
    if (rho >= 1e-3)
      opt.deep_limit = std::min<int64_t>(opt.deep_limit, 4);
    for (const Cluster &k : clusters) {
      const Vec2 &c = k.c;
      if (!(c[0] - rho > 0 && c[1] - rho > 0 && c[0] + c[1] + 2 * rho < 1))
        return false; // at the cell's boundary: the caller falls back
      opt.excluded.push_back({c[0], c[1], rho});
    }
    z = find_gradient_zeros(g, opt);
    drop_inside(z, opt.excluded); // certified before the search reached the square: the cluster's
    return !z.constant;
  };
  // Each cluster classified on a square that holds no other zero and stays inside the cell,
  // every zero outside the squares of half-width rho being certified (z).
  auto classify = [&](double rho, const GradientZeros &z) {
    DegenerateResolution res;
    res.zeros = z.zeros;
    for (const Cluster &k : clusters) {
      const Vec2 &c = k.c;
      double r0 = std::min({kLargestSquare, 0.5 * c[0], 0.5 * c[1], 0.25 * (1 - c[0] - c[1])});
      for (const GradientZero &p : z.zeros)
        r0 = std::min(r0, 0.5 * (linf(c, {p.u, p.v}) - p.radius));
      for (const Cluster &o : clusters)
        if (&o != &k)
          r0 = std::min(r0, 0.5 * (linf(c, o.c) - rho));
      const BernsteinTriangle::Jet jet = g.jet(c[0], c[1]);
      DegenerateCritical point;
      point.uv = c;
      point.value = jet.value;
      point.radius = rho;
      // Leading ray coefficients within `tol` of the value are skipped: a ray may dip that far
      // to the wrong side next to the node, so that is the node's slack as well.
      const double tol =
          4 * rounding + 2 * value_noise + 2 * slack_on_square(g, c, rho, jet.value, rounding);
      point.slack = tol;
      bool classified = false;
      for (int t = 0; t < kSquareTries && !classified; ++t) {
        const double r = r0 / std::pow(4.0, t);
        if (!(r >= 4 * rho))
          break;
        // Turned where a zero line of g - g(c) runs through a corner (a symmetric field along
        // a diagonal of the reference square): the turned square reaches r sqrt 2 at most.
        for (double angle : kSquareAngles)
          if (!classified && (angle == 0 || r * std::sqrt(2.0) <= r0))
            classified =
                classify_on_square(g, neg, c, point.value, r, angle, margin, tol, point.rays);
      }
      if (!classified)
        return DegenerateResolution{};
      res.slack = std::max(res.slack, point.slack);
      if (point.rays.lower.size() == 1 && point.rays.upper.size() == 1)
        ++res.regular; // a regular point: no node
      else
        res.points.push_back(std::move(point));
    }
    res.resolved = true;
    return res;
  };

  // First the largest squares: there every isolated zero of moderate order is resolved around
  // them, so a search that still runs out of boxes means a curve of critical points (give up at
  // once: ridges are common, and each attempt costs a search); unresolved zeros away from every
  // square are further degenerate points, clusters of their own. Clusters closer than a few
  // squares apart are one (the data's rounding scatters the zeros of a degenerate point).
  const double largest = kExclusions[std::size(kExclusions) - 1];
  std::vector<Cluster> merged;
  for (const Cluster &k : clusters) {
    bool near = false;
    for (const Cluster &m : merged)
      near = near || linf(k.c, m.c) <= 4 * largest;
    if (!near)
      merged.push_back(k);
  }
  clusters.swap(merged);
  GradientZeros z;
  for (int round = 0;; ++round) {
    if (round == 3 || !search(largest, z) || z.budget_exhausted)
      return out;
    if (z.unresolved == 0)
      break;
    const std::size_t before = clusters.size();
    add_unresolved(z, 4 * largest);
    if (clusters.size() == before || clusters.size() > kMaxClusters)
      return out;
    for (std::size_t i = before; i < clusters.size(); ++i)
      clusters[i].c = polish_zero(g, clusters[i].c, clusters[i].c, 1e-4);
  }
  DegenerateResolution at_largest = classify(largest, z);
  // Then smaller squares, for a smaller slack: the first that resolves and classifies.
  for (double rho : kExclusions) {
    if (rho == largest)
      break;
    GradientZeros zr;
    if (!search(rho, zr) || zr.budget_exhausted || zr.unresolved > 0)
      continue;
    DegenerateResolution res = classify(rho, zr);
    if (res.resolved)
      return res;
  }
  return at_largest;
}

std::optional<SectorRays> classify_corner(const BernsteinTriangle &g, const BernsteinTriangle &neg,
                                          int k, double r0, double min_r, double tol,
                                          double margin) {
  const Vec2 corner[3] = {{0, 0}, {1, 0}, {0, 1}};
  const Vec2 &v = corner[k], &next = corner[(k + 1) % 3], &prev = corner[(k + 2) % 3];
  const double level = g.coefficient(k == 1 ? g.degree() : 0, k == 2 ? g.degree() : 0);
  thread_local std::vector<SignArc> arcs;
  for (int t = 0; t < kSquareTries; ++t) {
    const double r = r0 / std::pow(4.0, t);
    if (!(r >= min_r))
      break;
    const std::array<Vec2, 2> side = {
        Vec2{v[0] + r * (next[0] - v[0]), v[1] + r * (next[1] - v[1])},
        Vec2{v[0] + r * (prev[0] - v[0]), v[1] + r * (prev[1] - v[1])}};
    if (!sign_arcs_on_polyline(g, side, false, level, tol, arcs))
      continue;
    SectorRays rays;
    bool classified = true;
    // The first and last arcs go on along the edges (their chains); the others are inside.
    for (std::size_t i = 1; i + 1 < arcs.size() && classified; ++i) {
      const SignArc &a = arcs[i];
      const int skip = a.lower ? certify_ray(g, v, a.point, level, margin, tol)
                               : certify_ray(neg, v, a.point, -level, margin, tol);
      classified = skip >= 0;
      (a.lower ? rays.lower : rays.upper).push_back(a.point);
      (a.lower ? rays.lower_skip : rays.upper_skip).push_back(skip);
    }
    if (classified)
      return rays;
  }
  return std::nullopt;
}

CornerResolution resolve_critical_corners(const BernsteinTriangle &g,
                                          const std::array<bool, 3> &critical,
                                          const std::array<double, 3> &reach,
                                          const GradientZeroOptions &options, bool search,
                                          double value_noise) {
  CornerResolution out;
  const Classifier f(g);
  if (!(f.scale > 0))
    return out;
  const double margin = f.margin, rounding = f.rounding;
  const BernsteinTriangle &neg = f.neg;
  const Vec2 corner[3] = {{0, 0}, {1, 0}, {0, 1}};
  const double hessian = InterpolationError(g).hessian_bound();
  for (double rho : kExclusions) {
    GradientZeros z;
    if (search) {
      GradientZeroOptions opt = options;
      opt.excluded.clear();
      for (int k = 0; k < 3; ++k)
        if (critical[k])
          opt.excluded.push_back({corner[k][0], corner[k][1], rho});
      if (rho >= 1e-3)
        opt.deep_limit = std::min<int64_t>(opt.deep_limit, 4);
      z = find_gradient_zeros(g, opt);
      if (z.constant)
        return out;
      if (z.budget_exhausted || z.unresolved > 0)
        continue;
      // A zero the search certified before reaching a square, inside it, is the corner's own.
      drop_inside(z, opt.excluded);
      bool near = false;
      for (const GradientZero &p : z.zeros)
        near = near || p.near_boundary;
      if (near)
        return out; // a zero on the cell's boundary elsewhere: the caller falls back
    }
    CornerResolution res;
    res.zeros = z.zeros;
    bool ok = true;
    for (int k = 0; k < 3 && ok; ++k) {
      if (!critical[k])
        continue;
      const Vec2 &v = corner[k];
      double r0 = std::min(reach[k], 0.25);
      for (const GradientZero &p : z.zeros)
        r0 = std::min(r0, 0.5 * (linf(v, {p.u, p.v}) - p.radius));
      const double level = g.coefficient(k == 1 ? g.degree() : 0, k == 2 ? g.degree() : 0);
      // Where the gradient at the corner exceeds what the Hessian can cancel within B, B holds
      // no zero and the corner stands for nothing but itself (its gradient is orthogonal to an
      // edge there, not zero).
      const Vec2 grad = g.jet(v[0], v[1]).gradient;
      const bool zero_free = std::hypot(grad[0], grad[1]) > 2 * std::sqrt(2.0) * hessian * rho;
      const double tol = 4 * rounding + 2 * value_noise +
                         (zero_free ? 0.0 : 2 * slack_on_square(g, v, rho, level, rounding));
      std::optional<SectorRays> rays = classify_corner(g, neg, k, r0, 4 * rho, tol, margin);
      if (!rays) {
        ok = false;
        break;
      }
      res.corners[k] = std::move(*rays);
      res.slack = std::max(res.slack, tol);
    }
    if (ok) {
      res.resolved = true;
      return res;
    }
    if (!search)
      return out; // the exclusion does not matter: nothing else to try
  }
  return out;
}

} // namespace hoct
