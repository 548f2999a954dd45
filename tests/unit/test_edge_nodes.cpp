// Edge critical points (find_edge_nodes): against sign changes of the edge derivative sampled
// finely, and the same nodes, bit for bit, on any thread count (on enough edges that both of
// its passes run on every thread).
#include "cell/edge_nodes.hpp"
#include "datasets/datasets.hpp"
#include "mesh/mesh.hpp"
#include "poly/bernstein_univariate.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <vector>

namespace hoct {
namespace {

Mesh random_mesh(long long cells, int degree) {
  DatasetOptions o;
  o.cells = cells;
  o.degree = degree;
  return build_mesh(generate_dataset("random", o));
}

// Sign changes of the derivative of edge polynomial c at 2001 equally spaced parameters.
int sampled_derivative_sign_changes(std::span<const double> c) {
  const int n = static_cast<int>(c.size()) - 1;
  std::vector<double> d(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i)
    d[i] = n * (c[i + 1] - c[i]);
  int changes = 0, last = 0;
  for (int k = 0; k <= 2000; ++k) {
    const double x = bernstein_value(d, k / 2000.0);
    const int s = (x > 0) - (x < 0);
    if (s != 0 && last != 0 && s != last)
      ++changes;
    if (s != 0)
      last = s;
  }
  return changes;
}

TEST(EdgeNodes, OneNodePerSignChangeOfTheDerivative) {
  for (int degree : {2, 3, 5}) {
    const Mesh mesh = random_mesh(4000, degree);
    const EdgeNodes en = find_edge_nodes(mesh.topology, mesh.field);
    int64_t with_nodes = 0;
    for (int64_t e = 0; e < mesh.topology.num_edges(); ++e) {
      ASSERT_EQ(en.degeneracy[e], kEdgeOk) << "degree " << degree << " edge " << e;
      const std::span<const double> c = mesh.field.edge_coefficients(e);
      ASSERT_EQ(en.count(e), sampled_derivative_sign_changes(c))
          << "degree " << degree << " edge " << e;
      for (int64_t i = en.offset[e]; i < en.offset[e + 1]; ++i) {
        const EdgeNode &node = en.nodes[i];
        EXPECT_TRUE(node.simple);
        EXPECT_GT(node.t, 0.0);
        EXPECT_LT(node.t, 1.0);
        EXPECT_DOUBLE_EQ(node.value, bernstein_value(c, node.t));
        if (i > en.offset[e]) {
          EXPECT_LT(en.nodes[i - 1].t, node.t);
        }
      }
      with_nodes += en.count(e) > 0;
    }
    EXPECT_GT(with_nodes, 100) << "degree " << degree; // the test sees nodes at all
  }
}

TEST(EdgeNodes, SameOnAnyThreadCount) {
  // ~60,000 edges: the node pass and the combining pass (from 16,384 edges per thread) both run
  // on every thread.
  const Mesh mesh = random_mesh(40000, 3);
  ASSERT_GT(mesh.topology.num_edges(), 3 * 16384);
  EdgeNodeOptions one;
  const EdgeNodes a = find_edge_nodes(mesh.topology, mesh.field, one);
  ASSERT_GT(a.nodes.size(), 1000u);
  for (int threads : {2, 3}) {
    EdgeNodeOptions o;
    o.threads = threads;
    const EdgeNodes b = find_edge_nodes(mesh.topology, mesh.field, o);
    ASSERT_EQ(b.nodes.size(), a.nodes.size()) << threads;
    for (int64_t e = 0; e < mesh.topology.num_edges(); ++e) {
      ASSERT_EQ(b.offset[e + 1], a.offset[e + 1]) << threads << " edge " << e;
      ASSERT_EQ(b.degeneracy[e], a.degeneracy[e]) << threads << " edge " << e;
    }
    for (std::size_t i = 0; i < a.nodes.size(); ++i) {
      EXPECT_EQ(std::memcmp(&b.nodes[i].t, &a.nodes[i].t, sizeof(double)), 0) << i;
      EXPECT_EQ(std::memcmp(&b.nodes[i].value, &a.nodes[i].value, sizeof(double)), 0) << i;
      EXPECT_EQ(std::memcmp(&b.nodes[i].second, &a.nodes[i].second, sizeof(double)), 0) << i;
      EXPECT_EQ(b.nodes[i].simple, a.nodes[i].simple) << i;
    }
  }
}

} // namespace
} // namespace hoct
