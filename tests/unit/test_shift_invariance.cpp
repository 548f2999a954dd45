// Adding a constant to a field does not change its tree: every generated dataset shifted by
// 1e3 ... 1e9 times its range, and squeezed to a range of 1e-10 around 1 (as kelvin or pascal
// data are), gives the persistence diagram of the unshifted field within the precision the
// shifted doubles resolve (the reported Field::precision: the stability of persistence diagrams
// bounds the bottleneck distance by the field's change), reports that precision, flags the
// pairs below it, and has the same fallback counts where the doubles resolve the field.
#include "datasets/datasets.hpp"
#include "mesh/mesh.hpp"
#include "pipeline/compute_tree.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <tuple>
#include <vector>

namespace hoct {
namespace {

struct Variant {
  double scale, offset; // values v become scale * v + offset
};

MeshInput dataset(const std::string &name, const Variant &v) {
  DatasetOptions o;
  if (name == "random")
    o.cells = 2000;
  o.scale = v.scale;
  o.offset = v.offset;
  return generate_dataset(name, o);
}

TreeResult exact_tree(const MeshInput &input) {
  const Mesh mesh = build_mesh(input);
  TreeRequest rq;
  return compute_tree(mesh, rq, &input).tree;
}

// The diagram of `t` in the unshifted field's units: ((birth - offset) / scale, ...).
std::vector<std::array<double, 2>> diagram(const TreeResult &t, const Variant &v) {
  std::vector<std::array<double, 2>> d;
  for (const auto &p : t.pairs)
    d.push_back({(p.birth_value - v.offset) / v.scale, (p.death_value - v.offset) / v.scale});
  return d;
}

double range_of(const MeshInput &m) {
  const auto [lo, hi] = std::minmax_element(m.values.begin(), m.values.end());
  return *hi - *lo;
}

class ShiftInvariance : public ::testing::TestWithParam<std::string> {};

TEST_P(ShiftInvariance, OffsetsUpToABillionRangesGiveTheSameDiagram) {
  const std::string name = GetParam();
  const MeshInput base_input = dataset(name, {1, 0});
  const double range = range_of(base_input);
  const TreeResult base = exact_tree(base_input);
  ASSERT_TRUE(base.stats.precision);
  ASSERT_TRUE(base.stats.exact);
  EXPECT_LT(*base.stats.precision, 1e-10 * range);
  const auto base_diagram = diagram(base, {1, 0});
  for (double k : {1e3, 1e5, 1e7, 1e9}) {
    SCOPED_TRACE("offset " + std::to_string(k) + " x range");
    const Variant v{1, k * range};
    const TreeResult t = exact_tree(dataset(name, v));
    ASSERT_TRUE(t.stats.precision && t.stats.exact);
    const double precision = *t.stats.precision;
    // The input's doubles near k * range are spaced about eps * k * range apart.
    EXPECT_GE(precision, std::numeric_limits<double>::epsilon() * k * range);
    EXPECT_LE(precision, 1e3 * std::numeric_limits<double>::epsilon() * k * range);
    EXPECT_LE(bottleneck_distance(base_diagram, diagram(t, v)), precision);
    // Every pair at or below the precision is flagged, none above it.
    int64_t below = 0;
    for (const auto &p : t.pairs)
      below += p.persistence() <= precision;
    EXPECT_EQ(t.stats.pairs_below_precision.value_or(-1), below);
    EXPECT_EQ(t.stats.exact->fallback_cells, base.stats.exact->fallback_cells);
    EXPECT_EQ(t.stats.exact->fallback_by_reason, base.stats.exact->fallback_by_reason);
  }
}

TEST_P(ShiftInvariance, ARangeOfTenToTheMinusTenAroundOne) {
  const std::string name = GetParam();
  const TreeResult base = exact_tree(dataset(name, {1, 0}));
  const Variant v{1e-10, 1};
  const TreeResult t = exact_tree(dataset(name, v));
  ASSERT_TRUE(t.stats.precision);
  // The precision in the unshifted field's units: about eps / 1e-10 times the degree's
  // conversion norm, far coarser than the unshifted field's own.
  const double precision = *t.stats.precision / v.scale;
  EXPECT_GE(precision, std::numeric_limits<double>::epsilon() / v.scale);
  EXPECT_LE(bottleneck_distance(diagram(base, {1, 0}), diagram(t, v)), precision);
  // Pairs above the precision: as many as the unshifted field has above it, give or take those
  // the rounding moves across it.
  auto above = [](const TreeResult &r, double scale, double p) {
    int64_t n = 0;
    for (const auto &x : r.pairs)
      n += x.persistence() / scale > p;
    return n;
  };
  EXPECT_LE(above(base, 1, 2 * precision), above(t, v.scale, precision));
  EXPECT_LE(above(t, v.scale, 2 * precision), above(base, 1, precision));
}

INSTANTIATE_TEST_SUITE_P(Datasets, ShiftInvariance,
                         ::testing::Values("gauss", "heater", "random", "sphere", "two-triangle"),
                         [](const auto &info) {
                           std::string s = info.param;
                           std::replace(s.begin(), s.end(), '-', '_');
                           return s;
                         });

// The conductor: its exact ridges are critical curves and the constant edges around its plateau
// level edges, shifted or not; only the plateau's constant cells fall back (exactly: no slack).
// What stays: the same fallback cells and level edges, the same node types, and every pair one
// tree is certain of (not flagged uncertain) in the other, within the precision.
TEST(ShiftInvariance, TheConductorKeepsItsCertainPairs) {
  const TreeResult base = exact_tree(dataset("conductor", {1, 0}));
  const double range = base.nodes.back().value - base.nodes.front().value;
  for (double k : {1e3, 1e5, 1e7}) {
    SCOPED_TRACE("offset " + std::to_string(k) + " x range");
    const Variant v{1, k * range};
    const TreeResult t = exact_tree(dataset("conductor", v));
    ASSERT_TRUE(t.stats.exact && base.stats.exact && t.stats.precision);
    // Its ridges are critical curves at every offset (the rounding tilts them by less than the
    // precision): only the plateau's cells fall back, the same ones.
    EXPECT_EQ(t.stats.exact->fallback_by_reason, base.stats.exact->fallback_by_reason);
    EXPECT_EQ(t.stats.exact->fallback_cells, base.stats.exact->fallback_cells);
    EXPECT_EQ(t.stats.exact->level_edges, base.stats.exact->level_edges);
    EXPECT_GT(t.stats.exact->level_edges, 0);
    EXPECT_EQ(t.stats.exact->fallback_cells,
              t.stats.exact->fallbacks(FallbackReason::ConstantCell));
    EXPECT_EQ(t.stats.exact->fallback_error, 0);
    ASSERT_EQ(t.nodes.size(), base.nodes.size());
    for (std::size_t i = 0; i < t.nodes.size(); ++i)
      EXPECT_EQ(t.nodes[i].type, base.nodes[i].type) << "node " << i;
    const double tol =
        *t.stats.precision + *base.stats.precision +
        2 * std::max(t.stats.exact->fallback_error, base.stats.exact->fallback_error);
    auto has_partner = [&](const std::array<double, 2> &p, const TreeResult &other,
                           const Variant &ov) {
      for (const auto &q : diagram(other, ov))
        if (std::abs(q[0] - p[0]) <= tol && std::abs(q[1] - p[1]) <= tol)
          return true;
      return false;
    };
    int64_t certain = 0;
    for (const auto &[tree, var, other, ovar] :
         {std::tuple{&base, Variant{1, 0}, &t, v}, std::tuple{&t, v, &base, Variant{1, 0}}})
      for (const auto &p : tree->pairs)
        if (!tree->uncertain(p)) {
          ++certain;
          const std::array<double, 2> d = {(p.birth_value - var.offset) / var.scale,
                                           (p.death_value - var.offset) / var.scale};
          EXPECT_TRUE(has_partner(d, *other, ovar))
              << "pair (" << d[0] << ", " << d[1] << "), persistence " << p.persistence();
        }
    EXPECT_GT(certain, 20);
  }
}

// The reference keeps vertex values exact: (x - c) + c == x for every node value x.
TEST(Reference, ShiftsOnlyFarFromZeroAndExactly) {
  EXPECT_EQ(reference_value(0, 3.5), 0);
  EXPECT_EQ(reference_value(-1, 1), 0);
  EXPECT_EQ(reference_value(1e7, 1e7 + 3), 1e7 + 1.5);
  EXPECT_EQ(reference_value(-1e7 - 3, -1e7), -1e7 - 1.5);
  const MeshInput in = dataset("heater", {1, 1e7});
  const Mesh mesh = build_mesh(in);
  const double c = mesh.field.reference();
  EXPECT_NE(c, 0);
  for (int64_t v = 0; v < mesh.topology.num_vertices(); ++v)
    ASSERT_EQ(mesh.field.vertex_value(v) + c, in.values[mesh.topology.vertex_point(v)]);
  // The exact tree's vertex nodes report the input's values, bit for bit.
  const TreeResult t = exact_tree(in);
  int vertices = 0;
  for (const auto &n : t.nodes)
    if (n.location == NodeLocation::Vertex) {
      ++vertices;
      bool found = false;
      for (double x : in.values)
        found |= x == n.value;
      EXPECT_TRUE(found) << n.value;
    }
  EXPECT_GT(vertices, 0);
}

} // namespace
} // namespace hoct
