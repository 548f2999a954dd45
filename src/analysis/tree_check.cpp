#include "analysis/tree_check.hpp"

#include "cell/degenerate_points.hpp"
#include "cell/edge_nodes.hpp"
#include "poly/reference_triangle.hpp"
#include "tree/union_find.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>

namespace hoct {
namespace {

using P2 = std::array<double, 2>;

constexpr const Vec2 (&kCorner)[3] = kReferenceCorner;

// Differences below this are not told apart: subnormal numbers have no relative precision left
// (a field of values around 1e-310 evaluates to 0 in places).
constexpr double kTiny = 1e-300;

std::string node_str(int64_t i) { return "node " + std::to_string(i); }

// One sample direction around a node: in `cell`, the point base + r * dir.
struct RingSample {
  int64_t cell;
  P2 base, dir;
};

// Samples around a node in circular order; `closed` when the ring goes all the way round (an
// interior point of the surface), open when it starts and ends on the mesh boundary.
struct Ring {
  std::vector<RingSample> samples;
  bool closed = true;
  double max_radius = 0.25; // keeps every sample inside its cell
  std::string unusable;     // why no ring could be built (non-manifold, ...)
};

// Lower and upper sectors of a sign pattern (no zeros).
struct Sectors {
  int lower = 0, upper = 0;
};

Sectors count_sectors(const std::vector<int8_t> &sign, bool closed) {
  Sectors s;
  const std::size_t n = sign.size();
  if (n == 0)
    return s;
  int changes = 0;
  for (std::size_t i = 1; i < n; ++i)
    changes += sign[i] != sign[i - 1];
  if (closed) {
    changes += sign[0] != sign[n - 1];
    if (changes == 0)
      (sign[0] > 0 ? s.upper : s.lower) = 1;
    else
      s.lower = s.upper = changes / 2;
    return s;
  }
  // Open: runs of each sign.
  for (std::size_t i = 0; i < n; ++i)
    if (i == 0 || sign[i] != sign[i - 1])
      ++(sign[i] > 0 ? s.upper : s.lower);
  return s;
}

// The most loops a Reeb graph of a function on the surface can have: per component, its first
// Betti number 1 - chi with boundary (2g + b - 1), and for a closed component g = (2 - chi) / 2
// if the surface is orientable (a Reeb graph has at most g loops there: Cole-McLaughlin et al.
// 2003), else 2 - chi. 0 when every component is a disk or a sphere.
int64_t max_reeb_loops(const Topology &t) {
  const int64_t nv = t.num_vertices();
  UnionFind uf(static_cast<std::size_t>(nv)), boundary(static_cast<std::size_t>(nv));
  for (int64_t e = 0; e < t.num_edges(); ++e) {
    const auto &ev = t.edge_vertices(e);
    uf.unite(ev[0], ev[1]);
    if (t.is_boundary_edge(e))
      boundary.unite(ev[0], ev[1]);
  }
  // Per component (its root): Euler characteristic and boundary loops.
  std::vector<int64_t> chi(static_cast<std::size_t>(nv), 0), loops(nv, 0);
  std::vector<uint8_t> on_boundary(static_cast<std::size_t>(nv), 0);
  for (int64_t v = 0; v < nv; ++v)
    ++chi[uf.find(v)];
  for (int64_t e = 0; e < t.num_edges(); ++e) {
    --chi[uf.find(t.edge_vertices(e)[0])];
    if (t.is_boundary_edge(e))
      for (int64_t v : t.edge_vertices(e))
        on_boundary[v] = 1;
  }
  for (int64_t c = 0; c < t.num_cells(); ++c)
    ++chi[uf.find(t.cell_vertices(c)[0])];
  for (int64_t v = 0; v < nv; ++v)
    if (on_boundary[v] && boundary.find(v) == v)
      ++loops[uf.find(v)];
  int64_t most = 0;
  for (int64_t v = 0; v < nv; ++v)
    if (uf.find(v) == v)
      most += loops[v] > 0 ? 1 - chi[v] : (t.orientable() ? (2 - chi[v]) / 2 : 2 - chi[v]);
  return most;
}

class Checker {
public:
  Checker(const TreeResult &t, const Mesh &m, const TreeCheckOptions &o)
      : tree_(t), mesh_(m), opt_(o), n_(static_cast<int64_t>(t.nodes.size())) {
    const double lo = m.field.min_value(), hi = m.field.max_value();
    scale_ = std::max({hi - lo, std::abs(lo), std::abs(hi)});
    for (const auto &node : t.nodes)
      if (std::isfinite(node.value))
        scale_ = std::max(scale_, std::abs(node.value));
    if (!(scale_ > 0))
      scale_ = 1;
    if (m.complete) {
      const Topology &t = m.topology;
      sphere_ = t.components() == 1 && t.euler_characteristic() == 2 && t.boundary_loops() == 0;
      max_loops_ = max_reeb_loops(t);
    }
  }

