// The certified local connections of single cells (connect_sectors) for small analytic fields:
// the join / split pairs against closed-form reasoning, every connection against a brute-force
// reference (union-find on a fine sampling of the cell's sub- or superlevel set: a connection
// must land in a component adjacent to its node, and the lower (upper) sectors of an interior
// node must reach each adjacent component), and the failed / degenerate flags.
#include "cell/cell_nodes.hpp"
#include "cell/sector_connections.hpp"
#include "poly/bernstein_triangle.hpp"
#include "poly/lattice.hpp"
#include "test_bernstein_forms.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numeric>
#include <set>
#include <utility>
#include <vector>

namespace hoct {
namespace {

using Fn = std::function<double(double, double)>;
using Pairs = std::vector<std::pair<int64_t, int64_t>>;

using testing::interpolate;
using testing::separable;

// One cell as connect_cell() assembles it: corners (refs 0..2), edge nodes (refs 100, 101, ...
// in the order added; per edge in ascending parameter), interior critical points (refs -1, -2,
// ...).
struct Cell {
  Fn f;
  CellNodes cn;
  std::vector<int> interior;
  std::vector<CellEdgeNode> edge;
  int64_t next_edge_ref = 100;
  explicit Cell(Fn field) : f(std::move(field)) {
    static constexpr double kCorner[3][2] = {{0, 0}, {1, 0}, {0, 1}};
    for (int k = 0; k < 3; ++k) {
      cn.nodes.push_back({{kCorner[k][0], kCorner[k][1]}, f(kCorner[k][0], kCorner[k][1]), k});
      cn.chain[k] = {k, (k + 1) % 3};
      cn.chain_s[k] = {0.0, 1.0};
    }
  }
  // An edge node of local edge k at parameter s, with the edge polynomial's second derivative.
  int64_t add_edge_node(int k, double s, double second) {
    const Vec2 p = point_on_edge(k, s);
    const int idx = static_cast<int>(cn.nodes.size());
    const int64_t ref = next_edge_ref++;
    cn.nodes.push_back({p, f(p[0], p[1]), ref});
    cn.chain[k].insert(cn.chain[k].end() - 1, idx);
    cn.chain_s[k].insert(cn.chain_s[k].end() - 1, s);
    edge.push_back({k, s, second, idx});
    return ref;
  }
  int64_t add_interior(const Vec2 &p) {
    const int64_t ref = -1 - static_cast<int64_t>(interior.size());
    interior.push_back(static_cast<int>(cn.nodes.size()));
    cn.nodes.push_back({p, f(p[0], p[1]), ref});
    return ref;
  }
  const LocalNode &node(int64_t ref) const {
    for (const LocalNode &n : cn.nodes)
      if (n.ref == ref)
        return n;
    ADD_FAILURE() << "no node " << ref;
    return cn.nodes[0];
  }
  SectorResult connect(const BernsteinTriangle &g, PathCounters *counters = nullptr) const {
    PathCounters local;
    SectorResult out;
    connect_sectors(g, cn, interior, edge, counters ? *counters : local, out, true);
    return out;
  }
};

Pairs sorted(Pairs p) {
  std::sort(p.begin(), p.end());
  return p;
}

// Brute-force reference: union-find over the points (i/N, j/N) of the cell where h < level,
// neighbours along the three directions of the uniform triangulation (PL connectivity).
class LevelSetComponents {
public:
  LevelSetComponents(const Fn &h, double level, int n = 120) : n_(n) {
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i + j <= n; ++i) {
        const Vec2 p = point(i, j);
        inside_.push_back(h(p[0], p[1]) < level);
      }
    parent_.resize(inside_.size());
    std::iota(parent_.begin(), parent_.end(), 0);
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i + j <= n; ++i) {
        if (!inside_[index(i, j)])
          continue;
        const int nb[3][2] = {{i + 1, j}, {i, j + 1}, {i - 1, j + 1}};
        for (const auto &q : nb)
          if (q[0] >= 0 && q[0] + q[1] <= n && inside_[index(q[0], q[1])])
            unite(index(i, j), index(q[0], q[1]));
      }
  }
  // The component of the sampled point nearest to p among those in the set (-1 if none within
  // two grid spacings).
  int component_at(const Vec2 &p) {
    int best = -1;
    double bd = 2.0 / n_;
    for (int j = 0; j <= n_; ++j)
      for (int i = 0; i + j <= n_; ++i)
        if (inside_[index(i, j)]) {
          const Vec2 q = point(i, j);
          const double d = std::hypot(q[0] - p[0], q[1] - p[1]);
          if (d <= bd)
            bd = d, best = find(index(i, j));
        }
    return best;
  }
  // The components meeting the disc of radius r around p.
  std::set<int> components_near(const Vec2 &p, double r) {
    std::set<int> out;
    for (int j = 0; j <= n_; ++j)
      for (int i = 0; i + j <= n_; ++i) {
        const Vec2 q = point(i, j);
        if (inside_[index(i, j)] && std::hypot(q[0] - p[0], q[1] - p[1]) <= r)
          out.insert(find(index(i, j)));
      }
    return out;
  }

private:
  Vec2 point(int i, int j) const {
    return {i / static_cast<double>(n_), j / static_cast<double>(n_)};
  }
  int index(int i, int j) const { return j * (n_ + 1) - j * (j - 1) / 2 + i; }
  int find(int x) {
    while (parent_[x] != x)
      x = parent_[x] = parent_[parent_[x]];
    return x;
  }
  void unite(int a, int b) { parent_[find(a)] = find(b); }
  int n_;
  std::vector<char> inside_;
  std::vector<int> parent_;
};

