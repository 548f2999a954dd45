#include "cell/edge_nodes.hpp"

#include "poly/root_isolation.hpp"
#include "util/parallel_for.hpp"

#include <algorithm>
#include <cmath>

namespace hoct {

namespace {

// The nodes of one edge (ascending t) and its degeneracy bits.
uint8_t edge_nodes_of(const BernsteinPoly &p, double value_scale, const EdgeNodeOptions &opt,
                      std::vector<EdgeNode> &nodes) {
  uint8_t deg = kEdgeOk;
  if (p.degree() < 1)
    return deg;
  const BernsteinPoly dp = p.derivative();
  // A constant edge (derivative zero up to rounding of the values).
  double dscale = 0, pscale = 0;
  for (double c : dp.coefficients())
    dscale = std::max(dscale, std::abs(c));
  for (double c : p.coefficients())
    pscale = std::max(pscale, std::abs(c));
  if (dscale <= 1e-12 * pscale)
    return deg | kEdgeConstant;
  const std::vector<Root> roots = find_roots(dp);
  if (roots.empty())
    return deg;
  const BernsteinPoly ddp = dp.derivative();
  for (const Root &r : roots) {
    if (r.t <= opt.vertex_tolerance || r.t >= 1 - opt.vertex_tolerance) {
      deg |= kEdgeRootAtVertex;
      continue; // the vertex itself is the node
    }
    const double second = ddp(r.t);
    if (!r.simple)
      deg |= kEdgeMultipleRoot;
    else if (std::abs(second) <= opt.flat_tolerance * value_scale)
      deg |= kEdgeFlatCriticalPoint;
    nodes.push_back({r.t, p(r.t), second, r.simple});
  }
  return deg;
}

// Most edges of a smooth field are strictly monotone: edge_nodes_of would find a derivative that
// is neither constant (at rounding level) nor has a root (certainly_rootless, the test
// find_roots starts with). Decided here without building the polynomials.
bool monotone(std::span<const double> c) {
  if (c.size() < 2)
    return false;
  constexpr std::size_t kSmall = 32;
  double small[kSmall];
  std::vector<double> large;
  double *d = small;
  if (c.size() - 1 > kSmall) {
    large.resize(c.size() - 1);
    d = large.data();
  }
  const int n = static_cast<int>(c.size()) - 1;
  double dscale = 0, pscale = 0;
  for (int i = 0; i < n; ++i) {
    d[i] = n * (c[i + 1] - c[i]); // as BernsteinPoly::derivative
    dscale = std::max(dscale, std::abs(d[i]));
  }
  for (double x : c)
    pscale = std::max(pscale, std::abs(x));
  return !(dscale <= 1e-12 * pscale) && certainly_rootless({d, static_cast<std::size_t>(n)});
}

} // namespace

EdgeNodes find_edge_nodes(const Topology &topo, const Field &field, const EdgeNodeOptions &opt) {
  const int64_t ne = topo.num_edges();
  EdgeNodes out;
  out.offset.resize(ne + 1);
  out.degeneracy.resize(ne);
  const double value_scale = std::max({std::abs(field.min_value()), std::abs(field.max_value()),
                                       field.max_value() - field.min_value(), 1e-300});
  // Fixed blocks of edges, each collecting its own nodes (counts first in offset[e + 1]); then
  // every block's offsets and nodes placed by prefix sums over the blocks, in parallel: the
  // result does not depend on the thread count.
  const int64_t blocks = std::max<int64_t>(1, std::min<int64_t>(ne, 256));
  std::vector<std::vector<EdgeNode>> block_nodes(blocks);
  out.offset[0] = 0;
  parallel_for(blocks, opt.threads, [&](int64_t b0, int64_t b1, int) {
    for (int64_t b = b0; b < b1; ++b)
      for (int64_t e = ne * b / blocks; e < ne * (b + 1) / blocks; ++e) {
        const std::size_t before = block_nodes[b].size();
        uint8_t degeneracy = kEdgeOk;
        if (!monotone(field.edge_coefficients(e)))
          degeneracy = edge_nodes_of(field.edge_polynomial(e), value_scale, opt, block_nodes[b]);
        out.degeneracy[e] = degeneracy;
        out.offset[e + 1] = static_cast<int64_t>(block_nodes[b].size() - before);
      }
  });
  std::vector<int64_t> block_base(blocks + 1, 0);
  for (int64_t b = 0; b < blocks; ++b)
    block_base[b + 1] = block_base[b] + static_cast<int64_t>(block_nodes[b].size());
  out.nodes.resize(static_cast<std::size_t>(block_base[blocks]));
  parallel_for(blocks, threads_for(ne, opt.threads, 65536), [&](int64_t b0, int64_t b1, int) {
    for (int64_t b = b0; b < b1; ++b) {
      int64_t sum = block_base[b];
      for (int64_t e = ne * b / blocks; e < ne * (b + 1) / blocks; ++e) {
        sum += out.offset[e + 1];
        out.offset[e + 1] = sum;
      }
      std::copy(block_nodes[b].begin(), block_nodes[b].end(),
                out.nodes.begin() + static_cast<std::ptrdiff_t>(block_base[b]));
    }
  });
  return out;
}

} // namespace hoct
