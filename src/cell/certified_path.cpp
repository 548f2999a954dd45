#include "cell/certified_path.hpp"

#include "poly/root_isolation.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace hoct {
namespace {

constexpr int kMaxSegmentDegree = 64;

// All Bernstein coefficients c[skip..n] below the threshold, or (with skip = 0) those of both
// halves after up to `depth` subdivisions at 1/2.
bool coefficients_below(const double *c, int n, double threshold, int skip, int depth) {
  bool ok = true;
  for (int i = skip; i <= n && ok; ++i)
    ok = c[i] < threshold;
  if (ok)
    return true;
  if (skip > 0 || depth <= 0 || n > kMaxSegmentDegree)
    return false;
  // The values themselves must be below at the ends for a subdivision to help.
  if (!(c[0] < threshold) || !(c[n] < threshold))
    return false;
  double w[kMaxSegmentDegree + 1], left[kMaxSegmentDegree + 1], right[kMaxSegmentDegree + 1];
  std::copy(c, c + n + 1, w);
  left[0] = w[0];
  right[n] = w[n];
  for (int r = 1; r <= n; ++r) {
    for (int i = 0; i <= n - r; ++i)
      w[i] = 0.5 * (w[i] + w[i + 1]);
    left[r] = w[0];
    right[n - r] = w[n - r];
  }
  return coefficients_below(left, n, threshold, 0, depth - 1) &&
         coefficients_below(right, n, threshold, 0, depth - 1);
}

bool coefficients_below(const BernsteinPoly &r, double threshold, int skip, int depth) {
  return coefficients_below(r.coefficients().data(), r.degree(), threshold, skip, depth);
}

// Largest alpha with p + alpha w in the closed reference triangle (w != 0), and which side
// (local edge) it hits: 0 (v = 0), 1 (u + v = 1), 2 (u = 0).
double ray_exit(const Vec2 &p, const Vec2 &w, int &edge) {
  double best = INFINITY;
  edge = -1;
  if (w[1] < 0) {
    const double a = p[1] / -w[1];
    if (a < best)
      best = a, edge = 0;
  }
  if (w[0] + w[1] > 0) {
    const double a = (1 - p[0] - p[1]) / (w[0] + w[1]);
    if (a < best)
      best = a, edge = 1;
  }
  if (w[0] < 0) {
    const double a = p[0] / -w[0];
    if (a < best)
      best = a, edge = 2;
  }
  return std::max(best, 0.0);
}

// Parameter along local edge k of a point on it.
double edge_parameter(int k, const Vec2 &p) {
  switch (k) {
  case 0:
    return p[0];
  case 1:
    return p[1];
  default:
    return 1 - p[1];
  }
}

} // namespace

void PathField::assign(const BernsteinTriangle &poly, bool negate) {
  g.assign(poly.degree(), poly.coefficients());
  double scale = 0;
  for (double &c : g.coefficients()) {
    scale = std::max(scale, std::abs(c));
    if (negate)
      c = -c;
  }
  margin = 1e-12 * std::max(scale, 1e-300);
}

bool certify_below(const BernsteinTriangle &g, const Vec2 &p, const Vec2 &q, double threshold,
                   int skip, int depth) {
  if (g.degree() > kMaxSegmentDegree)
    return coefficients_below(g.restrict_to_segment(p, q), threshold, skip, depth);
  double r[kMaxSegmentDegree + 1];
  g.restrict_to_segment(p, q, r);
  return coefficients_below(r, g.degree(), threshold, skip, depth);
}