// Every connection against the brute-force reference: joins go to a lower node in a component of
// {g < g(node)} adjacent to the node, splits likewise on {-g < -g(node)}; an interior node's
// connections of one kind reach exactly the adjacent components (each lower / upper sector its
// own); with paths, each polyline runs from the node to its target strictly below (above) the
// node's level.
void expect_matches_reference(const Cell &cell, const SectorResult &r) {
  ASSERT_EQ(r.join_paths.size(), r.join.size());
  ASSERT_EQ(r.split_paths.size(), r.split.size());
  for (int side = 0; side < 2; ++side) {
    const Pairs &pairs = side == 0 ? r.join : r.split;
    const double sign = side == 0 ? 1 : -1;
    const Fn h = [&](double u, double v) { return sign * cell.f(u, v); };
    std::set<int64_t> from;
    for (std::size_t i = 0; i < pairs.size(); ++i) {
      const auto [a, b] = pairs[i];
      const LocalNode &na = cell.node(a), &nb = cell.node(b);
      const double level = sign * na.value;
      SCOPED_TRACE(::testing::Message() << (side == 0 ? "join " : "split ") << a << " -> " << b);
      EXPECT_LT(sign * nb.value, level);
      // Below the level by a clear amount: a fresh sampling is meaningful near the nodes.
      LevelSetComponents sub(h, level - 1e-12);
      const int cb = sub.component_at(nb.uv);
      EXPECT_GE(cb, 0);
      EXPECT_EQ(sub.components_near(na.uv, 0.04).count(cb), 1u);
      const std::vector<Vec2> &path = (side == 0 ? r.join_paths : r.split_paths)[i];
      ASSERT_GE(path.size(), 2u);
      EXPECT_EQ(path.front(), na.uv);
      EXPECT_EQ(path.back(), nb.uv);
      for (std::size_t k = 1; k < path.size(); ++k)
        for (int t = k == 1 ? 1 : 0; t <= 100; ++t) {
          const double s = t / 100.0;
          const Vec2 x = {path[k - 1][0] + s * (path[k][0] - path[k - 1][0]),
                          path[k - 1][1] + s * (path[k][1] - path[k - 1][1])};
          ASSERT_LT(h(x[0], x[1]), level) << "segment " << k << " at " << s;
        }
      from.insert(a);
    }
    for (int64_t a : from) {
      if (a >= 0)
        continue; // edge nodes: their sectors along the edge need no connection
      const LocalNode &na = cell.node(a);
      LevelSetComponents sub(h, sign * na.value - 1e-12);
      std::multiset<int> reached;
      for (const auto &[x, b] : pairs)
        if (x == a)
          reached.insert(sub.component_at(cell.node(b).uv));
      const std::set<int> adjacent = sub.components_near(na.uv, 0.04);
      EXPECT_EQ(std::set<int>(reached.begin(), reached.end()), adjacent)
          << (side == 0 ? "join" : "split") << " sectors of " << a;
    }
  }
}

