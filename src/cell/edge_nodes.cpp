#include "cell/edge_nodes.hpp"

#include "poly/degree_dispatch.hpp"
#include "poly/root_isolation.hpp"
#include "util/parallel_for.hpp"

#include <algorithm>
#include <cmath>

namespace hoct {

namespace {

// The nodes of edge polynomial p (ascending t) and its degeneracy bits. Most edges of a smooth
// field are strictly monotone: they are decided on the coefficients without building anything
// (the derivative neither constant at rounding level nor near zero anywhere, the test
// find_roots starts with). The rest works in per-thread buffers: no allocation per edge.
uint8_t edge_nodes_of(std::span<const double> p, double value_scale, const EdgeNodeOptions &opt,
                      UninitializedVector<EdgeNode> &nodes) {
  uint8_t deg = kEdgeOk;
  const int n = static_cast<int>(p.size()) - 1;
  if (n < 1)
    return deg;
  // One unrolled pass for the common degrees: the extremes and largest magnitude of the
  // derivative's coefficients n (p[i+1] - p[i]) (as bernstein_derivative), and the values'
  // largest magnitude; most edges are decided there.
  double dscale = 0, dlo = INFINITY, dhi = -INFINITY, pscale = std::abs(p[0]);
  dispatch_degree(n, [&](auto D) {
    const int m = D.value >= 0 ? D.value : n;
#pragma GCC unroll 16
    for (int i = 0; i < m; ++i) {
      const double x = m * (p[i + 1] - p[i]);
      dscale = std::max(dscale, std::abs(x));
      dlo = std::min(dlo, x);
      dhi = std::max(dhi, x);
      pscale = std::max(pscale, std::abs(p[i + 1]));
    }
  });
  // A constant edge (derivative zero up to rounding of the values).
  if (dscale <= 1e-12 * pscale)
    return deg | kEdgeConstant;
  // Strictly monotone beyond find_roots' tangency threshold.
  if (certainly_rootless(dlo, dhi, dscale))
    return deg;
  thread_local std::vector<double> dp, ddp;
  thread_local std::vector<Root> roots;
  dp.resize(static_cast<std::size_t>(n));
  bernstein_derivative(p, dp.data());
  find_roots(dp, roots);
  if (roots.empty())
    return deg;
  // The second derivative (as BernsteinPoly::derivative: the zero constant below degree 2).
  ddp.assign(1, 0.0);
  if (n >= 2) {
    ddp.resize(static_cast<std::size_t>(n - 1));
    bernstein_derivative(dp, ddp.data());
  }
  for (const Root &r : roots) {
    if (r.t <= opt.vertex_tolerance || r.t >= 1 - opt.vertex_tolerance) {
      deg |= kEdgeRootAtVertex;
      continue; // the vertex itself is the node
    }
    const double second = bernstein_value(ddp, r.t);
    if (!r.simple)
      deg |= kEdgeMultipleRoot;
    else if (std::abs(second) <= opt.flat_tolerance * value_scale)
      deg |= kEdgeFlatCriticalPoint;
    nodes.push_back({r.t, bernstein_value(p, r.t), second, r.simple});
  }
  return deg;
}

} // namespace

EdgeNodes find_edge_nodes(const Topology &topo, const Field &field, const EdgeNodeOptions &opt) {
  const int64_t ne = topo.num_edges();
  EdgeNodes out;
  out.offset.resize(ne + 1);
  out.degeneracy.resize(ne);
  // The magnitude of the (relative) values the edge polynomials hold, and at least the range.
  const double value_scale = field.value_scale();
  // Fixed blocks of edges; each worker appends its blocks' nodes to a buffer of its own (counts
  // first in offset[e + 1], and where each block's nodes start); then every block's offsets and
  // nodes are placed by prefix sums over the blocks, in parallel: the result does not depend on
  // the thread count, and there are a few growing buffers instead of one per block.
  const int64_t blocks = std::max<int64_t>(1, std::min<int64_t>(ne, 256));
  const int threads = std::max(1, opt.threads);
  // Each worker's buffer on a cache line of its own: side by side, the vectors' end pointers,
  // written at every push, would share a line between the threads (pushes are rare, but the
  // padding costs nothing).
  struct alignas(64) WorkerNodes {
    UninitializedVector<EdgeNode> nodes;
  };
  std::vector<WorkerNodes> worker_nodes(static_cast<std::size_t>(threads));
  struct BlockSource {
    int worker;
    std::size_t begin, count;
  };
  std::vector<BlockSource> source(static_cast<std::size_t>(blocks));
  out.offset[0] = 0;
  parallel_for(blocks, threads, [&](int64_t b0, int64_t b1, int worker) {
    UninitializedVector<EdgeNode> &nodes = worker_nodes[static_cast<std::size_t>(worker)].nodes;
    for (int64_t b = b0; b < b1; ++b) {
      const std::size_t begin = nodes.size();
      // The block's bounds in locals: in the condition they would be a 64-bit division per
      // edge (the stores below may alias them).
      const int64_t first = ne * b / blocks, last = ne * (b + 1) / blocks;
      for (int64_t e = first; e < last; ++e) {
        const std::size_t before = nodes.size();
        out.degeneracy[e] = edge_nodes_of(field.edge_coefficients(e), value_scale, opt, nodes);
        out.offset[e + 1] = static_cast<int64_t>(nodes.size() - before);
      }
      source[b] = {worker, begin, nodes.size() - begin};
    }
  });
  std::vector<int64_t> block_base(blocks + 1, 0);
  for (int64_t b = 0; b < blocks; ++b)
    block_base[b + 1] = block_base[b] + static_cast<int64_t>(source[b].count);
  // One worker's buffer holding every block in order (one thread) becomes the list itself.
  bool in_order = true;
  for (int64_t b = 0; b < blocks; ++b)
    in_order = in_order && source[b].worker == 0 &&
               source[b].begin == static_cast<std::size_t>(block_base[b]);
  if (in_order)
    out.nodes = std::move(worker_nodes[0].nodes);
  else
    out.nodes.resize(static_cast<std::size_t>(block_base[blocks]));
  parallel_for(blocks, threads_for(ne, opt.threads, 16384), [&](int64_t b0, int64_t b1, int) {
    for (int64_t b = b0; b < b1; ++b) {
      int64_t sum = block_base[b];
      const int64_t first = ne * b / blocks, last = ne * (b + 1) / blocks;
      for (int64_t e = first; e < last; ++e) {
        sum += out.offset[e + 1];
        out.offset[e + 1] = sum;
      }
      const BlockSource &src = source[b];
      if (in_order)
        continue;
      const auto from = worker_nodes[static_cast<std::size_t>(src.worker)].nodes.begin() +
                        static_cast<std::ptrdiff_t>(src.begin);
      std::copy(from, from + static_cast<std::ptrdiff_t>(src.count),
                out.nodes.begin() + static_cast<std::ptrdiff_t>(block_base[b]));
    }
  });
  return out;
}

} // namespace hoct