int connect_lower(const PathField &f, const CellNodes &cn, const std::vector<double> &values,
                  const Vec2 &c, double level, const Vec2 &dir, int skip, PathCounters &counters,
                  std::vector<Vec2> *path) {
  if (path)
    path->clear();
  const double thr = level - f.margin;
  // 1. A certified first step into the sector.
  int exit_edge;
  const double norm = std::hypot(dir[0], dir[1]);
  const Vec2 w = {dir[0] / norm, dir[1] / norm};
  double delta = std::min(0.25, 0.5 * ray_exit(c, w, exit_edge));
  Vec2 s{};
  bool started = false;
  for (; delta > 1e-9; delta *= 0.5) {
    s = {c[0] + delta * w[0], c[1] + delta * w[1]};
    if (certify_below(f.g, c, s, thr, std::max(skip, 1))) {
      started = true;
      break;
    }
  }
  if (!started)
    return -1;
  // Candidate targets: nodes below the threshold, nearest first; from the first step's end,
  // those ahead of the sector's start (on the side of its direction) before those behind it,
  // which a segment can reach only by crossing back through the node's neighbourhood.
  struct Candidate {
    double key;
    int node;
    bool operator<(const Candidate &o) const {
      return key < o.key || (key == o.key && node < o.node);
    }
  };
  thread_local std::vector<Candidate> order; // reused: no allocation per call
  auto try_targets = [&](const Vec2 &x, bool ahead_first) {
    order.clear();
    for (std::size_t i = 0; i < cn.nodes.size(); ++i)
      if (values[i] < thr) {
        const auto &p = cn.nodes[i].uv;
        double key = (p[0] - x[0]) * (p[0] - x[0]) + (p[1] - x[1]) * (p[1] - x[1]);
        if (ahead_first && (p[0] - c[0]) * w[0] + (p[1] - c[1]) * w[1] <= 0)
          key += 16; // beyond any squared distance in the reference triangle
        order.push_back({key, static_cast<int>(i)});
      }
    std::sort(order.begin(), order.end());
    for (const Candidate &t : order)
      if (certify_below(f.g, x, cn.nodes[t.node].uv, thr, 0))
        return t.node;
    return -1;
  };
  if (path)
    *path = {c, s};
  int m = try_targets(s, true);
  if (m >= 0) {
    ++counters.direct;
    if (path)
      path->push_back(cn.nodes[m].uv);
    return m;
  }
  // 2. Certified descent steps.
  Vec2 x = s;
  for (int step = 0; step < 100; ++step) {
    ++counters.steps;
    const Vec2 grad = f.g.jet(x[0], x[1]).gradient;
    const double gn = std::hypot(grad[0], grad[1]);
    if (!(gn > 0))
      break;
    const Vec2 d = {-grad[0] / gn, -grad[1] / gn};
    int edge;
    const double amax = ray_exit(x, d, edge);
    if (!(amax > 1e-14))
      break;
    const Vec2 end = {x[0] + amax * d[0], x[1] + amax * d[1]};
    const BernsteinPoly r = f.g.restrict_to_segment(x, end);
    // The first local minimum along the ray, else the boundary.
    double tstar = 1.0;
    for (const Root &root : find_roots(r.derivative()))
      if (root.t > 1e-12) {
        tstar = root.t;
        break;
      }
    bool on_boundary = tstar == 1.0;
    Vec2 y{};
    bool ok = false;
    for (int shrink = 0; shrink < 30; ++shrink) {
      y = {x[0] + tstar * amax * d[0], x[1] + tstar * amax * d[1]};
      if (coefficients_below(r.subinterval(0, tstar), thr, 0, 6)) {
        ok = true;
        break;
      }
      tstar *= 0.5;
      on_boundary = false;
    }
    if (!ok)
      break;
    if (on_boundary) {
      // On local edge `edge`: the lower of the two chain nodes around the hit point, reached
      // along the monotone edge.
      const double sp = edge_parameter(edge, end);
      const auto &ch = cn.chain[edge];
      const auto &cs = cn.chain_s[edge];
      for (std::size_t i = 0; i + 1 < ch.size(); ++i)
        if (sp >= cs[i] && sp <= cs[i + 1]) {
          const int lo = values[ch[i]] < values[ch[i + 1]] ? ch[i] : ch[i + 1];
          if (values[lo] < thr) {
            ++counters.traced;
            if (path) {
              path->push_back(end);
              path->push_back(cn.nodes[lo].uv);
            }
            return lo;
          }
          break;
        }
      break;
    }
    x = y;
    if (path)
      path->push_back(x);
    m = try_targets(x, false);
    if (m >= 0) {
      ++counters.traced;
      if (path)
        path->push_back(cn.nodes[m].uv);
      return m;
    }
  }
  return -1;
}

} // namespace hoct