// ---------------------------------------------------------------------------------------------

// (u - 1/3)^2 - (v - 1/3)^2: saddle at (1/3, 1/3) (value 0), lower sectors along +-v, upper
// along +-u. Edge 0 has its minimum (1/3, 0) (-1/9; the interior ascends from it: no interior
// sector), edge 2 its maximum (0, 1/3) (1/9; the interior descends from it); edge 1 is linear.
// The lower sector along -v holds the edge-0 minimum, the one along +v corner 2 (-1/3); the upper
// sector along +u holds corner 1 (1/3), the one along -u the edge-2 maximum.
Cell saddle_cell(double scale = 1, double offset = 0) {
  Cell c([=](double u, double v) {
    return offset + scale * ((u - 1.0 / 3) * (u - 1.0 / 3) - (v - 1.0 / 3) * (v - 1.0 / 3));
  });
  c.add_edge_node(0, 1.0 / 3, 2 * scale);  // ref 100
  c.add_edge_node(2, 2.0 / 3, -2 * scale); // ref 101
  c.add_interior({1.0 / 3, 1.0 / 3});      // ref -1
  return c;
}

TEST(SectorConnections, QuadraticSaddle) {
  const Cell cell = saddle_cell();
  const BernsteinTriangle g = interpolate(2, cell.f);
  PathCounters counters;
  const SectorResult r = cell.connect(g, &counters);
  EXPECT_FALSE(r.failed);
  EXPECT_FALSE(r.degenerate);
  EXPECT_EQ(sorted(r.join), (Pairs{{-1, 2}, {-1, 100}}));
  EXPECT_EQ(sorted(r.split), (Pairs{{-1, 1}, {-1, 101}}));
  EXPECT_EQ(counters.failed, 0);
  EXPECT_EQ(counters.direct + counters.traced, 4);
  expect_matches_reference(cell, r);
  // The reference sees the two lower (upper) sectors as two components.
  LevelSetComponents below([&](double u, double v) { return cell.f(u, v); }, -1e-12);
  EXPECT_EQ(below.components_near({1.0 / 3, 1.0 / 3}, 0.04).size(), 2u);
  // ... with the two targets in different ones (a swapped pair of targets would not pass).
  EXPECT_NE(below.component_at(cell.node(2).uv), below.component_at(cell.node(100).uv));
}

TEST(SectorConnections, SingleMaximum) {
  // -(u - 0.3)^2 - (v - 0.25)^2: every edge has a maximum from which the interior ascends (to
  // the peak), the peak one lower sector (the whole cell but the peak).
  Cell cell([](double u, double v) { return -(u - 0.3) * (u - 0.3) - (v - 0.25) * (v - 0.25); });
  const int64_t e0 = cell.add_edge_node(0, 0.3, -2), e1 = cell.add_edge_node(1, 0.475, -4),
                e2 = cell.add_edge_node(2, 0.75, -2);
  const int64_t peak = cell.add_interior({0.3, 0.25});
  const SectorResult r = cell.connect(interpolate(2, cell.f));
  EXPECT_FALSE(r.failed);
  EXPECT_FALSE(r.degenerate);
  EXPECT_EQ(sorted(r.split), sorted({{e0, peak}, {e1, peak}, {e2, peak}}));
  ASSERT_EQ(r.join.size(), 1u);
  EXPECT_EQ(r.join[0].first, peak);
  EXPECT_NE(r.join[0].second, peak);
  expect_matches_reference(cell, r);
}