  TreeCheckReport run() {
    structure();
    if (!mesh_.complete)
      return std::move(report_);
    for (int64_t i = 0; i < n_; ++i)
      placement(i);
    if (opt_.check_types && !placement_failed_)
      for (int64_t i = 0; i < n_; ++i)
        neighbourhood(i);
    recorded_persistence();
    if (report_.failures.empty())
      pairs();
    if (opt_.check_completeness && tree_.stats.nodes_before_simplification)
      report_.skipped.push_back(
          {"completeness", {}, {}, "a simplified tree: its pruned extrema are not looked for"});
    else if (opt_.check_completeness && !placement_failed_)
      completeness();
    return std::move(report_);
  }

private:
  void fail(const std::string &check, std::vector<int64_t> nodes, std::vector<int64_t> arcs,
            const std::string &msg) {
    report_.failures.push_back({check, std::move(nodes), std::move(arcs), msg});
  }

  // Tree-ness, Euler relation, order, degrees versus types.
  void structure() {
    const auto &arcs = tree_.arcs;
    const int64_t na = static_cast<int64_t>(arcs.size());
    const int64_t components =
        mesh_.complete ? std::max<int64_t>(1, mesh_.topology.components()) : 1;
    deg_.assign(n_, {0, 0});
    flat_end_.assign(static_cast<std::size_t>(n_), 0);
    double magnitude = 0;
    for (const auto &nd : tree_.nodes)
      magnitude = std::max(magnitude, std::abs(nd.value));
    // As contract_flat (tree/tree_result.cpp) decides what is flat.
    const double flat =
        (n_ > 0 ? 1e-12 * (tree_.nodes.back().value - tree_.nodes.front().value) : 0.0) +
        2 * std::numeric_limits<double>::epsilon() * magnitude;
    for (int64_t i = 0; i + 1 < n_; ++i)
      if (tree_.nodes[i + 1].value < tree_.nodes[i].value)
        fail("order", {i, i + 1}, {},
             node_str(i) + " (value " + fmt(tree_.nodes[i].value) + ") comes before " +
                 node_str(i + 1) + " (value " + fmt(tree_.nodes[i + 1].value) +
                 "): nodes must ascend by value");
    UnionFind uf(static_cast<std::size_t>(std::max<int64_t>(n_, 1)));
    int64_t joined = 0;
    for (int64_t a = 0; a < na; ++a) {
      const int64_t x = arcs[a][0], y = arcs[a][1];
      if (x < 0 || y < 0 || x >= n_ || y >= n_) {
        fail("tree", {}, {a}, "arc " + std::to_string(a) + " refers to a node that does not exist");
        continue;
      }
      if (x == y) {
        fail("tree", {x}, {a}, "arc " + std::to_string(a) + " is a loop at " + node_str(x));
        continue;
      }
      // Lower node first in the total order (value, index).
      if (!node_less(tree_.nodes[x].value, x, tree_.nodes[y].value, y))
        fail("order", {x, y}, {a},
             "arc " + std::to_string(a) + " runs from " + node_str(x) + " down to " + node_str(y));
      const int64_t lo = node_less(tree_.nodes[x].value, x, tree_.nodes[y].value, y) ? x : y;
      const int64_t hi = lo == x ? y : x;
      ++deg_[lo][0];
      ++deg_[hi][1];
      if (std::abs(tree_.nodes[x].value - tree_.nodes[y].value) <= flat)
        flat_end_[static_cast<std::size_t>(x)] = flat_end_[static_cast<std::size_t>(y)] = 1;
      if (uf.find(x) == uf.find(y)) {
        // A loop of the level sets: only where the surface has holes or handles.
        if (max_loops_ == 0)
          fail("tree", {x, y}, {a},
               "arc " + std::to_string(a) + " closes a cycle (" + node_str(x) + " and " +
                   node_str(y) +
                   " are already connected), but the domain has no holes or "
                   "handles (a contour tree has no loops)");
      } else {
        uf.unite(x, y);
        ++joined;
      }
    }
    if (n_ == 0 && mesh_.complete && mesh_.topology.num_cells() > 0)
      fail("tree", {}, {},
           "the tree is empty, but the mesh has " + std::to_string(mesh_.topology.num_cells()) +
               " cells (a field has a minimum)");
    const int64_t tree_components = n_ - joined;
    if (n_ > 0 && tree_components != components)
      fail("tree", {}, {},
           "the tree has " + std::to_string(tree_components) +
               " connected component(s), the mesh " + std::to_string(components));
    // The loops: arcs beyond a spanning forest (0 for a tree).
    const int64_t loops = na - (n_ - tree_components);
    if (n_ > 0 && max_loops_ == 0 && na != n_ - components)
      fail("tree", {}, {},
           std::to_string(na) + " arcs for " + std::to_string(n_) + " nodes and " +
               std::to_string(components) + " component(s) (a tree has nodes - 1 arcs)");
    if (n_ > 0 && loops > max_loops_ && max_loops_ > 0)
      fail("loops", {}, {},
           "the graph has " + std::to_string(loops) +
               " loops, but a Reeb graph on this surface "
               "has at most " +
               std::to_string(max_loops_) + " (genus and boundary loops)");
    if (n_ > 0 && loops != tree_.loops)
      fail("loops", {}, {},
           "the graph has " + std::to_string(loops) +
               " loops (arcs - nodes + components), but "
               "it records " +
               std::to_string(tree_.loops));
    int64_t euler = 0;
    for (int64_t i = 0; i < n_; ++i)
      euler += deg_[i][0] + deg_[i][1] - 2;
    if (n_ > 0 && euler != 2 * loops - 2 * components)
      fail("euler", {}, {},
           "sum of (degree - 2) over the nodes is " + std::to_string(euler) + ", not " +
               std::to_string(2 * loops - 2 * components) + " (2 (loops - components))");
    for (int64_t i = 0; i < n_; ++i)
      degree_vs_type(i, components);
  }

