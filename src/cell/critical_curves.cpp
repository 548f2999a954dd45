#include "cell/critical_curves.hpp"

#include "poly/symmetric_eigen2.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>

namespace hoct {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();
constexpr int kFirstGrid = 8; // the first boxes: an 8 x 8 grid over the unit square
constexpr int kMaxDepth = 12; // splits below it: boxes down to 1 / 32768
constexpr int kRegionGrids[] = {8, 16, 32, 64}; // Q's grids, coarsest first
// Slabs closer than this (reference units) meet; a boundary point this close to a slab is on it.
constexpr double kTouch = 1e-12;
constexpr double kOnCurve = 1e-9;
// A slab's half-width that holds its whole box (see examine).
constexpr double kWholeBox = 1e300;
constexpr std::size_t kRayTries = 6; // anchors tried per ray, nearest first

// What the box test needs of g beyond its value at a point: the third-derivative bound and the
// rounding of the jet's value, gradient and Hessian.
struct Model {
  double k3 = 0, dval = 0, dgrad = 0, dhess = 0;
};

double largest_abs(const BernsteinTriangle &p) {
  double m = 0;
  for (double x : p.coefficients())
    m = std::max(m, std::abs(x));
  return m;
}

// `noise`: how far the values may be off (the data's precision): the gradient and Hessian of a
// polynomial that close to g are what the boxes must allow for, so that a ridge the data's
// rounding tilted by less than its precision is still one curve.
Model model_of(const BernsteinTriangle &g, double scale, double noise) {
  Model m;
  const int d = g.degree();
  if (d >= 3) {
    const BernsteinTriangle gu = g.du(), gv = g.dv();
    const BernsteinTriangle guu = gu.du(), guv = gu.dv(), gvv = gv.dv();
    // |D3 g [a, b, c]| <= max |third partials| |a|_1 |b|_1 |c|_1 <= that 2 sqrt 2 |a| |b| |c|.
    m.k3 = 2 * std::sqrt(2.0) *
           std::max({largest_abs(guu.du()), largest_abs(guu.dv()), largest_abs(guv.dv()),
                     largest_abs(gvv.dv())});
  }
  m.dval = 64 * (d + 1) * kEps * scale + noise;
  m.dgrad = 4 * d * m.dval;
  m.dhess = 16 * d * d * m.dval;
  return m;
}

// A box of the cover with a slab: its zeros lie where |n.(y - c) - w0| <= eps, and there
// |g - value| <= bound.
struct SlabBox {
  Vec2 c;
  double r;
  Vec2 n;
  double w0, eps, value, bound;
};

enum class Verdict { kNoZero, kSlab, kSplit };

Verdict examine(const BernsteinTriangle &g, const Model &m, double target, const Vec2 &c, double r,
                SlabBox &out) {
  const BernsteinTriangle::Jet j = g.jet(c[0], c[1]);
  const double rho = r * std::sqrt(2.0);
  // The gradient's remainder past its linear model over the box, with the rounding of both.
  const double rg = 0.5 * m.k3 * rho * rho + m.dhess * rho + m.dgrad;
  const double a = j.hessian[0][0], b = j.hessian[0][1], d = j.hessian[1][1];
  // First without the eigenvectors (most boxes): |grad g(x)| <= |H| rho + rg at a zero.
  if (std::hypot(j.gradient[0], j.gradient[1]) > std::sqrt(a * a + 2 * b * b + d * d) * rho + rg)
    return Verdict::kNoZero;
  const SymmetricEigen2 eh = symmetric_eigen2(j.hessian);
  const bool hi_first = std::abs(eh.hi) >= std::abs(eh.lo);
  const double lambda = eh.larger(), mu = eh.smaller();
  const Vec2 n = hi_first ? eh.v_hi : eh.v_lo, t = hi_first ? eh.v_lo : eh.v_hi;
  const double gn = n[0] * j.gradient[0] + n[1] * j.gradient[1];
  const double gt = t[0] * j.gradient[0] + t[1] * j.gradient[1];
  // How far the box reaches along n and t from its centre.
  const double reach_n = r * (std::abs(n[0]) + std::abs(n[1]));
  const double reach_t = r * (std::abs(t[0]) + std::abs(t[1]));
  if (std::abs(gn) > std::abs(lambda) * reach_n + rg || std::abs(gt) > std::abs(mu) * reach_t + rg)
    return Verdict::kNoZero;
  const double common =
      m.k3 * rho * rho * rho / 6 + 0.5 * m.dhess * rho * rho + m.dgrad * rho + m.dval;
  // Where g varies little over the whole box (next to a point where the Hessian vanishes too,
  // on the curve or isolated), the whole box is the slab: it then meets every neighbour's.
  const double blob = std::hypot(gn, gt) * rho + 0.5 * std::abs(lambda) * rho * rho + common;
  if (blob <= target) {
    out = {c, r, n, 0, kWholeBox, j.value, blob};
    return Verdict::kSlab;
  }
  if (!(std::abs(lambda) > 0))
    return Verdict::kSplit;
  const double w0 = -gn / lambda, eps = rg / std::abs(lambda);
  const double bound = rho * std::abs(gt) + 0.5 * std::abs(mu) * rho * rho +
                       0.5 * std::abs(lambda) * eps * eps + common;
  out = {c, r, n, w0, eps, j.value - 0.5 * lambda * w0 * w0, bound};
  return bound <= target ? Verdict::kSlab : Verdict::kSplit;
}

// The slab's parameter interval on the segment p + s (q - p), s in [0, 1] (empty: lo > hi).
void slab_interval(const SlabBox &b, const Vec2 &p, const Vec2 &q, double &lo, double &hi) {
  const double f0 = b.n[0] * (p[0] - b.c[0]) + b.n[1] * (p[1] - b.c[1]) - b.w0;
  const double f1 = b.n[0] * (q[0] - p[0]) + b.n[1] * (q[1] - p[1]);
  const double w = b.eps + kTouch;
  if (std::abs(f1) <= 1e-300) {
    lo = std::abs(f0) <= w ? 0.0 : 1.0;
    hi = std::abs(f0) <= w ? 1.0 : 0.0;
    return;
  }
  double s0 = (-w - f0) / f1, s1 = (w - f0) / f1;
  if (s0 > s1)
    std::swap(s0, s1);
  lo = std::max(0.0, s0);
  hi = std::min(1.0, s1);
}

// True if the slabs of two touching boxes meet on their common side (or corner).
bool slabs_meet(const SlabBox &a, const SlabBox &b) {
  const double x0 = std::max(a.c[0] - a.r, b.c[0] - b.r), x1 = std::min(a.c[0] + a.r, b.c[0] + b.r);
  const double y0 = std::max(a.c[1] - a.r, b.c[1] - b.r), y1 = std::min(a.c[1] + a.r, b.c[1] + b.r);
  if (x0 > x1 + kTouch || y0 > y1 + kTouch)
    return false;
  const Vec2 p = {x0, y0}, q = {std::max(x0, x1), std::max(y0, y1)};
  double alo, ahi, blo, bhi;
  slab_interval(a, p, q, alo, ahi);
  slab_interval(b, p, q, blo, bhi);
  return std::max(alo, blo) <= std::min(ahi, bhi);
}

bool in_box(const SlabBox &b, const Vec2 &p, double tol) {
  return std::abs(p[0] - b.c[0]) <= b.r + tol && std::abs(p[1] - b.c[1]) <= b.r + tol;
}

bool on_slab(const SlabBox &b, const Vec2 &p) {
  return in_box(b, p, kTouch) &&
         std::abs(b.n[0] * (p[0] - b.c[0]) + b.n[1] * (p[1] - b.c[1]) - b.w0) <= b.eps + kOnCurve;
}

// A point of the box's slab in the closed reference triangle (where the cell's zeros are): the
// middle of its centre line's chord through box and triangle, else the nearest corner of that
// polygon within the slab; false if the slab misses the triangle.
bool slab_point(const SlabBox &b, Vec2 &out) {
  // The box clipped by u >= 0, v >= 0 and u + v <= 1 (each as a . y <= c): at most 7 corners.
  struct Polygon {
    std::array<Vec2, 8> p;
    std::size_t n = 0;
    std::size_t size() const { return n; }
    const Vec2 &operator[](std::size_t i) const { return p[i]; }
    void push_back(const Vec2 &x) { p[n++] = x; }
  };
  Polygon poly;
  poly.push_back({b.c[0] - b.r, b.c[1] - b.r});
  poly.push_back({b.c[0] + b.r, b.c[1] - b.r});
  poly.push_back({b.c[0] + b.r, b.c[1] + b.r});
  poly.push_back({b.c[0] - b.r, b.c[1] + b.r});
  const double planes[3][3] = {{-1, 0, 0}, {0, -1, 0}, {1, 1, 1}};
  for (const auto &pl : planes) {
    Polygon next;
    for (std::size_t i = 0; i < poly.size(); ++i) {
      const Vec2 &p = poly[i], &q = poly[(i + 1) % poly.size()];
      const double fp = pl[0] * p[0] + pl[1] * p[1] - pl[2],
                   fq = pl[0] * q[0] + pl[1] * q[1] - pl[2];
      if (fp <= 0)
        next.push_back(p);
      if ((fp < 0 && fq > 0) || (fp > 0 && fq < 0)) {
        const double s = fp / (fp - fq);
        next.push_back({p[0] + s * (q[0] - p[0]), p[1] + s * (q[1] - p[1])});
      }
    }
    poly = next;
    if (poly.size() == 0)
      return false;
  }
  auto f = [&](const Vec2 &p) {
    return b.n[0] * (p[0] - b.c[0]) + b.n[1] * (p[1] - b.c[1]) - b.w0;
  };
  Vec2 sum{0, 0};
  int crossings = 0;
  std::size_t nearest = 0;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const Vec2 &p = poly[i], &q = poly[(i + 1) % poly.size()];
    const double fp = f(p), fq = f(q);
    if (std::abs(fp) < std::abs(f(poly[nearest])))
      nearest = i;
    if ((fp <= 0 && fq > 0) || (fp > 0 && fq <= 0)) {
      const double s = fp / (fp - fq);
      sum = {sum[0] + p[0] + s * (q[0] - p[0]), sum[1] + p[1] + s * (q[1] - p[1])};
      ++crossings;
    }
  }
  if (crossings > 0) {
    out = {sum[0] / crossings, sum[1] / crossings};
    return true;
  }
  out = poly[nearest];
  return std::abs(f(out)) <= b.eps + kTouch;
}