TEST(SectorConnections, SingleMinimum) {
  // The mirror image: joins from the edge minima to the pit, one split from the pit.
  Cell cell([](double u, double v) { return (u - 0.3) * (u - 0.3) + (v - 0.25) * (v - 0.25); });
  const int64_t e0 = cell.add_edge_node(0, 0.3, 2), e1 = cell.add_edge_node(1, 0.475, 4),
                e2 = cell.add_edge_node(2, 0.75, 2);
  const int64_t pit = cell.add_interior({0.3, 0.25});
  const SectorResult r = cell.connect(interpolate(2, cell.f));
  EXPECT_FALSE(r.failed);
  EXPECT_FALSE(r.degenerate);
  EXPECT_EQ(sorted(r.join), sorted({{e0, pit}, {e1, pit}, {e2, pit}}));
  ASSERT_EQ(r.split.size(), 1u);
  EXPECT_EQ(r.split[0].first, pit);
  expect_matches_reference(cell, r);
}

TEST(SectorConnections, MonotoneLinearFieldHasNone) {
  // Only corners: every sector lies along an edge. The result is reset from a previous use.
  Cell cell([](double u, double v) { return 0.2 + u - 0.5 * v; });
  SectorResult out;
  out.join = {{7, 8}};
  out.split = {{9, 10}};
  out.failed = out.degenerate = true;
  PathCounters counters;
  connect_sectors(interpolate(1, cell.f), cell.cn, cell.interior, cell.edge, counters, out, true);
  EXPECT_TRUE(out.join.empty());
  EXPECT_TRUE(out.split.empty());
  EXPECT_FALSE(out.failed);
  EXPECT_FALSE(out.degenerate);
  EXPECT_EQ(counters.direct + counters.traced + counters.failed, 0);
}

TEST(SectorConnections, EdgeMinimumWithDescendingInterior) {
  // (u - 0.4)^2 - v: edge 0 has its minimum at u = 0.4 (value 0) but the interior descends from
  // it: one lower sector, {v > (u - 0.4)^2}, whose only node is corner 2 (-0.84) (corners 0 and
  // 1 are above; edges 1 and 2 are monotone).
  Cell cell([](double u, double v) { return (u - 0.4) * (u - 0.4) - v; });
  const int64_t e0 = cell.add_edge_node(0, 0.4, 2);
  const SectorResult r = cell.connect(interpolate(2, cell.f));
  EXPECT_FALSE(r.failed);
  EXPECT_FALSE(r.degenerate);
  EXPECT_EQ(r.join, (Pairs{{e0, 2}}));
  EXPECT_TRUE(r.split.empty());
  expect_matches_reference(cell, r);
}

TEST(SectorConnections, SkewedEdgeSectorFollowsTheConjugateDirection) {
  // (u - 0.4 - v)^2 - 1e-7 v, as the reference field of a thin cell is: the lower sector of the
  // edge-0 minimum (0.4, 0) is a wedge of width ~ sqrt(1e-7 v) around the line u = 0.4 + v, and
  // along the inward normal the field dips below 0 by at most 2.5e-15, inside the margin. Along
  // the direction conjugate to the edge, (1, 1), it falls by 1e-7 v, and the sector reaches the
  // minimum of edge 1 near (0.7, 0.3), the cell's only node below 0. (Too thin for the sampled
  // reference; the path is checked against the field instead.)
  Cell cell([](double u, double v) { return (u - 0.4 - v) * (u - 0.4 - v) - 1e-7 * v; });
  const int64_t e0 = cell.add_edge_node(0, 0.4, 2);
  // Edge 1 at (1 - s, s): (0.6 - 2 s)^2 - 1e-7 s, minimum at s = 0.3 + 1.25e-8, second 8.
  const int64_t e1 = cell.add_edge_node(1, 0.3 + 1.25e-8, 8);
  for (int k = 0; k < 3; ++k)
    ASSERT_GT(cell.cn.nodes[k].value, 0);
  ASSERT_LT(cell.node(e1).value, -2e-8);
  const SectorResult r = cell.connect(interpolate(2, cell.f));
  EXPECT_FALSE(r.failed);
  EXPECT_FALSE(r.degenerate);
  EXPECT_EQ(r.join, (Pairs{{e0, e1}}));
  EXPECT_TRUE(r.split.empty());
  ASSERT_EQ(r.join_paths.size(), 1u);
  const std::vector<Vec2> &path = r.join_paths[0];
  ASSERT_GE(path.size(), 3u);
  // The first step leaves along (1, 1).
  EXPECT_NEAR(path[1][0] - path[0][0], path[1][1] - path[0][1], 1e-12);
  EXPECT_GT(path[1][1], 0);
  for (std::size_t k = 1; k < path.size(); ++k)
    for (int t = k == 1 ? 1 : 0; t <= 100; ++t) {
      const double s = t / 100.0;
      EXPECT_LT(cell.f(path[k - 1][0] + s * (path[k][0] - path[k - 1][0]),
                       path[k - 1][1] + s * (path[k][1] - path[k - 1][1])),
                0.0)
          << "segment " << k << " at " << s;
    }
}