  void degree_vs_type(int64_t i, int64_t components) {
    const TreeNode &nd = tree_.nodes[i];
    const int up = deg_[i][0], down = deg_[i][1];
    if (nd.up != up || nd.down != down) {
      // Readers and builders fill up/down; they must agree with the arcs.
      if (nd.up != 0 || nd.down != 0)
        fail("degree", {i}, {},
             node_str(i) + " records " + std::to_string(nd.up) + " arcs up and " +
                 std::to_string(nd.down) + " down, but the arcs give " + std::to_string(up) +
                 " and " + std::to_string(down));
    }
    const bool single = up + down == 0 && n_ <= components;
    std::string want;
    switch (nd.type) {
    // A minimum has arcs up only: one, or more where a flat region (one contracted node) is
    // both a minimum and a split; the samples around the node then tell (a non-flat minimum has
    // one upper sector, so two arcs up fail there).
    case NodeType::Minimum:
      if (!(down == 0 && (up >= 1 || single)))
        want = "a minimum has arcs up only";
      break;
    case NodeType::Maximum:
      if (!(up == 0 && (down >= 1 || single)))
        want = "a maximum has arcs down only";
      break;
    case NodeType::Saddle:
      // (ContourTree::types calls the node of a one-node tree, e.g. a constant field, a saddle.)
      if (!(up >= 1 && down >= 1 && up + down >= 3) && !single)
        want = "a saddle has at least three arcs, up and down";
      break;
    case NodeType::Regular:
      if (!tree_.augmented)
        want = "a reduced tree has no regular nodes";
      else if (!(up == 1 && down == 1))
        want = "a regular node has one arc up and one down";
      break;
    }
    if (!want.empty())
      fail("degree", {i}, {},
           node_str(i) + " is a " + to_string(nd.type) + " with " + std::to_string(up) +
               " arc(s) up and " + std::to_string(down) + " down: " + want);
  }

  // Value and position versus the field and the geometry at (cell, u, v).
  void placement(int64_t i) {
    const TreeNode &nd = tree_.nodes[i];
    const int64_t nc = mesh_.topology.num_cells();
    const double u = nd.uv[0], v = nd.uv[1];
    constexpr double slack = 1e-9;
    if (nd.cell < 0 || nd.cell >= nc || !std::isfinite(u) || !std::isfinite(v) || u < -slack ||
        v < -slack || u + v > 1 + slack) {
      fail("position", {i}, {},
           node_str(i) + " is not in the mesh: cell " + std::to_string(nd.cell) + " of " +
               std::to_string(nc) + ", (u, v) = (" + fmt(u) + ", " + fmt(v) + ")");
      placement_failed_ = true;
      return;
    }
    const double f = mesh_.field.value(nd.cell, u, v);
    if (!(std::abs(f - nd.value) <= std::max(opt_.value_tolerance * scale_, kTiny)))
      fail("value", {i}, {},
           node_str(i) + " has value " + fmt(nd.value) + " but the field at cell " +
               std::to_string(nd.cell) + " (" + fmt(u) + ", " + fmt(v) + ") is " + fmt(f));
    const Vec3 p = mesh_.geometry.position(nd.cell, u, v);
    const double dist =
        std::hypot(p[0] - nd.position[0], p[1] - nd.position[1], p[2] - nd.position[2]);
    if (!(dist <= opt_.position_tolerance * std::max(mesh_.geometry.extent(), 1e-300)))
      fail("position", {i}, {},
           node_str(i) + " is at (" + fmt(nd.position[0]) + ", " + fmt(nd.position[1]) + ", " +
               fmt(nd.position[2]) + ") but cell " + std::to_string(nd.cell) + " (" + fmt(u) +
               ", " + fmt(v) + ") maps to (" + fmt(p[0]) + ", " + fmt(p[1]) + ", " + fmt(p[2]) +
               ")");
    critical(i);
  }

  // A node inside a cell must be a critical point of its polynomial (the gradient vanishes), a
  // node on an edge a critical point of the edge (the derivative along it vanishes): to 1e-6 of
  // the cell's gradient scale, far above the certified placement (1e-12) and far below the
  // gradient at a regular point. Vertices may be anything; fallback nodes are the PL rule's and
  // flat regions' nodes stand for many, so those are skipped; regular nodes are not critical.
  void critical(int64_t i) {
    const TreeNode &nd = tree_.nodes[i];
    if (nd.fallback || nd.merged > 1 || nd.type == NodeType::Regular)
      return;
    const double u = nd.uv[0], v = nd.uv[1];
    const NodeLocation where = classify_location(u, v);
    if (where == NodeLocation::Vertex)
      return;
    const BernsteinTriangle p = mesh_.field.cell_polynomial(nd.cell);
    double scale = 0;
    for (const auto &dp : {p.du(), p.dv()})
      for (double c : dp.coefficients())
        scale = std::max(scale, std::abs(c));
    if (!(scale > 0))
      return; // a constant cell: every point is critical
    const Vec2 g = p.gradient(u, v);
    double residual = std::hypot(g[0], g[1]);
    std::string what = "|gradient|";
    if (where == NodeLocation::Edge) {
      const int k = std::abs(v) <= 1e-12 ? 0 : std::abs(u) <= 1e-12 ? 2 : 1;
      const Vec2 t = edge_tangent(k);
      residual = std::abs(g[0] * t[0] + g[1] * t[1]);
      what = "|derivative along edge " + std::to_string(k) + "|";
    }
    if (!(residual <= 1e-6 * scale))
      fail("critical", {i}, {},
           node_str(i) + " is not a critical point: " + what + " = " + fmt(residual) + " at cell " +
               std::to_string(nd.cell) + " (" + fmt(u) + ", " + fmt(v) + "), against " +
               fmt(scale) + " for the cell's gradient");
  }