// A value of g on the curve: Newton steps (the Hessian's null direction dropped) from the box's
// slab onto the zeros, where g is constant; the box's estimate if they do not converge. Any value
// is sound (the slack is measured from it); this one is the same to rounding in every cell the
// curve crosses, so that their nodes merge as one flat region.
double on_curve_value(const BernsteinTriangle &g, const SlabBox &b) {
  const Vec2 start = {std::clamp(b.c[0] + b.w0 * b.n[0], b.c[0] - b.r, b.c[0] + b.r),
                      std::clamp(b.c[1] + b.w0 * b.n[1], b.c[1] - b.r, b.c[1] + b.r)};
  const Vec2 x = polish_zero(g, start, b.c, 3 * b.r, 1e-6);
  const double v = g(x[0], x[1]);
  return std::abs(v - b.value) <= b.bound ? v : b.value;
}

int find(std::vector<int> &parent, int i) {
  while (parent[i] != i)
    i = parent[i] = parent[parent[i]];
  return i;
}

// The polylines of the boundary of a union of grid squares (grid n x n over the unit square, the
// squares (i, j) with i + j < n: those meeting the reference triangle's interior) that lie inside
// the triangle: closed loops, or open runs from the triangle's boundary to its boundary.
struct Polyline {
  std::vector<Vec2> points;
  bool closed;
};

