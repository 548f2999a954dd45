#include "tree/persistence.hpp"

#include "tree/union_find.hpp"
#include "util/parallel_for.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>

namespace hoct {

const char *to_string(PersistencePair::Kind k) {
  switch (k) {
  case PersistencePair::Kind::Join:
    return "join";
  case PersistencePair::Kind::Split:
    return "split";
  case PersistencePair::Kind::Global:
    return "global";
  case PersistencePair::Kind::Loop:
    return "loop";
  }
  return "?";
}

std::vector<std::array<double, 2>> pair_points(const std::vector<PersistencePair> &pairs,
                                               PersistencePair::Kind kind) {
  std::vector<std::array<double, 2>> p;
  for (const auto &x : pairs)
    if (x.kind == kind)
      p.push_back({x.birth_value, x.death_value});
  return p;
}

std::vector<std::array<double, 2>> PersistenceDiagram::points(PersistencePair::Kind kind) const {
  return pair_points(pairs, kind);
}

namespace {

// Elder rule along `order` (position i -> node). Each component remembers its oldest node.
template <class Order>
void elder_sweep(const ScalarGraph &g, const Order &order, PersistencePair::Kind kind,
                 std::vector<PersistencePair> &out, std::vector<int64_t> *oldest_out) {
  const int64_t n = g.size();
  std::vector<int64_t> rank(n), oldest(n);
  for (int64_t i = 0; i < n; ++i)
    rank[order(i)] = i;
  UnionFind uf(n);
  std::vector<int64_t> roots;
  for (int64_t i = 0; i < n; ++i) {
    const int64_t v = order(i);
    oldest[v] = v;
    roots.clear();
    for (int64_t u : g.neighbors(v))
      if (rank[u] < rank[v])
        roots.push_back(uf.find(u));
    std::sort(roots.begin(), roots.end());
    roots.erase(std::unique(roots.begin(), roots.end()), roots.end());
    if (roots.empty())
      continue; // v is born
    // The component with the oldest birth survives; the others die at v.
    int64_t elder = roots[0];
    for (int64_t r : roots)
      if (rank[oldest[r]] < rank[oldest[elder]])
        elder = r;
    for (int64_t r : roots)
      if (r != elder)
        out.push_back({kind, oldest[r], v, g.value(oldest[r]), g.value(v)});
    const int64_t keep = oldest[elder];
    for (int64_t r : roots)
      uf.unite(r, v);
    oldest[uf.find(v)] = keep;
  }
  if (oldest_out) {
    oldest_out->assign(n, -1);
    for (int64_t v = 0; v < n; ++v)
      (*oldest_out)[v] = oldest[uf.find(v)];
  }
}

// The elder rule along nodes 0 .. n-1 (ascending) or n-1 .. 0 (descending), the earlier
// neighbours of each node listed in a CSR (`offset`, `adj`): the same steps as elder_sweep.
void elder_sweep_sorted(std::span<const double> values, const std::vector<int64_t> &offset,
                        const std::vector<int64_t> &adj, bool ascending, PersistencePair::Kind kind,
                        std::vector<PersistencePair> &out, std::vector<int64_t> &oldest_out) {
  const int64_t n = static_cast<int64_t>(values.size());
  std::vector<int64_t> oldest(n);
  UnionFind uf(n);
  std::vector<int64_t> roots;
  // Born earlier in the sweep.
  const auto older = [ascending](int64_t a, int64_t b) { return ascending ? a < b : a > b; };
  for (int64_t i = 0; i < n; ++i) {
    const int64_t v = ascending ? i : n - 1 - i;
    oldest[v] = v;
    roots.clear();
    for (int64_t k = offset[v]; k < offset[v + 1]; ++k)
      roots.push_back(uf.find(adj[k]));
    std::sort(roots.begin(), roots.end());
    roots.erase(std::unique(roots.begin(), roots.end()), roots.end());
    if (roots.empty())
      continue;
    int64_t elder = roots[0];
    for (int64_t r : roots)
      if (older(oldest[r], oldest[elder]))
        elder = r;
    for (int64_t r : roots)
      if (r != elder)
        out.push_back({kind, oldest[r], v, values[oldest[r]], values[v]});
    const int64_t keep = oldest[elder];
    for (int64_t r : roots)
      uf.unite(r, v);
    oldest[uf.find(v)] = keep;
  }
  oldest_out.assign(n, -1);
  for (int64_t v = 0; v < n; ++v)
    oldest_out[v] = oldest[uf.find(v)];
}

// One (min, max) pair per component: the component's oldest minimum and oldest maximum (each
// node's, from the two sweeps).
template <class Value>
void global_pairs(const std::vector<int64_t> &global_min, const std::vector<int64_t> &global_max,
                  const Value &value, std::vector<PersistencePair> &pairs) {
  std::vector<char> done(global_min.size(), 0);
  for (std::size_t v = 0; v < global_min.size(); ++v) {
    const int64_t lo = global_min[v], hi = global_max[v];
    if (done[lo])
      continue;
    done[lo] = 1;
    pairs.push_back({PersistencePair::Kind::Global, lo, hi, value(lo), value(hi)});
  }
}

} // namespace

PersistenceDiagram persistence_diagram_ascending(std::span<const double> values,
                                                 std::span<const std::array<int64_t, 2>> edges,
                                                 int threads) {
  const int64_t n = static_cast<int64_t>(values.size());
  // The join sweep's lower neighbours per node, or the split sweep's upper ones (a CSR).
  auto neighbours = [&](bool below, std::vector<int64_t> &offset, std::vector<int64_t> &adj) {
    offset.assign(static_cast<std::size_t>(n + 1), 0);
    for (const auto &e : edges)
      if (e[0] != e[1])
        ++offset[(below ? std::max(e[0], e[1]) : std::min(e[0], e[1])) + 1];
    for (int64_t v = 0; v < n; ++v)
      offset[v + 1] += offset[v];
    adj.resize(static_cast<std::size_t>(offset[n]));
    std::vector<int64_t> fill(offset.begin(), offset.end() - 1);
    for (const auto &e : edges)
      if (e[0] != e[1]) {
        const int64_t a = std::min(e[0], e[1]), b = std::max(e[0], e[1]);
        if (below)
          adj[fill[b]++] = a;
        else
          adj[fill[a]++] = b;
      }
  };
  PersistenceDiagram d;
  std::vector<int64_t> global_min, global_max;
  // The join pairs, then the split pairs: two independent sweeps, each with its neighbours.
  std::vector<PersistencePair> split;
  parallel_chunks(2, 2, threads, [&](int64_t sweep, int64_t, int64_t, int) {
    std::vector<int64_t> offset, adj;
    neighbours(sweep == 0, offset, adj);
    if (sweep == 0)
      elder_sweep_sorted(values, offset, adj, true, PersistencePair::Kind::Join, d.pairs,
                         global_min);
    else
      elder_sweep_sorted(values, offset, adj, false, PersistencePair::Kind::Split, split,
                         global_max);
  });
  d.pairs.insert(d.pairs.end(), split.begin(), split.end());
  global_pairs(
      global_min, global_max, [&](int64_t v) { return values[v]; }, d.pairs);
  return d;
}

PersistenceDiagram persistence_diagram(const ScalarGraph &g) {
  PersistenceDiagram d;
  const auto &asc = g.ascending();
  const int64_t n = g.size();
  std::vector<int64_t> global_min, global_max;
  elder_sweep(
      g, [&](int64_t i) { return asc[i]; }, PersistencePair::Kind::Join, d.pairs, &global_min);
  elder_sweep(
      g, [&](int64_t i) { return asc[n - 1 - i]; }, PersistencePair::Kind::Split, d.pairs,
      &global_max);
  global_pairs(
      global_min, global_max, [&](int64_t v) { return g.value(v); }, d.pairs);
  return d;
}

namespace {

// Is there a matching of the "forced" points of `left` into `right` using edges within eps?
// adjacency[i] lists (cost, j) sorted by cost.
bool saturates(const std::vector<std::vector<std::pair<double, int>>> &adj,
               const std::vector<char> &forced, int right_size, double eps) {
  std::vector<int> match_right(right_size, -1);
  std::vector<int> seen(right_size, -1);
  int stamp = 0;
  std::function<bool(int)> augment = [&](int i) -> bool {
    for (const auto &[cost, j] : adj[i]) {
      if (cost > eps)
        break;
      if (seen[j] == stamp)
        continue;
      seen[j] = stamp;
      if (match_right[j] < 0 || augment(match_right[j])) {
        match_right[j] = i;
        return true;
      }
    }
    return false;
  };
  for (std::size_t i = 0; i < adj.size(); ++i) {
    if (!forced[i])
      continue;
    ++stamp;
    if (!augment(static_cast<int>(i)))
      return false;
  }
  return true;
}

double linf(const std::array<double, 2> &p, const std::array<double, 2> &q) {
  return std::max(std::abs(p[0] - q[0]), std::abs(p[1] - q[1]));
}

} // namespace

double bottleneck_distance(const std::vector<std::array<double, 2>> &a,
                           const std::vector<std::array<double, 2>> &b) {
  // Feasible at eps iff a matching of A-B edges (cost <= eps) covers every point whose distance
  // to the diagonal exceeds eps, on both sides; by the Mendelsohn-Dulmage theorem it suffices to
  // cover each side's forced points separately. Edges costing at least both points' diagonal
  // distances are never needed (exchange argument) and are dropped.
  const int n = static_cast<int>(a.size()), m = static_cast<int>(b.size());
  auto diag = [](const std::array<double, 2> &p) { return std::abs(p[1] - p[0]) / 2; };
  std::vector<std::vector<std::pair<double, int>>> adj_a(n), adj_b(m);
  std::vector<double> candidates = {0.0};
  for (int i = 0; i < n; ++i)
    candidates.push_back(diag(a[i]));
  for (int j = 0; j < m; ++j)
    candidates.push_back(diag(b[j]));
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < m; ++j) {
      const double c = linf(a[i], b[j]);
      if (c >= std::max(diag(a[i]), diag(b[j])))
        continue;
      adj_a[i].push_back({c, j});
      adj_b[j].push_back({c, i});
      candidates.push_back(c);
    }
  for (auto &l : adj_a)
    std::sort(l.begin(), l.end());
  for (auto &l : adj_b)
    std::sort(l.begin(), l.end());
  std::sort(candidates.begin(), candidates.end());
  candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
  auto feasible = [&](double eps) {
    std::vector<char> fa(n), fb(m);
    for (int i = 0; i < n; ++i)
      fa[i] = diag(a[i]) > eps;
    for (int j = 0; j < m; ++j)
      fb[j] = diag(b[j]) > eps;
    return saturates(adj_a, fa, m, eps) && saturates(adj_b, fb, n, eps);
  };
  std::size_t lo = 0, hi = candidates.size() - 1; // candidates[hi] (the largest) is feasible
  while (lo < hi) {
    const std::size_t mid = (lo + hi) / 2;
    if (feasible(candidates[mid]))
      hi = mid;
    else
      lo = mid + 1;
  }
  return candidates[lo];
}

} // namespace hoct