  // Each pair's persistence as a file recorded it against its nodes' values.
  void recorded_persistence() {
    const auto &rec = tree_.recorded_persistence;
    if (rec.empty())
      return;
    if (rec.size() != tree_.pairs.size()) {
      fail("pairs", {}, {},
           std::to_string(rec.size()) + " recorded persistences for " +
               std::to_string(tree_.pairs.size()) + " pairs");
      return;
    }
    for (std::size_t k = 0; k < rec.size(); ++k) {
      const PersistencePair &p = tree_.pairs[k];
      if (!(std::abs(rec[k] - p.persistence()) <= std::max(opt_.value_tolerance * scale_, kTiny)))
        fail("pairs", {p.birth, p.death}, {},
             "pair " + std::to_string(k) + " records persistence " + fmt(rec[k]) + ", but " +
                 node_str(p.birth) + " and " + node_str(p.death) + " differ by " +
                 fmt(p.persistence()));
    }
  }

  // The recorded persistence pairs against the elder-rule pairs of the tree's own arcs.
  void pairs() {
    if (tree_.pairs.empty() && n_ <= 1)
      return;
    const std::vector<PersistencePair> want = tree_pairs(as_contour_tree(tree_));
    auto key = [](const PersistencePair &p) {
      return std::array<int64_t, 3>{std::min(p.birth, p.death), std::max(p.birth, p.death),
                                    static_cast<int64_t>(p.kind)};
    };
    std::vector<std::array<int64_t, 3>> got_keys, want_keys;
    for (const auto &p : tree_.pairs)
      got_keys.push_back(key(p));
    for (const auto &p : want)
      want_keys.push_back(key(p));
    std::sort(got_keys.begin(), got_keys.end());
    std::sort(want_keys.begin(), want_keys.end());
    if (got_keys == want_keys)
      return;
    std::string first;
    for (const auto &k : want_keys)
      if (!std::binary_search(got_keys.begin(), got_keys.end(), k)) {
        first = "; missing, e.g. " + node_str(k[0]) + " with " + node_str(k[1]);
        break;
      }
    if (first.empty())
      for (const auto &k : got_keys)
        if (!std::binary_search(want_keys.begin(), want_keys.end(), k)) {
          first = "; not a pair of the arcs, e.g. " + node_str(k[0]) + " with " + node_str(k[1]);
          break;
        }
    fail("pairs", {}, {},
         std::to_string(tree_.pairs.size()) + " persistence pairs recorded, but the arcs give " +
             std::to_string(want.size()) + first);
  }

  // Extrema the tree must have, decided from the edge polynomials alone. A vertex whose every
  // edge ascends from it (a non-zero derivative) is a strict local minimum: in each cell around
  // it the derivative along a direction of the corner's cone is a convex combination of those
  // along its two edges. An edge critical point that is a strict minimum of its edge, where the
  // field rises into every cell of the edge (a positive inward derivative), is one too. Maxima
  // alike. Each must be a minimum (maximum) node of the tree at that point, unless the tree has
  // a flat region of its value or fallback nodes in its cells (then it is reported as skipped).
  void completeness() {
    const Topology &t = mesh_.topology;
    const Field &field = mesh_.field;
    // Slopes of the relative values the field holds: relative to their range, not to |f|.
    const double tol = 1e-9 * field.value_scale();
    const int64_t nv = t.num_vertices(), ne = t.num_edges();
    // Per vertex: every edge so far ascends (bit 0) / descends (bit 1) away from it.
    std::vector<uint8_t> all(static_cast<std::size_t>(nv), 3);
    std::vector<uint8_t> has_edge(static_cast<std::size_t>(nv), 0);
    for (int64_t e = 0; e < ne; ++e) {
      const auto c = field.edge_coefficients(e);
      const int d = static_cast<int>(c.size()) - 1;
      if (d < 1) {
        for (int64_t v : t.edge_vertices(e))
          all[v] = 0;
        continue;
      }
      const double from_lo = d * (c[1] - c[0]), from_hi = d * (c[d - 1] - c[d]);
      for (int end = 0; end < 2; ++end) {
        const int64_t v = t.edge_vertices(e)[end];
        const double slope = end == 0 ? from_lo : from_hi;
        has_edge[v] = 1;
        if (!(slope > tol))
          all[v] &= uint8_t(~1u);
        if (!(slope < -tol))
          all[v] &= uint8_t(~2u);
      }
    }
    build_vertex_cells();
    for (int64_t v = 0; v < nv; ++v) {
      if (!has_edge[v] || all[v] == 0)
        continue;
      std::vector<int64_t> cells;
      for (int64_t k = vertex_offset_[v]; k < vertex_offset_[v + 1]; ++k)
        cells.push_back(vertex_cells_[k].first);
      const int64_t c = vertex_cells_[vertex_offset_[v]].first;
      const int corner = vertex_cells_[vertex_offset_[v]].second;
      expect_extremum((all[v] & 1) ? NodeType::Minimum : NodeType::Maximum, c, kCorner[corner],
                      field.reference() + field.vertex_value(v), cells,
                      "vertex " + std::to_string(v));
    }
    EdgeNodeOptions eo;
    const EdgeNodes en = find_edge_nodes(t, field, eo);
    for (int64_t e = 0; e < ne; ++e) {
      if (en.degeneracy[e] != kEdgeOk)
        continue;
      for (int64_t i = en.offset[e]; i < en.offset[e + 1]; ++i) {
        const EdgeNode &node = en.nodes[i];
        if (!node.simple || std::abs(node.second) <= tol)
          continue;
        const bool edge_min = node.second > 0;
        bool extremum = true;
        std::vector<int64_t> cells;
        for (int j = 0; j < t.edge_cell_count(e) && extremum; ++j) {
          const int64_t c = t.edge_cells_begin(e)[j];
          cells.push_back(c);
          const int k = t.local_edge(c, e);
          const double sk = t.edge_reversed(c, k) ? 1 - node.t : node.t;
          const Vec2 uv = point_on_edge(k, sk);
          const Vec2 g = field.cell_polynomial(c).gradient(uv[0], uv[1]);
          const Vec2 n = inward_normal(k);
          const double s = g[0] * n[0] + g[1] * n[1];
          extremum = edge_min ? s > tol : s < -tol;
        }
        if (!extremum)
          continue;
        const int64_t c = t.edge_cells_begin(e)[0];
        const int k = t.local_edge(c, e);
        const Vec2 uv = point_on_edge(k, t.edge_reversed(c, k) ? 1 - node.t : node.t);
        expect_extremum(
            edge_min ? NodeType::Minimum : NodeType::Maximum, c, uv, field.reference() + node.value,
            cells, "the critical point of edge " + std::to_string(e) + " at t = " + fmt(node.t));
      }
    }
  }

