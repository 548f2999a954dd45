// Independent truth for exact trees: the PL trees of ever finer refinements of the same field
// (k x k sub-triangles per cell, k = 4, 16, 64) converge to the exact tree, their diagrams'
// bottleneck distance to it not growing and ending below 1e-3.
#pragma once

#include "mesh/mesh.hpp"
#include "pipeline/compute_tree.hpp"
#include "tree/persistence.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

namespace hoct::testing {

inline std::vector<std::array<double, 2>> pair_diagram(const TreeResult &t) {
  std::vector<std::array<double, 2>> d;
  for (const auto &p : t.pairs)
    d.push_back({p.birth_value, p.death_value});
  return d;
}

inline void expect_refinements_converge(const Mesh &mesh, const MeshInput &input,
                                        const TreeResult &exact) {
  double last = INFINITY;
  for (int k : {4, 16, 64}) {
    TreeRequest rq;
    rq.method = TreeMethod::Refine;
    rq.refine = k;
    const double d =
        bottleneck_distance(pair_diagram(exact), pair_diagram(compute_tree(mesh, rq, &input).tree));
    EXPECT_LE(d, last * 1.0001 + 1e-12) << "k=" << k;
    last = d;
  }
  EXPECT_LT(last, 1e-3);
}

} // namespace hoct::testing