std::vector<Polyline> region_boundary(const std::vector<char> &in, int n) {
  auto inside = [&](int i, int j) {
    return i >= 0 && j >= 0 && i < n && j < n && in[static_cast<std::size_t>(i * n + j)];
  };
  // Directed sides with the region on their left, from vertex (i, j) (id i (n + 1) + j).
  struct Side {
    int i0, j0, i1, j1;
    bool used;
  };
  std::vector<Side> sides;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      if (inside(i, j)) {
        if (!inside(i, j - 1))
          sides.push_back({i, j, i + 1, j, false});
        if (!inside(i + 1, j))
          sides.push_back({i + 1, j, i + 1, j + 1, false});
        if (!inside(i, j + 1))
          sides.push_back({i + 1, j + 1, i, j + 1, false});
        if (!inside(i - 1, j))
          sides.push_back({i, j + 1, i, j, false});
      }
  const int nv = (n + 1) * (n + 1);
  std::vector<std::array<int, 2>> out_of(static_cast<std::size_t>(nv), {-1, -1});
  for (std::size_t k = 0; k < sides.size(); ++k) {
    auto &o = out_of[static_cast<std::size_t>(sides[k].i0 * (n + 1) + sides[k].j0)];
    (o[0] < 0 ? o[0] : o[1]) = static_cast<int>(k);
  }
  // A side is kept if it lies inside the closed triangle and not on its legs u = 0, v = 0.
  auto kept = [&](const Side &s) {
    if (s.i0 + s.j0 > n || s.i1 + s.j1 > n)
      return false;
    return !(s.i0 == 0 && s.i1 == 0) && !(s.j0 == 0 && s.j1 == 0);
  };
  std::vector<Polyline> lines;
  for (std::size_t start = 0; start < sides.size(); ++start) {
    if (sides[start].used)
      continue;
    std::vector<int> loop;
    int k = static_cast<int>(start);
    while (k >= 0 && !sides[static_cast<std::size_t>(k)].used) {
      Side &s = sides[static_cast<std::size_t>(k)];
      s.used = true;
      loop.push_back(k);
      const auto &o = out_of[static_cast<std::size_t>(s.i1 * (n + 1) + s.j1)];
      const int dx = s.i1 - s.i0, dy = s.j1 - s.j0;
      int next = -1;
      // At a vertex two squares touch only diagonally: turn left, keeping each loop tight.
      for (int c : o)
        if (c >= 0 && !sides[static_cast<std::size_t>(c)].used) {
          const Side &t = sides[static_cast<std::size_t>(c)];
          const bool left = (t.i1 - t.i0) == -dy && (t.j1 - t.j0) == dx;
          if (next < 0 || left)
            next = c;
        }
      k = next;
    }
    // Runs of kept sides, cyclically.
    const std::size_t m = loop.size();
    std::size_t first_dropped = m;
    for (std::size_t i = 0; i < m; ++i)
      if (!kept(sides[static_cast<std::size_t>(loop[i])])) {
        first_dropped = i;
        break;
      }
    auto point = [&](int i, int j) {
      return Vec2{static_cast<double>(i) / n, static_cast<double>(j) / n};
    };
    if (first_dropped == m) {
      Polyline p{{}, true};
      for (int id : loop)
        p.points.push_back(
            point(sides[static_cast<std::size_t>(id)].i0, sides[static_cast<std::size_t>(id)].j0));
      lines.push_back(std::move(p));
      continue;
    }
    Polyline run{{}, false};
    for (std::size_t step = 1; step <= m; ++step) {
      const Side &s = sides[static_cast<std::size_t>(loop[(first_dropped + step) % m])];
      if (kept(s)) {
        if (run.points.empty())
          run.points.push_back(point(s.i0, s.j0));
        run.points.push_back(point(s.i1, s.j1));
      } else if (!run.points.empty()) {
        lines.push_back(std::move(run));
        run = {{}, false};
      }
    }
    if (!run.points.empty())
      lines.push_back(std::move(run));
  }
  return lines;
}

} // namespace