  void expect_extremum(NodeType type, int64_t cell, const Vec2 &uv, double value,
                       const std::vector<int64_t> &cells, const std::string &what) {
    const Vec3 p = mesh_.geometry.position(cell, uv[0], uv[1]);
    const double close = 1e-7 * std::max(mesh_.geometry.extent(), 1e-300);
    const double vtol = std::max(opt_.value_tolerance * scale_, kTiny);
    // Tree nodes of that value (they ascend by value).
    auto lo = std::lower_bound(tree_.nodes.begin(), tree_.nodes.end(), value - vtol,
                               [](const TreeNode &a, double x) { return a.value < x; });
    bool flat = false;
    for (auto it = lo; it != tree_.nodes.end() && it->value <= value + vtol; ++it) {
      const double dist =
          std::hypot(it->position[0] - p[0], it->position[1] - p[1], it->position[2] - p[2]);
      if (dist <= close && it->type == type) {
        ++report_.extrema_confirmed;
        return;
      }
      flat |= it->merged > 1;
    }
    bool fallback = false;
    for (const TreeNode &nd : tree_.nodes)
      fallback |= nd.fallback && std::find(cells.begin(), cells.end(), nd.cell) != cells.end();
    const std::string msg = what + " is a strict local " +
                            (type == NodeType::Minimum ? "minimum" : "maximum") + " (value " +
                            fmt(value) + ", from the edge polynomials) but the tree has no " +
                            to_string(type) + " there";
    if (flat || fallback)
      report_.skipped.push_back({"completeness",
                                 {},
                                 {},
                                 msg + (flat ? " (a flat region of its value may stand for it)"
                                             : " (fallback nodes in its cells)")});
    else
      fail("completeness", {}, {}, msg);
  }

  // ---- rings of samples around a node ----

  // The cells around each vertex, (cell, corner), built on first use.
  void build_vertex_cells() {
    if (!vertex_offset_.empty())
      return;
    const Topology &t = mesh_.topology;
    vertex_offset_.assign(t.num_vertices() + 1, 0);
    for (int64_t c = 0; c < t.num_cells(); ++c)
      for (int k = 0; k < 3; ++k)
        ++vertex_offset_[t.cell_vertices(c)[k] + 1];
    for (int64_t v = 0; v < t.num_vertices(); ++v)
      vertex_offset_[v + 1] += vertex_offset_[v];
    vertex_cells_.resize(vertex_offset_.back());
    std::vector<int64_t> fill(vertex_offset_.begin(), vertex_offset_.end() - 1);
    for (int64_t c = 0; c < t.num_cells(); ++c)
      for (int k = 0; k < 3; ++k)
        vertex_cells_[fill[t.cell_vertices(c)[k]]++] = {c, k};
  }

  int local_edge_of(int64_t c, int64_t e) const { return mesh_.topology.local_edge(c, e); }

  // Directions from corner k of the reference triangle towards corner j.
  static P2 towards(int k, int j) {
    return {kCorner[j][0] - kCorner[k][0], kCorner[j][1] - kCorner[k][1]};
  }

