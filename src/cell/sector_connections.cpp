#include "cell/sector_connections.hpp"

#include <cmath>

namespace hoct {
namespace {

// Eigen-decomposition of a symmetric 2x2 matrix: eigenvalues ascending, unit eigenvectors.
void eigen2(const Mat2 &h, double lambda[2], Vec2 vec[2]) {
  const double a = h[0][0], b = h[0][1], c = h[1][1];
  const double mean = 0.5 * (a + c), diff = 0.5 * (a - c);
  const double r = std::hypot(diff, b);
  lambda[0] = mean - r;
  lambda[1] = mean + r;
  // Eigenvector of the larger eigenvalue: angle theta with tan(2 theta) = 2b / (a - c).
  const double theta = 0.5 * std::atan2(2 * b, a - c);
  vec[1] = {std::cos(theta), std::sin(theta)};
  vec[0] = {-std::sin(theta), std::cos(theta)};
}

} // namespace

SectorResult connect_sectors(const BernsteinTriangle &g, const CellNodes &cn,
                             const std::vector<int> &interior,
                             const std::vector<CellEdgeNode> &edge, PathCounters &counters,
                             bool with_paths) {
  SectorResult out;
  const PathField down(g);
  const PathField up = down.negated();
  thread_local std::vector<double> vals, neg_vals; // reused across cells of a thread
  vals.resize(cn.nodes.size());
  neg_vals.resize(cn.nodes.size());
  for (std::size_t i = 0; i < cn.nodes.size(); ++i) {
    vals[i] = cn.nodes[i].value;
    neg_vals[i] = -cn.nodes[i].value;
  }
  std::vector<Vec2> path;
  std::vector<Vec2> *want = with_paths ? &path : nullptr;
  auto lower = [&](int node, const Vec2 &dir, int skip) {
    const int m =
        connect_lower(down, cn, vals, cn.nodes[node].uv, vals[node], dir, skip, counters, want);
    if (m < 0) {
      out.failed = true;
      return;
    }
    out.join.emplace_back(cn.nodes[node].ref, cn.nodes[m].ref);
    if (with_paths)
      out.join_paths.push_back(path);
  };
  auto upper = [&](int node, const Vec2 &dir, int skip) {
    const int m = connect_lower(up, cn, neg_vals, cn.nodes[node].uv, neg_vals[node], dir, skip,
                                counters, want);
    if (m < 0) {
      out.failed = true;
      return;
    }
    out.split.emplace_back(cn.nodes[node].ref, cn.nodes[m].ref);
    if (with_paths)
      out.split_paths.push_back(path);
  };

  // Second derivatives once per cell (only where there are interior nodes).
  BernsteinTriangle guu, guv, gvv;
  if (!interior.empty()) {
    guu = down.gu.du();
    guv = down.gu.dv();
    gvv = down.gv.dv();
  }
  for (int node : interior) {
    const Vec2 &p = cn.nodes[node].uv;
    double lambda[2];
    Vec2 vec[2];
    const double huv = guv(p[0], p[1]);
    eigen2({{{guu(p[0], p[1]), huv}, {huv, gvv(p[0], p[1])}}}, lambda, vec);
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
  const double gscale = std::abs(down.margin) * 1e4; // 1e-8 of the value scale
  for (const CellEdgeNode &e : edge) {
    const Vec2 &p = cn.nodes[e.node].uv;
    const Vec2 n = inward_normal(e.local_edge);
    const double sn = down.gu(p[0], p[1]) * n[0] + down.gv(p[0], p[1]) * n[1];
    if (std::abs(sn) <= gscale) {
      out.degenerate = true;
      continue;
    }
    if (sn < 0 && e.second > 0)
      lower(e.node, n, 1); // the edge ascends both ways, the interior descends
    else if (sn > 0 && e.second < 0)
      upper(e.node, n, 1);
  }
  return out;
}

} // namespace hoct