TEST(SectorConnections, MaximumAndSaddle) {
  // A(u) + C(v), A' = (u - 0.2)(u - 0.5), C = -(v - 0.25)^2 / 2: a maximum at (0.2, 0.25) and a
  // saddle at (0.5, 0.25) (lower sectors along +-v, upper along +-u). Edge 0: a maximum at 0.2
  // and a minimum at 0.5, both with the interior ascending; edge 2: a maximum at v = 0.25
  // (s = 0.75), interior ascending; edge 1 monotone. Lower sectors: the saddle's two, the
  // peak's one; upper: the saddle's two, the edge-0 maximum's and the edge-2 maximum's.
  const auto A = [](double u) { return u * u * u / 3 - 0.35 * u * u + 0.1 * u; };
  Cell cell([=](double u, double v) { return A(u) - 0.5 * (v - 0.25) * (v - 0.25); });
  const int64_t e00 = cell.add_edge_node(0, 0.2, -0.3), e01 = cell.add_edge_node(0, 0.5, 0.3),
                e2 = cell.add_edge_node(2, 0.75, -1);
  const int64_t peak = cell.add_interior({0.2, 0.25}), saddle = cell.add_interior({0.5, 0.25});
  const SectorResult r = cell.connect(interpolate(3, cell.f));
  EXPECT_FALSE(r.failed);
  EXPECT_FALSE(r.degenerate);
  ASSERT_EQ(r.join.size(), 3u);
  ASSERT_EQ(r.split.size(), 4u);
  Pairs saddle_join, saddle_split;
  std::multiset<int64_t> join_from, split_from;
  for (const auto &p : r.join) {
    join_from.insert(p.first);
    if (p.first == saddle)
      saddle_join.push_back(p);
  }
  for (const auto &p : r.split) {
    split_from.insert(p.first);
    if (p.first == saddle)
      saddle_split.push_back(p);
  }
  EXPECT_EQ(join_from, (std::multiset<int64_t>{saddle, saddle, peak}));
  EXPECT_EQ(split_from, (std::multiset<int64_t>{saddle, saddle, e00, e2}));
  // The saddle's sectors: down to the edge-0 minimum and (via edge 1) corner 2; up to corner 1
  // and along the ridge to the peak.
  EXPECT_EQ(sorted(saddle_join), sorted({{saddle, 2}, {saddle, e01}}));
  EXPECT_EQ(sorted(saddle_split), sorted({{saddle, 1}, {saddle, peak}}));
  expect_matches_reference(cell, r);
}

// ---------------------------------------------------------------------------------------------
// Flags.

TEST(SectorConnections, SectorsShallowerThanTheMarginFail) {
  // The saddle on top of 1: scaled by 1e-14 its sectors' nodes are within the certification
  // margin (1e-12 of the coefficients) of its level, so no sector is certified: the cell must
  // fall back. Scaled by 1e-9 they are well outside it, and the connections are the saddle's.
  {
    const Cell cell = saddle_cell(1e-14, 1);
    PathCounters counters;
    const SectorResult r = cell.connect(interpolate(2, cell.f), &counters);
    EXPECT_TRUE(r.failed);
    EXPECT_FALSE(r.degenerate);
    EXPECT_TRUE(r.join.empty());
    EXPECT_TRUE(r.split.empty());
    EXPECT_EQ(counters.failed, 4);
  }
  {
    const Cell cell = saddle_cell(1e-9, 1);
    PathCounters counters;
    const SectorResult r = cell.connect(interpolate(2, cell.f), &counters);
    EXPECT_FALSE(r.failed);
    EXPECT_FALSE(r.degenerate);
    EXPECT_EQ(sorted(r.join), (Pairs{{-1, 2}, {-1, 100}}));
    EXPECT_EQ(sorted(r.split), (Pairs{{-1, 1}, {-1, 101}}));
    EXPECT_EQ(counters.failed, 0);
  }
}