  Ring vertex_ring(int64_t c0, int corner0) {
    Ring ring;
    ring.max_radius = 0.25;
    build_vertex_cells();
    const Topology &t = mesh_.topology;
    const int64_t vtx = t.cell_vertices(c0)[corner0];
    const int64_t count = vertex_offset_[vtx + 1] - vertex_offset_[vtx];
    // The fan: start at a cell with a boundary edge at the vertex, if any.
    int64_t start = -1;
    int start_corner = 0;
    int64_t start_edge = -1;
    for (int64_t i = vertex_offset_[vtx]; i < vertex_offset_[vtx + 1]; ++i) {
      const auto [c, k] = vertex_cells_[i];
      for (int le : {k, (k + 2) % 3}) {
        const int64_t e = t.cell_edge(c, le);
        if (t.edge_cell_count(e) > 2) {
          ring.unusable = "non-manifold edge at the vertex";
          return ring;
        }
        if (t.edge_cell_count(e) == 1 && start < 0) {
          start = c;
          start_corner = k;
          start_edge = e;
        }
      }
    }
    ring.closed = start < 0;
    if (start < 0) {
      start = c0;
      start_corner = corner0;
      start_edge = t.cell_edge(c0, corner0);
    }
    int64_t c = start, e_in = start_edge;
    int k = start_corner;
    const int m = std::max(4, opt_.samples / 2);
    for (int64_t step = 0; step < count; ++step) {
      // The corners across the entering edge and across the leaving edge.
      const int a = (k + 1) % 3, b = (k + 2) % 3;
      const bool in_is_a = t.cell_edge(c, k) == e_in; // local edge k joins corners k and k+1
      const int from = in_is_a ? a : b, to = in_is_a ? b : a;
      const P2 da = towards(k, from), db = towards(k, to);
      // Both ends on the edges (thin sectors hug the edges: creases of the C0 field).
      for (int s = 0; s <= m; ++s) {
        const double w = static_cast<double>(s) / m;
        ring.samples.push_back(
            {c, kCorner[k], {(1 - w) * da[0] + w * db[0], (1 - w) * da[1] + w * db[1]}});
      }
      const int le_out = in_is_a ? (k + 2) % 3 : k;
      const int64_t e_out = t.cell_edge(c, le_out);
      const int64_t next = t.neighbor(c, le_out);
      if (next < 0)
        break;
      if (next == start) {
        if (step + 1 != count)
          ring.unusable = "the cells around the vertex form more than one fan";
        return ring;
      }
      int kn = 0;
      while (kn < 3 && t.cell_vertices(next)[kn] != vtx)
        ++kn;
      c = next;
      k = kn;
      e_in = e_out;
      if (step + 1 == count)
        ring.unusable = "the cells around the vertex do not close up";
    }
    if (ring.closed)
      ring.unusable = "the cells around the vertex do not close up";
    else if (static_cast<int64_t>(ring.samples.size()) != count * (m + 1))
      ring.unusable = "the cells around the vertex form more than one fan";
    return ring;
  }

  // Unit-ish vectors along local edge k (from corner k to k+1) and into the cell.
  static void edge_frame(int k, P2 &along, P2 &inward) {
    const double h = std::numbers::sqrt2 / 2;
    if (k == 0) {
      along = {1, 0};
      inward = {0, 1};
    } else if (k == 1) {
      along = {-h, h};
      inward = {-h, -h};
    } else {
      along = {0, -1};
      inward = {1, 0};
    }
  }

  Ring edge_ring(int64_t c, double u, double v) {
    Ring ring;
    const Topology &t = mesh_.topology;
    // Which local edge, and the parameter t from corner k to corner k+1.
    const double d0 = std::abs(v), d1 = std::abs(1 - u - v), d2 = std::abs(u);
    int k = 0;
    double tk = u;
    if (d1 <= d0 && d1 <= d2) {
      k = 1;
      tk = v;
    } else if (d2 < d0) {
      k = 2;
      tk = 1 - v;
    }
    tk = std::clamp(tk, 0.0, 1.0);
    const int64_t e = t.cell_edge(c, k);
    if (t.edge_cell_count(e) > 2) {
      ring.unusable = "non-manifold edge";
      return ring;
    }
    ring.max_radius = 0.5 * std::min(tk, 1 - tk);
    const int m = std::max(4, opt_.samples);
    // Parameter from the edge's lower vertex.
    const double s_global = t.edge_reversed(c, k) ? 1 - tk : tk;
    auto half_disk = [&](int64_t cell, int kk, double tt, bool forward) {
      P2 along, inward;
      edge_frame(kk, along, inward);
      const P2 base = point_on_edge(kk, tt);
      // Both ends on the edge itself: along a crease the lower (upper) sectors are thin.
      for (int s = 0; s <= m; ++s) {
        const double w = static_cast<double>(s) / m;
        const double ang = std::numbers::pi * (forward ? w : 1 - w);
        ring.samples.push_back({cell,
                                base,
                                {std::cos(ang) * along[0] + std::sin(ang) * inward[0],
                                 std::cos(ang) * along[1] + std::sin(ang) * inward[1]}});
      }
    };
    // In c: from towards corner k+1, through the inside, to towards corner k.
    half_disk(c, k, tk, true);
    const int64_t n = t.neighbor(c, k);
    ring.closed = n >= 0;
    if (n >= 0) {
      const int kn = local_edge_of(n, e);
      const double tn = t.edge_reversed(n, kn) ? 1 - s_global : s_global;
      // Continue from the side of c's corner k: in n that corner is corner kn (then go from
      // "towards kn" to "towards kn+1") when both cells run the edge the same way.
      const bool same_way = t.cell_vertices(n)[kn] == t.cell_vertices(c)[k];
      half_disk(n, kn, tn, !same_way);
      ring.max_radius = std::min(ring.max_radius, 0.5 * std::min(tn, 1 - tn));
    }
    return ring;
  }

