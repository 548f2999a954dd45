#include "tree/sweep_contour_tree.hpp"

#include "util/page_pool.hpp"
#include "util/parallel_for.hpp"
#include "util/stopwatch.hpp"
#include "util/uninitialized_vector.hpp"

#include <algorithm>
#include <array>
#include <initializer_list>
#include <stdexcept>

namespace hoct {
namespace {

using clock_type = Stopwatch::clock;

// Augmented merge tree in rank space (indices of type I: 32 bits when they fit, halving the
// memory the sweeps touch at random): parent[r] is the rank of r's parent, -1 at a root;
// children[r] counts the ranks whose parent is r.
template <class I> struct RankTree {
  UninitializedVector<I> parent;
  UninitializedVector<int32_t> children;
};

// Scratch memory of the sweeps on one thread, kept for its next sweep: first touching fresh
// pages costs about as much as the work done in them. Kept between calls too, up to
// kKeptScratchBytes (on graphs of thousands of nodes the allocator would otherwise return the
// pages at the end of every call and fault them in again at the next).
template <class I> struct SweepScratch {
  UninitializedVector<I> pairs; // (higher, lower) rank pairs, by window of higher ranks
  UninitializedVector<I> sets;  // the union-find's parent, size and top arrays
  UninitializedVector<I> lower; // one window's lower neighbours, by higher rank
  void reserve(int64_t n, std::size_t edges) {
    pairs.clear(); // nothing of the last sweep to keep (reserve would copy it)
    sets.clear();
    pairs.reserve(2 * edges);
    sets.reserve(3 * static_cast<std::size_t>(n));
  }
  std::size_t bytes() const {
    return (pairs.capacity() + sets.capacity() + lower.capacity()) * sizeof(I);
  }
};
constexpr std::size_t kKeptScratchBytes = std::size_t{16} << 20;
template <class I> SweepScratch<I> &thread_scratch() {
  thread_local SweepScratch<I> scratch;
  return scratch;
}

// Calls f(rank of a, rank of b) for every piece (a, b) of every chain not skipped (each node's
// rank looked up once), in runs of chains between skipped ones.
template <class ToRank, class F>
void for_each_chain_piece(const EdgeChains &chains, const ToRank &to_rank, const F &f) {
  const int64_t count = static_cast<int64_t>(chains.ends.size());
  const int64_t *offset = chains.offset.data();
  const std::array<int64_t, 2> *ends = chains.ends.data();
  int64_t i = 0;
  for (std::size_t s = 0; s <= chains.skip.size(); ++s) {
    const int64_t stop = s < chains.skip.size() ? chains.skip[s] : count;
    int64_t lo = i < count ? offset[i] : 0;
    for (; i < stop; ++i) {
      const int64_t hi = offset[i + 1];
      auto prev = to_rank(ends[i][0]);
      for (int64_t k = lo; k < hi; ++k) {
        const auto r = to_rank(chains.first + k);
        f(prev, r);
        prev = r;
      }
      f(prev, to_rank(ends[i][1]));
      lo = hi;
    }
    i = stop + 1;
  }
}

// The sweep upwards over ranks 0..n-1 of the graph whose edges (all lists and the chains),
// mapped to ranks by `to_rank`, connect each rank to its lower neighbours: when a component meets
// the current rank, the component's highest node so far gets the current rank as its parent.
template <class I, class ToRank>
RankTree<I> sweep_up(int64_t n, std::initializer_list<std::span<const GraphEdge>> lists,
                     const EdgeChains &chains, const ToRank &to_rank, SweepScratch<I> &scratch) {
  // Ranks are scattered at random over the mesh, so the edges are first distributed (as
  // (higher, lower) rank pairs) into windows of 4096 ranks; each window's pairs are then sorted
  // by higher rank with their counters in cache, and its ranks swept.
  constexpr int kWindowBits = 12;
  const int64_t windows = (n >> kWindowBits) + 1;
  std::vector<int64_t> window_start(windows + 1, 0);
  auto count = [&](I ra, I rb) {
    if (ra != rb)
      ++window_start[(std::max(ra, rb) >> kWindowBits) + 1];
  };
  for (std::span<const GraphEdge> edges : lists)
    for (const GraphEdge &e : edges)
      count(to_rank(e.a), to_rank(e.b));
  for_each_chain_piece(chains, to_rank, count);
  for (int64_t w = 1; w <= windows; ++w)
    window_start[w] += window_start[w - 1];
  const std::size_t m = static_cast<std::size_t>(window_start[windows]);
  auto &pairs = scratch.pairs, &lower = scratch.lower;
  pairs.resize(2 * m);
  {
    std::vector<int64_t> fill(window_start.begin(), window_start.end() - 1);
    auto place = [&](I ra, I rb) {
      if (ra != rb) {
        I *p = &pairs[2 * fill[std::max(ra, rb) >> kWindowBits]++];
        p[0] = std::max(ra, rb);
        p[1] = std::min(ra, rb);
      }
    };
    for (std::span<const GraphEdge> edges : lists)
      for (const GraphEdge &e : edges)
        place(to_rank(e.a), to_rank(e.b));
    for_each_chain_piece(chains, to_rank, place);
  }
  RankTree<I> t;
  t.parent.resize(static_cast<std::size_t>(n));
  std::fill(t.parent.begin(), t.parent.end(), I{-1});
  t.children.resize(static_cast<std::size_t>(n));
  std::fill(t.children.begin(), t.children.end(), 0);
  // Union by size with path halving; top[root] is the highest rank of the root's component so
  // far (the node whose parent the current rank becomes when that component joins it).
  scratch.sets.resize(3 * static_cast<std::size_t>(n));
  I *uf = scratch.sets.data(), *size = uf + n, *top = size + n;
  auto find = [&](I x) {
    while (uf[x] != x) {
      uf[x] = uf[uf[x]];
      x = uf[x];
    }
    return x;
  };
  std::array<I, (std::size_t{1} << kWindowBits) + 1> bound;
  for (int64_t w = 0; w < windows; ++w) {
    const int64_t r0 = w << kWindowBits, r1 = std::min(n, (w + 1) << kWindowBits);
    const int64_t k0 = window_start[w], k1 = window_start[w + 1];
    std::fill(bound.begin(), bound.begin() + (r1 - r0) + 1, I{0});
    for (int64_t k = k0; k < k1; ++k)
      ++bound[pairs[2 * k] - r0 + 1];
    for (int64_t j = 1; j <= r1 - r0; ++j)
      bound[j] += bound[j - 1];
    lower.resize(static_cast<std::size_t>(k1 - k0));
    for (int64_t k = k0; k < k1; ++k)
      lower[bound[pairs[2 * k] - r0]++] = pairs[2 * k + 1];
    // bound[j] is now the end of rank r0 + j's lower neighbours, bound[j - 1] their start.
    I begin = 0;
    for (I v = static_cast<I>(r0); v < static_cast<I>(r1); ++v) {
      uf[v] = v;
      size[v] = 1;
      top[v] = v;
      I rv = v; // v's root
      const I end = bound[v - r0];
      for (I k = begin; k < end; ++k) {
        const I r = find(lower[k]);
        if (r == rv)
          continue;
        t.parent[top[r]] = v;
        ++t.children[v];
        const I big = size[r] > size[rv] ? r : rv, small = big == r ? rv : r;
        uf[small] = big;
        size[big] += size[small];
        rv = big;
        top[rv] = v;
      }
      begin = end;
    }
  }
  return t;
}

} // namespace

namespace {

void check_edges(std::span<const GraphEdge> edges, int64_t n) {
  for (const GraphEdge &e : edges)
    if (e.a < 0 || e.b < 0 || e.a >= n || e.b >= n)
      throw std::out_of_range("sweep_contour_tree: edge endpoint out of range");
}

void check_chains(const EdgeChains &c, int64_t n) {
  const std::size_t count = c.ends.size();
  if (count == 0 && c.skip.empty())
    return;
  if (c.offset.size() != count + 1)
    throw std::invalid_argument("sweep_contour_tree: chain offsets do not match the chains");
  bool ascending = true;
  for (std::size_t i = 0; i < count; ++i)
    ascending &= c.offset[i + 1] >= c.offset[i];
  if (!ascending)
    throw std::invalid_argument("sweep_contour_tree: chain offsets not ascending");
  if (c.offset[0] < 0 || c.first < 0 || c.first > n - c.offset[count])
    throw std::out_of_range("sweep_contour_tree: chain node out of range");
  bool ends_in_range = true;
  for (const auto &e : c.ends)
    ends_in_range &= static_cast<uint64_t>(e[0]) < static_cast<uint64_t>(n) &&
                     static_cast<uint64_t>(e[1]) < static_cast<uint64_t>(n);
  if (!ends_in_range)
    throw std::out_of_range("sweep_contour_tree: chain end out of range");
  for (std::size_t i = 0; i < c.skip.size(); ++i)
    if ((i > 0 && c.skip[i] <= c.skip[i - 1]) || c.skip[i] < 0 ||
        c.skip[i] >= static_cast<int64_t>(count))
      throw std::invalid_argument("sweep_contour_tree: skipped chains not ascending chain numbers");
}

// The number of chain pieces (an upper bound where chains are skipped).
std::size_t chain_pieces(const EdgeChains &c) {
  return c.ends.empty() ? 0
                        : c.ends.size() + static_cast<std::size_t>(c.offset.back() - c.offset[0]);
}

// The join and split trees in rank space of the nodes in `order` (ascending).
template <class I> struct RankTrees {
  RankTree<I> join, split; // split in mirrored ranks n - 1 - r
};
template <class I>
RankTrees<I> sweep_both(std::span<const int64_t> order, const SweepEdges &edges, int threads) {
  const int64_t n = static_cast<int64_t>(order.size());
  UninitializedVector<I> rank;
  rank.resize(static_cast<std::size_t>(n));
  parallel_for(n, threads_for(n, threads, int64_t{1} << 16), [&](int64_t begin, int64_t end, int) {
    for (int64_t r = begin; r < end; ++r)
      rank[order[r]] = static_cast<I>(r);
  });
  const I last = static_cast<I>(n - 1);
  RankTrees<I> t;
  const int sweep_threads = std::min(threads, 2);
  const std::size_t max_edges = edges.common.size() + chain_pieces(edges.chains) +
                                std::max(edges.join_only.size(), edges.split_only.size());
  parallel_for(2, sweep_threads, [&](int64_t begin, int64_t end, int) {
    SweepScratch<I> &s = thread_scratch<I>();
    s.reserve(n, max_edges);
    for (int64_t k = begin; k < end; ++k)
      if (k == 0)
        t.join = sweep_up<I>(
            n, {edges.common, edges.join_only}, edges.chains, [&](int64_t v) { return rank[v]; },
            s);
      else
        t.split = sweep_up<I>(
            n, {edges.common, edges.split_only}, edges.chains,
            [&](int64_t v) { return static_cast<I>(last - rank[v]); }, s);
    if (s.bytes() > kKeptScratchBytes)
      s = {};
  });
  return t;
}

template <class I>
KeptMergeTrees kept_ranked(std::span<const int64_t> order, const SweepEdges &edges,
                           std::span<const uint8_t> keep, int threads) {
  const int64_t n = static_cast<int64_t>(order.size());
  RankTrees<I> t = sweep_both<I>(order, edges, threads);
  const RankTree<I> &join = t.join, &split = t.split;
  auto split_parent = [&](int64_t r) -> int64_t {
    const I p = split.parent[n - 1 - r];
    return p < 0 ? -1 : n - 1 - p;
  };
  KeptMergeTrees out;
  UninitializedVector<I> index, nearest;
  index.resize(static_cast<std::size_t>(n));
  nearest.resize(static_cast<std::size_t>(n));
  for (int64_t r = 0; r < n; ++r) {
    const bool regular = join.children[r] == 1 && split.children[n - 1 - r] == 1 && !keep[order[r]];
    index[r] = regular ? I{-1} : static_cast<I>(out.nodes.size());
    if (!regular)
      out.nodes.push_back(order[r]);
  }
  const std::size_t k = out.nodes.size();
  out.join_parent.resize(k);
  out.split_parent.resize(k);
  for (int64_t r = n - 1; r >= 0; --r) {
    const I p = join.parent[r];
    const I near_p = p < 0 ? I{-1} : nearest[p];
    nearest[r] = index[r] >= 0 ? index[r] : near_p;
    if (index[r] >= 0)
      out.join_parent[index[r]] = near_p;
  }
  for (int64_t r = 0; r < n; ++r) {
    const int64_t p = split_parent(r);
    const I near_p = p < 0 ? I{-1} : nearest[p];
    nearest[r] = index[r] >= 0 ? index[r] : near_p;
    if (index[r] >= 0)
      out.split_parent[index[r]] = near_p;
  }
  return out;
}

template <class I>
ContourTree sweep_ranked(std::span<const double> values, const SweepEdges &edges, bool augmented,
                         int threads, SweepTimings *timings, std::span<const uint8_t> keep) {
  const auto t0 = clock_type::now();
  const int64_t n = static_cast<int64_t>(values.size());
  UninitializedVector<int64_t> order;
  order.resize(static_cast<std::size_t>(n));
  ascending_order(values, order, threads);
  const auto t1 = clock_type::now();
  RankTrees<I> trees = sweep_both<I>(order, edges, threads);
  const RankTree<I> &join = trees.join, &split = trees.split;
  const auto t2 = clock_type::now();
  // Both trees in ascending ranks: join parents above, split parents below.
  auto split_parent = [&](int64_t r) -> int64_t {
    const I p = split.parent[n - 1 - r];
    return p < 0 ? -1 : n - 1 - p;
  };
  auto split_children = [&](int64_t r) { return split.children[n - 1 - r]; };
  ContourTree out;
  if (augmented) {
    std::vector<int64_t> jp(n), sp(n);
    std::vector<int32_t> su(n);
    for (int64_t r = 0; r < n; ++r) {
      jp[r] = join.parent[r] < 0 ? -1 : join.parent[r];
      sp[r] = split_parent(r);
      su[r] = split_children(r);
    }
    out.nodes.assign(order.begin(), order.end());
    out.arcs = merge_join_split(std::move(jp), {join.children.begin(), join.children.end()},
                                std::move(sp), std::move(su));
  } else {
    // A node's down-degree in the contour tree is its number of join-tree children, its
    // up-degree its number of split-tree children. Regular nodes (one of each) are spliced out of
    // both trees first; merging what is left gives the reduced tree directly, without building
    // the augmented one (Carr, Snoeyink, Axen 2003).
    UninitializedVector<I> index, nearest;
    index.resize(static_cast<std::size_t>(n));
    nearest.resize(static_cast<std::size_t>(n));
    for (int64_t r = 0; r < n; ++r) {
      const bool regular =
          join.children[r] == 1 && split_children(r) == 1 && (keep.empty() || !keep[order[r]]);
      index[r] = regular ? I{-1} : static_cast<I>(out.nodes.size());
      if (!regular)
        out.nodes.push_back(order[r]);
    }
    const int64_t k = static_cast<int64_t>(out.nodes.size());
    std::vector<int64_t> jp(k), sp(k);
    std::vector<int32_t> jd(k), su(k);
    // Join parents are above: the nearest kept node at or above each rank, top down.
    for (int64_t r = n - 1; r >= 0; --r) {
      const I p = join.parent[r];
      const I near_p = p < 0 ? I{-1} : nearest[p];
      nearest[r] = index[r] >= 0 ? index[r] : near_p;
      if (index[r] >= 0) {
        jp[index[r]] = near_p;
        jd[index[r]] = join.children[r];
      }
    }
    // Split parents are below: bottom up.
    for (int64_t r = 0; r < n; ++r) {
      const int64_t p = split_parent(r);
      const I near_p = p < 0 ? I{-1} : nearest[p];
      nearest[r] = index[r] >= 0 ? index[r] : near_p;
      if (index[r] >= 0) {
        sp[index[r]] = near_p;
        su[index[r]] = split_children(r);
      }
    }
    out.arcs = merge_join_split(std::move(jp), std::move(jd), std::move(sp), std::move(su));
  }
  std::sort(out.arcs.begin(), out.arcs.end());
  out.values.resize(out.nodes.size());
  for (std::size_t i = 0; i < out.nodes.size(); ++i)
    out.values[i] = values[out.nodes[i]];
  if (timings) {
    timings->order = seconds_between(t0, t1);
    timings->sweeps = seconds_between(t1, t2);
    timings->merge = seconds_between(t2, clock_type::now());
  }
  return out;
}

} // namespace

ContourTree sweep_contour_tree(std::span<const double> values, const SweepEdges &edges,
                               bool augmented, int threads, SweepTimings *timings,
                               std::span<const uint8_t> keep) {
  const PageReuseScope reuse_pages; // the order's sort buffers become the sweeps' scratch
  const int64_t n = static_cast<int64_t>(values.size());
  for (auto list : {edges.common, edges.join_only, edges.split_only})
    check_edges(list, n);
  check_chains(edges.chains, n);
  if (!keep.empty() && static_cast<int64_t>(keep.size()) != n)
    throw std::invalid_argument("sweep_contour_tree: one keep flag per node needed");
  // 32-bit ranks and offsets where every rank and every edge count fits.
  const std::size_t m = edges.common.size() + chain_pieces(edges.chains) +
                        std::max(edges.join_only.size(), edges.split_only.size());
  if (n < (int64_t{1} << 31) - 1 && m < (std::size_t{1} << 31) - 1)
    return sweep_ranked<int32_t>(values, edges, augmented, threads, timings, keep);
  return sweep_ranked<int64_t>(values, edges, augmented, threads, timings, keep);
}

KeptMergeTrees sweep_merge_trees(std::span<const double> values, const SweepEdges &edges,
                                 std::span<const uint8_t> keep, int threads,
                                 std::span<const int64_t> order) {
  const PageReuseScope reuse_pages;
  const int64_t n = static_cast<int64_t>(values.size());
  for (auto list : {edges.common, edges.join_only, edges.split_only})
    check_edges(list, n);
  check_chains(edges.chains, n);
  if (static_cast<int64_t>(keep.size()) != n)
    throw std::invalid_argument("sweep_merge_trees: one keep flag per node needed");
  if (!order.empty() && static_cast<int64_t>(order.size()) != n)
    throw std::invalid_argument("sweep_merge_trees: the order must list every node");
  std::vector<int64_t> own;
  if (order.empty()) {
    own = ascending_order(values, threads);
    order = own;
  }
  const std::size_t m = edges.common.size() + chain_pieces(edges.chains) +
                        std::max(edges.join_only.size(), edges.split_only.size());
  if (n < (int64_t{1} << 31) - 1 && m < (std::size_t{1} << 31) - 1)
    return kept_ranked<int32_t>(order, edges, keep, threads);
  return kept_ranked<int64_t>(order, edges, keep, threads);
}

ContourTree sweep_contour_tree_wide(std::span<const double> values, const SweepEdges &edges,
                                    bool augmented, int threads) {
  for (auto list : {edges.common, edges.join_only, edges.split_only})
    check_edges(list, static_cast<int64_t>(values.size()));
  check_chains(edges.chains, static_cast<int64_t>(values.size()));
  return sweep_ranked<int64_t>(values, edges, augmented, threads, nullptr, {});
}

} // namespace hoct
