#include "cell/sector_connections.hpp"

#include "poly/symmetric_eigen2.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace hoct {

void connect_sectors(const BernsteinTriangle &g, const CellNodes &cn,
                     const std::vector<int> &interior, const std::vector<CellEdgeNode> &edge,
                     PathCounters &counters, SectorResult &out, bool with_paths,
                     std::span<const SectorRays *const> rays,
                     const std::array<const SectorRays *, 3> &corner_rays) {
  out.join.clear();
  out.split.clear();
  out.join_paths.clear();
  out.split_paths.clear();
  out.failed = out.degenerate = false;
  const bool corners = corner_rays[0] || corner_rays[1] || corner_rays[2];
  if (interior.empty() && edge.empty() && !corners)
    return; // only corners: every sector lies along an edge
  // The fields the paths follow, set when a sector needs one: g for descending paths, -g for
  // ascending ones (most cells of a smooth field have edge nodes whose sectors all lie along
  // their edges, and need neither). Per-thread storage, reused from cell to cell.
  thread_local PathField down_field, up_field;
  bool have_down = false, have_up = false;
  auto down = [&]() -> const PathField & {
    if (!have_down)
      down_field.assign(g, false);
    have_down = true;
    return down_field;
  };
  auto up = [&]() -> const PathField & {
    if (!have_up)
      up_field.assign(g, true);
    have_up = true;
    return up_field;
  };
  thread_local std::vector<double> vals, neg_vals; // reused across cells of a thread
  vals.resize(cn.nodes.size());
  neg_vals.resize(cn.nodes.size());
  for (std::size_t i = 0; i < cn.nodes.size(); ++i) {
    vals[i] = cn.nodes[i].value;
    neg_vals[i] = -cn.nodes[i].value;
  }
  std::vector<Vec2> path;
  std::vector<Vec2> *want = with_paths ? &path : nullptr;
  // Each sector is tried along up to two directions (the second only if the first fails); the
  // cell fails when neither gives a certified path.
  // `from`: where the path starts, if not at the node (a critical curve's anchor).
  auto lower = [&](int node, const Vec2 &dir, int skip, const Vec2 *alt = nullptr,
                   const Vec2 *from = nullptr) {
    const Vec2 &start = from ? *from : cn.nodes[node].uv;
    int m = connect_lower(down(), cn, vals, start, vals[node], dir, skip, counters, want);
    if (m < 0 && alt)
      m = connect_lower(down(), cn, vals, start, vals[node], *alt, skip, counters, want);
    if (m < 0) {
      ++counters.failed;
      out.failed = true;
      return;
    }
    out.join.emplace_back(cn.nodes[node].ref, cn.nodes[m].ref);
    if (with_paths)
      out.join_paths.push_back(path);
  };
  auto upper = [&](int node, const Vec2 &dir, int skip, const Vec2 *alt = nullptr,
                   const Vec2 *from = nullptr) {
    const Vec2 &start = from ? *from : cn.nodes[node].uv;
    int m = connect_lower(up(), cn, neg_vals, start, neg_vals[node], dir, skip, counters, want);
    if (m < 0 && alt)
      m = connect_lower(up(), cn, neg_vals, start, neg_vals[node], *alt, skip, counters, want);
    if (m < 0) {
      ++counters.failed;
      out.failed = true;
      return;
    }
    out.split.emplace_back(cn.nodes[node].ref, cn.nodes[m].ref);
    if (with_paths)
      out.split_paths.push_back(path);
  };

  // A critical corner's sectors inside the cell (the corners are nodes 0, 1, 2).
  for (int k = 0; k < 3; ++k)
    if (const SectorRays *s = corner_rays[k]) {
      const Vec2 &p = cn.nodes[k].uv;
      for (std::size_t i = 0; i < s->lower.size(); ++i)
        lower(k, {s->lower[i][0] - p[0], s->lower[i][1] - p[1]}, s->lower_skip[i]);
      for (std::size_t i = 0; i < s->upper.size(); ++i)
        upper(k, {s->upper[i][0] - p[0], s->upper[i][1] - p[1]}, s->upper_skip[i]);
    }
  auto hessian = [&](const Vec2 &p) { return g.jet(p[0], p[1]).hessian; };
  for (std::size_t i = 0; i < interior.size(); ++i) {
    const int node = interior[i];
    const Vec2 &p = cn.nodes[node].uv;
    if (!rays.empty() && rays[i]) {
      const SectorRays &s = *rays[i];
      for (std::size_t k = 0; k < s.lower.size(); ++k) {
        const Vec2 &a = s.lower_from.empty() ? p : s.lower_from[k];
        lower(node, {s.lower[k][0] - a[0], s.lower[k][1] - a[1]}, s.lower_skip[k], nullptr, &a);
      }
      for (std::size_t k = 0; k < s.upper.size(); ++k) {
        const Vec2 &a = s.upper_from.empty() ? p : s.upper_from[k];
        upper(node, {s.upper[k][0] - a[0], s.upper[k][1] - a[1]}, s.upper_skip[k], nullptr, &a);
      }
      continue;
    }
    const SymmetricEigen2 eh = symmetric_eigen2(hessian(p));
    const double lambda[2] = {eh.lo, eh.hi};
    const Vec2 vec[2] = {eh.v_lo, eh.v_hi};
    const Vec2 neg0 = {-vec[0][0], -vec[0][1]}, neg1 = {-vec[1][0], -vec[1][1]};
    if (lambda[0] < 0 && lambda[1] > 0) { // saddle: two lower, two upper sectors
      lower(node, vec[0], 2);
      lower(node, neg0, 2);
      upper(node, vec[1], 2);
      upper(node, neg1, 2);
    } else if (lambda[1] < 0) { // maximum: one lower sector
      lower(node, vec[0], 2);
    } else if (lambda[0] > 0) { // minimum: one upper sector
      upper(node, vec[1], 2);
    } else {
      out.degenerate = true;
    }
  }
  // The normal derivative's sign decides whether an edge node has an interior sector. It is
  // trusted above 1e3 times the rounding level of the gradient's coefficients (64 eps of their
  // scale, as in find_gradient_zeros); below, the node is treated as a critical point of the
  // field lying on the edge (degenerate: fall back). The level is relative to the gradient, not
  // the values: in a thin cell the reference normal derivative is small with the cell's width.
  // The largest gradient coefficient, d |c[a+1,b] - c[a,b]| or d |c[a,b+1] - c[a,b]|.
  const double grad_scale = g.gradient_scale();
  const double gscale = 1e3 * 64 * std::numeric_limits<double>::epsilon() * grad_scale;
  for (const CellEdgeNode &e : edge) {
    const Vec2 &p = cn.nodes[e.node].uv;
    const Vec2 n = inward_normal(e.local_edge);
    const BernsteinTriangle::Jet jet = g.jet(p[0], p[1]);
    const double sn = jet.gradient[0] * n[0] + jet.gradient[1] * n[1];
    if (std::abs(sn) <= gscale) {
      out.degenerate = true;
      continue;
    }
    const bool descends = sn < 0 && e.second > 0; // the edge ascends both ways, the interior
    const bool ascends = sn > 0 && e.second < 0;  // descends (or the reverse)
    if (!descends && !ascends)
      continue;
    // The sector's axis: the direction conjugate to the edge under the Hessian (the tangential
    // slope of the quadratic model vanishes along it), where the sublevel set of the node's
    // value has its depth; in thin cells the reference normal is nearly tangent in the physical
    // plane and the dip along it can be below certification margins. The normal is the fallback.
    const Vec2 t = edge_tangent(e.local_edge);
    const Mat2 &h = jet.hessian;
    const double htt =
        t[0] * (h[0][0] * t[0] + h[0][1] * t[1]) + t[1] * (h[1][0] * t[0] + h[1][1] * t[1]);
    const double htn =
        t[0] * (h[0][0] * n[0] + h[0][1] * n[1]) + t[1] * (h[1][0] * n[0] + h[1][1] * n[1]);
    const double k = htn / htt;
    const Vec2 conj = {n[0] - k * t[0], n[1] - k * t[1]};
    const bool use_conj = std::isfinite(k) && std::abs(k) < 1e6 && (descends ? htt > 0 : htt < 0);
    if (descends)
      use_conj ? lower(e.node, conj, 1, &n) : lower(e.node, n, 1);
    else
      use_conj ? upper(e.node, conj, 1, &n) : upper(e.node, n, 1);
  }
}

} // namespace hoct