  Ring interior_ring(int64_t c, double u, double v) {
    Ring ring;
    ring.closed = true;
    ring.max_radius = 0.5 * std::min({u, v, (1 - u - v) / std::numbers::sqrt2});
    const int m = std::max(8, 2 * opt_.samples);
    for (int s = 0; s < m; ++s) {
      const double ang = 2 * std::numbers::pi * s / m;
      ring.samples.push_back({c, {u, v}, {std::cos(ang), std::sin(ang)}});
    }
    return ring;
  }

  // Type versus samples of the field around the node.
  void neighbourhood(int64_t i) {
    const TreeNode &nd = tree_.nodes[i];
    if (nd.fallback) {
      skip(i, node_str(i) + " lies in a degenerate cell's PL fallback: its type is the "
                            "refinement's (skipped)");
      return;
    }
    if (nd.merged > 1) {
      skip(i, node_str(i) + " stands for a flat region of " + std::to_string(nd.merged) +
                  " nodes of one value (skipped)");
      return;
    }
    if (flat_end_[static_cast<std::size_t>(i)]) {
      skip(i, node_str(i) + " is one of a flat region's nodes, left uncontracted (skipped)");
      return;
    }
    const double u = nd.uv[0], v = nd.uv[1];
    Ring ring;
    switch (classify_location(u, v)) {
    case NodeLocation::Vertex: {
      int corner = 0;
      if (u >= 0.5)
        corner = 1;
      else if (v >= 0.5)
        corner = 2;
      ring = vertex_ring(nd.cell, corner);
      break;
    }
    case NodeLocation::Edge:
      ring = edge_ring(nd.cell, u, v);
      break;
    default:
      ring = interior_ring(nd.cell, u, v);
    }
    if (!ring.unusable.empty()) {
      skip(i, node_str(i) + ": " + ring.unusable + " (skipped)");
      return;
    }
    const int up = deg_[i][0], down = deg_[i][1];
    bool conclusive = false;
    std::string seen;
    std::vector<int8_t> sign(ring.samples.size());
    std::vector<BernsteinTriangle> polys;
    std::vector<int64_t> poly_cell;
    auto poly = [&](int64_t c) -> const BernsteinTriangle & {
      for (std::size_t j = 0; j < poly_cell.size(); ++j)
        if (poly_cell[j] == c)
          return polys[j];
      poly_cell.push_back(c);
      polys.push_back(mesh_.field.cell_polynomial(c));
      return polys.back();
    };
    // Rounding of the polynomials' evaluation: a few hundred ulps of their coefficients.
    double eps = 0;
    for (const auto &s : ring.samples)
      for (double b : poly(s.cell).coefficients())
        eps = std::max(eps, std::abs(b));
    // The cell polynomials hold f - reference (mesh/field.hpp); the node's absolute value was
    // rounded to its own units in the last place when the reference was added back.
    const double relative = nd.value - mesh_.field.reference();
    eps = std::max((eps * 256 + 2 * std::abs(nd.value)) * std::numeric_limits<double>::epsilon(),
                   kTiny);
    // The smallest radius at which every sample differs from the node's value by more than
    // rounding decides: small enough to see only this node, large enough to be above rounding.
    for (double r : {1e-5, 3e-5, 1e-4, 3e-4, 1e-3, 3e-3, 1e-2}) {
      if (r > ring.max_radius)
        break;
      bool flat = false;
      for (std::size_t j = 0; j < ring.samples.size() && !flat; ++j) {
        const auto &s = ring.samples[j];
        const double x = s.base[0] + r * s.dir[0], y = s.base[1] + r * s.dir[1];
        const double d = poly(s.cell)(std::max(0.0, x), std::max(0.0, y)) - relative;
        if (!(std::abs(d) > eps))
          flat = true;
        sign[j] = d > 0 ? 1 : -1;
      }
      if (flat)
        continue;
      conclusive = true;
      const Sectors sec = count_sectors(sign, ring.closed);
      if (type_matches(nd.type, sec, ring.closed) && down <= sec.lower && up <= sec.upper &&
          (!ring.closed || !sphere_ || nd.type != NodeType::Saddle || up + down == sec.lower + 1)) {
        ++report_.nodes_checked;
        return;
      }
      seen = std::to_string(sec.lower) + " lower and " + std::to_string(sec.upper) +
             " upper sector(s) at radius " + fmt(r);
      const int64_t near = other_node_within(i, r);
      if (near >= 0) {
        skip(i, node_str(i) + ": " + node_str(near) +
                    " is too close to tell their neighbourhoods apart (skipped; " + seen + ")");
        return;
      }
      break;
    }
    // Inside a cell, sectors narrower than the samples' spacing (the cusps of a degenerate
    // critical point) are seen exactly: the sign arcs of f - value on the boundaries of squares
    // around the node, from the roots of f - value on their sides.
    if (ring.closed && ring.max_radius >= 1e-5) {
      thread_local std::vector<SignArc> arcs;
      const BernsteinTriangle &g = poly(nd.cell);
      for (double r : {1e-4, 1e-3, 1e-2}) {
        if (r > 0.5 * ring.max_radius)
          break;
        for (double angle : {0.0, 0.3}) { // turned if a zero line runs through a corner
          if (!sign_arcs_on_square(g, {u, v}, r, relative, eps, arcs, angle))
            continue;
          Sectors sec{0, 0};
          for (const SignArc &a : arcs)
            ++(a.lower ? sec.lower : sec.upper);
          if (type_matches(nd.type, sec, true) && down <= sec.lower && up <= sec.upper) {
            ++report_.nodes_checked;
            return;
          }
          break;
        }
      }
    }
    if (ring.max_radius < 1e-5) {
      skip(i, node_str(i) + ": too close to a cell corner or side to sample around it (skipped)");
      return;
    }
    if (!conclusive) {
      skip(i, node_str(i) + ": the field is flat around it to rounding (a contracted plateau or "
                            "a degenerate critical point; skipped)");
      return;
    }
    fail("type", {i}, {},
         node_str(i) + " (" + to_string(nd.location) + " of cell " + std::to_string(nd.cell) +
             ") is a " + to_string(nd.type) + " with " + std::to_string(down) +
             " arc(s) down and " + std::to_string(up) + " up, but the field around it has " + seen);
  }