CurveResolution resolve_critical_curves(const BernsteinTriangle &g,
                                        std::span<const Vec2> boundary_points, double value_noise,
                                        const std::array<bool, 3> &corners,
                                        const std::array<double, 3> &corner_reach,
                                        int64_t max_boxes) {
  CurveResolution out;
  const int d = g.degree();
  if (d < 2)
    return out;
  double scale = 0, lo = INFINITY, hi = -INFINITY;
  for (double x : g.coefficients()) {
    scale = std::max(scale, std::abs(x));
    lo = std::min(lo, x);
    hi = std::max(hi, x);
  }
  if (!(hi > lo))
    return out;
  const Model m = model_of(g, scale, value_noise);
  const double variation = hi - lo;
  const double target = std::max(1e-8 * variation, 16 * m.dval);
  const double curve_limit = std::max(1e-7 * variation, 64 * m.dval);

  // 1. The cover.
  std::vector<SlabBox> boxes;
  struct Pending {
    Vec2 c;
    double r;
    int depth;
  };
  std::vector<Pending> stack;
  for (int i = 0; i < kFirstGrid; ++i)
    for (int j = 0; i + j < kFirstGrid; ++j)
      stack.push_back({{(i + 0.5) / kFirstGrid, (j + 0.5) / kFirstGrid}, 0.5 / kFirstGrid, 0});
  while (!stack.empty()) {
    const Pending p = stack.back();
    stack.pop_back();
    if (++out.boxes > max_boxes)
      return out;
    SlabBox b;
    switch (examine(g, m, target, p.c, p.r, b)) {
    case Verdict::kNoZero:
      break;
    case Verdict::kSlab:
      boxes.push_back(b);
      break;
    case Verdict::kSplit:
      if (p.depth == kMaxDepth)
        return out;
      for (int k = 0; k < 4; ++k) {
        const double h = 0.5 * p.r;
        const Vec2 c = {p.c[0] + (k & 1 ? h : -h), p.c[1] + (k & 2 ? h : -h)};
        if ((c[0] - h) + (c[1] - h) < 1)
          stack.push_back({c, h, p.depth + 1});
      }
    }
  }
  if (boxes.empty())
    return out; // no zero at all: not this method's cell

  // 2. Curves: slabs that meet, through a hash of the first grid's squares.
  const int nb = static_cast<int>(boxes.size());
  std::vector<int> parent(static_cast<std::size_t>(nb));
  for (int i = 0; i < nb; ++i)
    parent[static_cast<std::size_t>(i)] = i;
  std::vector<std::vector<int>> bucket(kFirstGrid * kFirstGrid);
  auto cell_of = [](double x) {
    return std::clamp(static_cast<int>(x * kFirstGrid), 0, kFirstGrid - 1);
  };
  for (int i = 0; i < nb; ++i)
    bucket[static_cast<std::size_t>(cell_of(boxes[static_cast<std::size_t>(i)].c[0]) * kFirstGrid +
                                    cell_of(boxes[static_cast<std::size_t>(i)].c[1]))]
        .push_back(i);
  for (int i = 0; i < nb; ++i) {
    const SlabBox &a = boxes[static_cast<std::size_t>(i)];
    const int bx = cell_of(a.c[0]), by = cell_of(a.c[1]);
    for (int x = std::max(bx - 1, 0); x <= std::min(bx + 1, kFirstGrid - 1); ++x)
      for (int y = std::max(by - 1, 0); y <= std::min(by + 1, kFirstGrid - 1); ++y)
        for (int j : bucket[static_cast<std::size_t>(x * kFirstGrid + y)])
          if (j > i && slabs_meet(a, boxes[static_cast<std::size_t>(j)]))
            parent[static_cast<std::size_t>(find(parent, i))] = find(parent, j);
  }
  // Curves whose slabs all miss the triangle (a ridge just beyond the cell, met by boxes that
  // straddle its boundary) hold no zero of the cell: dropped.
  std::vector<char> inside(static_cast<std::size_t>(nb), 0);
  std::vector<Vec2> anchor(static_cast<std::size_t>(nb));
  std::vector<char> has_anchor(static_cast<std::size_t>(nb), 0);
  for (int i = 0; i < nb; ++i)
    if (slab_point(boxes[static_cast<std::size_t>(i)], anchor[static_cast<std::size_t>(i)])) {
      has_anchor[static_cast<std::size_t>(i)] = 1;
      inside[static_cast<std::size_t>(find(parent, i))] = 1;
    }
  std::vector<int> curve_of(static_cast<std::size_t>(nb), -1),
      index_of(static_cast<std::size_t>(nb), -1);
  std::vector<std::vector<int>> members;
  for (int i = 0; i < nb; ++i) {
    const int root = find(parent, i);
    if (!inside[static_cast<std::size_t>(root)])
      continue;
    if (index_of[static_cast<std::size_t>(root)] < 0) {
      index_of[static_cast<std::size_t>(root)] = static_cast<int>(members.size());
      members.emplace_back();
    }
    curve_of[static_cast<std::size_t>(i)] = index_of[static_cast<std::size_t>(root)];
    members[static_cast<std::size_t>(curve_of[static_cast<std::size_t>(i)])].push_back(i);
  }
  if (members.empty())
    return out;
  const double rounding = 64 * (d + 1) * kEps * scale;
  const double margin = 1e-12 * scale;
  BernsteinTriangle neg(d, g.coefficients());
  for (double &x : neg.coefficients())
    x = -x;
  for (const std::vector<int> &mem : members) {
    CriticalCurve cv;
    // The value: that of the tightest box; the slack: every box's distance from it.
    const SlabBox *best = nullptr;
    for (int i : mem)
      if (!best || boxes[static_cast<std::size_t>(i)].bound < best->bound)
        best = &boxes[static_cast<std::size_t>(i)];
    // On the curve itself g is constant: Newton steps from the tightest slab's centre onto it
    // (the Hessian's null direction dropped) give its value to rounding, the same in every cell
    // it crosses, where the boxes' estimates differ by their bounds.
    cv.value = on_curve_value(g, *best);
    double spread = 0;
    for (int i : mem) {
      const SlabBox &b = boxes[static_cast<std::size_t>(i)];
      spread = std::max(spread, std::abs(b.value - cv.value) + b.bound);
    }
    if (!(spread <= curve_limit))
      return out;
    cv.slack = 2 * spread + 4 * rounding + 2 * value_noise;
    // Anchors: a point of each slab in the cell.
    for (int i : mem)
      if (has_anchor[static_cast<std::size_t>(i)])
        cv.anchors.push_back(anchor[static_cast<std::size_t>(i)]);
    Vec2 mid{0, 0};
    for (const Vec2 &a : cv.anchors)
      mid = {mid[0] + a[0] / cv.anchors.size(), mid[1] + a[1] / cv.anchors.size()};
    cv.uv =
        *std::min_element(cv.anchors.begin(), cv.anchors.end(), [&](const Vec2 &p, const Vec2 &q) {
          return std::hypot(p[0] - mid[0], p[1] - mid[1]) <
                 std::hypot(q[0] - mid[0], q[1] - mid[1]);
        });
    out.curves.push_back(std::move(cv));
  }

  // 3. Each curve's sectors, on the coarsest grid whose region Q works.
  thread_local std::vector<SignArc> arcs;
  for (std::size_t k = 0; k < out.curves.size(); ++k) {
    CriticalCurve &cv = out.curves[k];
    const std::vector<int> &mem = members[k];
    bool classified = false;
    for (int n : kRegionGrids) {
      if (classified)
        break;
      std::vector<char> in(static_cast<std::size_t>(n * n), 0);
      auto squares_of = [&](const SlabBox &b, auto &&f) {
        const int i0 = std::clamp(static_cast<int>(std::floor((b.c[0] - b.r) * n)), 0, n - 1);
        const int i1 = std::clamp(static_cast<int>(std::ceil((b.c[0] + b.r) * n)) - 1, 0, n - 1);
        const int j0 = std::clamp(static_cast<int>(std::floor((b.c[1] - b.r) * n)), 0, n - 1);
        const int j1 = std::clamp(static_cast<int>(std::ceil((b.c[1] + b.r) * n)) - 1, 0, n - 1);
        for (int i = i0; i <= i1; ++i)
          for (int j = j0; j <= j1; ++j)
            f(i, j);
      };
      for (int i : mem)
        squares_of(boxes[static_cast<std::size_t>(i)], [&](int a, int b) {
          for (int x = a - 1; x <= a + 1; ++x)
            for (int y = b - 1; y <= b + 1; ++y)
              if (x >= 0 && y >= 0 && x + y < n)
                in[static_cast<std::size_t>(x * n + y)] = 1;
        });
      // No other curve's box in Q.
      bool clear = true;
      for (int i = 0; i < nb && clear; ++i)
        if (curve_of[static_cast<std::size_t>(i)] >= 0 &&
            curve_of[static_cast<std::size_t>(i)] != static_cast<int>(k))
          squares_of(boxes[static_cast<std::size_t>(i)], [&](int a, int b) {
            if (a + b < n && in[static_cast<std::size_t>(a * n + b)])
              clear = false;
          });
      if (!clear)
        continue;
      // Every boundary point in Q lies on the curve.
      // Every boundary point in Q lies on the curve, or is joined to it by a ray: the lowest
      // (highest) point of a part of {g < L} ({g > L}) in Q that touches the curve but not Q's
      // inner boundary can only be such a point (or on the curve, within the slack).
      std::vector<int> on;
      std::vector<SignArc> targets;
      for (std::size_t p = 0; p < boundary_points.size() && clear; ++p) {
        const Vec2 &x = boundary_points[p];
        bool in_q = false;
        const int i = std::clamp(static_cast<int>(x[0] * n), 0, n - 1);
        const int j = std::clamp(static_cast<int>(x[1] * n), 0, n - 1);
        for (int a = i - 1; a <= i + 1 && !in_q; ++a)
          for (int b = j - 1; b <= j + 1 && !in_q; ++b)
            if (a >= 0 && b >= 0 && a + b < n && in[static_cast<std::size_t>(a * n + b)] &&
                x[0] >= static_cast<double>(a) / n - kTouch &&
                x[0] <= static_cast<double>(a + 1) / n + kTouch &&
                x[1] >= static_cast<double>(b) / n - kTouch &&
                x[1] <= static_cast<double>(b + 1) / n + kTouch)
              in_q = true;
        if (!in_q)
          continue;
        bool member = false;
        for (int bi : mem)
          member = member || on_slab(boxes[static_cast<std::size_t>(bi)], x);
        const double h = g(x[0], x[1]) - cv.value;
        if (member && std::abs(h) <= cv.slack)
          on.push_back(static_cast<int>(p));
        else if (!member && std::abs(h) > cv.slack)
          targets.push_back({h < 0, x});
        else
          clear = false;
      }
      if (!clear)
        continue;
      // The sign arcs on Q's inner boundary; each arc, and each boundary point above, gets a
      // ray from an anchor (the nearest that certifies).
      bool ok = true;
      for (const Polyline &line : region_boundary(in, n)) {
        ok = sign_arcs_on_polyline(g, line.points, line.closed, cv.value, cv.slack, arcs);
        if (!ok)
          break;
        targets.insert(targets.end(), arcs.begin(), arcs.end());
      }
      SectorRays rays;
      std::vector<std::pair<double, std::size_t>> near;
      for (const SignArc &a : targets) {
        if (!ok)
          break;
        near.clear();
        for (std::size_t i = 0; i < cv.anchors.size(); ++i)
          near.push_back(
              {std::hypot(cv.anchors[i][0] - a.point[0], cv.anchors[i][1] - a.point[1]), i});
        const std::size_t tries = std::min<std::size_t>(near.size(), kRayTries);
        std::partial_sort(near.begin(), near.begin() + static_cast<std::ptrdiff_t>(tries),
                          near.end());
        int skip = -1;
        Vec2 from{};
        for (std::size_t i = 0; i < tries && skip < 0; ++i) {
          from = cv.anchors[near[i].second];
          skip = a.lower ? certify_ray(g, from, a.point, cv.value, margin, cv.slack)
                         : certify_ray(neg, from, a.point, -cv.value, margin, cv.slack);
        }
        ok = skip >= 0;
        (a.lower ? rays.lower : rays.upper).push_back(a.point);
        (a.lower ? rays.lower_skip : rays.upper_skip).push_back(skip);
        (a.lower ? rays.lower_from : rays.upper_from).push_back(from);
      }
      if (!ok)
        continue;
      cv.rays = std::move(rays);
      cv.boundary_nodes = std::move(on);
      classified = true;
    }
    if (!classified)
      return CurveResolution{};
    out.slack = std::max(out.slack, cv.slack);
  }
  // A boundary point on two curves cannot be.
  std::vector<int> seen(boundary_points.size(), 0);
  for (const CriticalCurve &cv : out.curves)
    for (int p : cv.boundary_nodes)
      if (seen[static_cast<std::size_t>(p)]++)
        return CurveResolution{};
  // Corners whose edge's derivative vanishes there but which lie on no curve: their gradient is
  // orthogonal to that edge. Their sectors come from the corner triangle (cell/degenerate_
  // points.hpp), kept clear of every box of the cover, so that it holds no zero.
  for (int k = 0; k < 3; ++k) {
    if (!corners[k] || (k < static_cast<int>(seen.size()) && seen[static_cast<std::size_t>(k)]))
      continue;
    const Vec2 v = k == 0 ? Vec2{0, 0} : k == 1 ? Vec2{1, 0} : Vec2{0, 1};
    double r0 = std::min(corner_reach[k], 0.25);
    for (int i = 0; i < nb; ++i)
      if (curve_of[static_cast<std::size_t>(i)] >= 0) {
        const SlabBox &b = boxes[static_cast<std::size_t>(i)];
        r0 = std::min(r0, 0.5 * (std::max(std::abs(v[0] - b.c[0]), std::abs(v[1] - b.c[1])) - b.r));
      }
    out.corners[k] = classify_corner(g, neg, k, r0, 1e-6, 4 * rounding + 2 * value_noise, margin);
    if (!out.corners[k])
      return CurveResolution{};
  }
  out.resolved = true;
  return out;
}

} // namespace hoct