TEST(SectorConnections, LowerSectorWithoutCertifiedStartFails) {
  // An interior node classified as a maximum (Hessian diag(-2, -4), lower sector along the v
  // axis, +v) but 0.1 off the true maximum (0.3, 0.4) of -(u - 0.3)^2 - 2 (v - 0.3)^2 + 0.4 v,
  // as a wrongly located critical point would be: the field ascends from it along +v, so no
  // first step is certified below its level and the cell must fall back. (Only that node is
  // given: its sector alone is at stake.)
  Cell cell([](double u, double v) {
    return -(u - 0.3) * (u - 0.3) - 2 * (v - 0.3) * (v - 0.3) + 0.4 * v;
  });
  cell.add_interior({0.3, 0.3});
  PathCounters counters;
  const SectorResult r = cell.connect(interpolate(2, cell.f), &counters);
  EXPECT_TRUE(r.failed);
  EXPECT_FALSE(r.degenerate);
  EXPECT_TRUE(r.join.empty());
  EXPECT_TRUE(r.split.empty());
  EXPECT_EQ(counters.failed, 1);
  // At the true maximum the same sector connects.
  Cell good(cell.f);
  const int64_t peak = good.add_interior({0.3, 0.4});
  const SectorResult ok = good.connect(interpolate(2, good.f));
  EXPECT_FALSE(ok.failed);
  ASSERT_EQ(ok.join.size(), 1u);
  EXPECT_EQ(ok.join[0].first, peak);
  expect_matches_reference(good, ok);
}

TEST(SectorConnections, SingularHessianIsDegenerate) {
  // (u - 0.3)^2: a line of critical points; at (0.3, 0.3) the Hessian diag(2, 0) is singular
  // (exactly: the coefficients do not depend on v), neither saddle nor extremum. The edge nodes
  // on u = 0.3 are omitted so that only the interior classification is at stake.
  Cell cell([](double u, double) { return (u - 0.3) * (u - 0.3); });
  cell.add_interior({0.3, 0.3});
  const BernsteinTriangle g = separable({0.09, -0.21, 0.49}, {0, 0, 0});
  ASSERT_NEAR(g(0.7, 0.2), cell.f(0.7, 0.2), 1e-15);
  const SectorResult r = cell.connect(g);
  EXPECT_TRUE(r.degenerate);
  EXPECT_TRUE(r.join.empty());
  EXPECT_TRUE(r.split.empty());
}

TEST(SectorConnections, EdgeNodeWithVanishingNormalDerivativeIsDegenerate) {
  // (u - 0.3)^2 + v^2 + eta v: for eta = 0 the minimum (0.3, 0) of edge 0 is a critical point of
  // the field (normal derivative exactly 0), for eta = 1e-13 it is one up to rounding of the
  // gradient (below 1e3 * 64 eps of its scale): degenerate, and no path is tried from it even
  // where the rounded sign says the interior descends (eta = -1e-13). For eta = 1e-6 the
  // interior ascends from it: no sector, no flag.
  for (const double eta : {0.0, 1e-13, -1e-13, 1e-6}) {
    Cell cell([eta](double u, double v) { return (u - 0.3) * (u - 0.3) + v * v + eta * v; });
    cell.add_edge_node(0, 0.3, 2);
    const BernsteinTriangle g = separable({0.09, -0.21, 0.49}, {0, eta / 2, 1 + eta});
    ASSERT_NEAR(g(0.7, 0.2), cell.f(0.7, 0.2), 1e-15);
    const SectorResult r = cell.connect(g);
    EXPECT_EQ(r.degenerate, std::abs(eta) < 1e-9) << eta;
    EXPECT_FALSE(r.failed) << eta;
    EXPECT_TRUE(r.join.empty()) << eta;
    EXPECT_TRUE(r.split.empty()) << eta;
  }
}

} // namespace
} // namespace hoct