  // On a closed ring (inside the surface) a regular node has one lower and one upper sector. On
  // the boundary (open ring) two lower sectors already joined below are regular too.
  // Another node whose position is within about the sampling radius r (parameter units, scaled
  // by the cell's Jacobian) of node i, or -1.
  int64_t other_node_within(int64_t i, double r) const {
    const TreeNode &nd = tree_.nodes[i];
    const auto j = mesh_.geometry.jacobian(nd.cell, nd.uv[0], nd.uv[1]);
    const double scale =
        std::max(std::hypot(j[0][0], j[0][1], j[0][2]), std::hypot(j[1][0], j[1][1], j[1][2]));
    const double reach = 4 * r * scale;
    for (int64_t k = 0; k < n_; ++k) {
      const Vec3 &p = tree_.nodes[k].position;
      if (k != i &&
          std::hypot(p[0] - nd.position[0], p[1] - nd.position[1], p[2] - nd.position[2]) <= reach)
        return k;
    }
    return -1;
  }

  static bool type_matches(NodeType type, const Sectors &s, bool closed) {
    switch (type) {
    case NodeType::Minimum:
      return s.lower == 0;
    case NodeType::Maximum:
      return s.upper == 0;
    case NodeType::Regular:
      return closed ? s.lower == 1 && s.upper == 1 : s.lower >= 1 && s.upper >= 1;
    case NodeType::Saddle:
      return s.lower >= 2 || s.upper >= 2;
    }
    return false;
  }

  void skip(int64_t i, const std::string &msg) {
    report_.skipped.push_back({"type", {i}, {}, msg});
  }

  static std::string fmt(double x) {
    std::ostringstream s;
    s.precision(17);
    s << x;
    return s.str();
  }

  const TreeResult &tree_;
  const Mesh &mesh_;
  const TreeCheckOptions &opt_;
  const int64_t n_;
  double scale_ = 1;
  bool placement_failed_ = false;
  // On a sphere an inner saddle with k lower and k upper sectors has exactly k + 1 arcs (each
  // lower sector joined below cuts the sphere); on a disk the boundary allows up to 2k.
  bool sphere_ = false;
  int64_t max_loops_ = 0;               // of a Reeb graph on this surface (max_reeb_loops)
  std::vector<std::array<int, 2>> deg_; // up, down
  // Nodes with an arc of length zero (to flat-region rounding): a flat region left uncontracted
  // (--keep-flat, the augmented tree), such as a ridge's pieces cell by cell.
  std::vector<char> flat_end_;
  std::vector<int64_t> vertex_offset_;
  std::vector<std::pair<int64_t, int>> vertex_cells_;
  TreeCheckReport report_;
};

} // namespace

std::string TreeCheckReport::summary(std::size_t max_lines) const {
  std::ostringstream s;
  for (std::size_t i = 0; i < failures.size() && i < max_lines; ++i)
    s << "FAIL [" << failures[i].check << "] " << failures[i].message << "\n";
  if (failures.size() > max_lines)
    s << "... and " << failures.size() - max_lines << " more failure(s)\n";
  s << failures.size() << " failure(s), " << nodes_checked
    << " node type(s) confirmed by samples of the field, " << skipped.size() << " skipped\n";
  return s.str();
}

TreeCheckReport check_tree(const TreeResult &tree, const Mesh &mesh,
                           const TreeCheckOptions &options) {
  if (mesh.origins.identity())
    return Checker(tree, mesh, options).run();
  // The tree names input cells (a quadrilateral as such); the checks look at the mesh's
  // triangles (mesh/cell_split). A cell the input does not have stays out of range.
  TreeResult local = tree;
  for (TreeNode &n : local.nodes)
    if (n.cell >= 0) {
      const CellPlace p = mesh.origins.to_mesh(n.cell, n.uv);
      n.cell = p.cell >= 0 ? p.cell : mesh.topology.num_cells();
      n.uv = p.uv;
    }
  return Checker(local, mesh, options).run();
}

} // namespace hoct
