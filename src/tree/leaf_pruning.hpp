// Leaf pruning of a contour tree (or of a Reeb graph's trees) in order of persistence: the
// engine of the persistence simplification and of the branch decomposition (the rules are
// tree/simplification.hpp's). A candidate is (persistence, leaf, saddle), the least popped first,
// validated when popped; a leaf whose saddle has no other arc on its side waits until that saddle
// is spliced out.
//
// No adjacency lists: each node keeps, for its arcs up and for its arcs down, their number and
// the XOR of their other ends and of their ids. The pruning only ever reads a side holding one
// arc (a leaf's, a regular node's two), which the XORs then name; removing or splicing an arc
// updates a few numbers at its ends. Arc ids: the input's 0 .. m-1, then each arc made by a
// splice the next one.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace hoct {

struct Branch;

class LeafPruning {
public:
  // Nodes 0 .. n-1 with their values, arcs (lower node first) between distinct nodes.
  LeafPruning(std::span<const double> values, std::span<const std::array<int64_t, 2>> arcs);

  // Prunes valid leaves while the least candidate persistence is below `limit` and more than two
  // nodes are left.
  void prune(double limit);

  struct Pruned {
    int64_t leaf, saddle, arc;
    double persistence;
  };
  const std::vector<Pruned> &order() const { return order_; }
  bool removed(int64_t v) const { return nodes_[v].up < 0; }
  // The arcs left, as (id, lower node, upper node) with lower < upper, by id.
  std::vector<std::array<int64_t, 3>> arcs_left() const;
  // The branch hierarchy of what was pruned so far (tree/simplification.hpp's Branch list): the
  // root (the last arc left in the order (lower node, upper node, id)), then the pruned leaves
  // in reverse pruning order, each the child of the branch whose arc took in its saddle.
  std::vector<Branch> branches() const;

private:
  struct Node {
    int32_t up = 0, down = 0; // arcs on each side; up < 0: removed
    double value = 0;
    int64_t up_end = 0, down_end = 0; // XOR of the other ends of the arcs on each side
    int64_t up_arc = 0, down_arc = 0; // XOR of their ids
  };
  struct Candidate {
    double persistence;
    int64_t leaf, saddle;
    bool operator<(const Candidate &o) const {
      if (persistence != o.persistence)
        return persistence < o.persistence;
      return leaf != o.leaf ? leaf < o.leaf : saddle < o.saddle;
    }
  };
  // Arc `id` from lo up to hi joins (count 1) or leaves (count -1) the sides of its ends.
  void link(int64_t id, int64_t lo, int64_t hi, int count);
  void add_candidate(int64_t leaf, bool initial);
  bool next_candidate(double limit, Candidate &c);
  std::array<int64_t, 2> ends(int64_t id) const;

  std::span<const std::array<int64_t, 2>> input_arcs_;
  std::vector<Node> nodes_;
  std::vector<std::array<int64_t, 2>> made_; // ends of the arcs made by splices
  // Each arc's fate: left (-1), pruned with a leaf (-2), or the arc a splice merged it into.
  std::vector<int64_t> fate_;
  std::vector<int64_t> spliced_into_; // node -> the arc made when it was spliced out, or -1
  std::vector<Candidate> sorted_;     // the initial leaves, ascending
  std::size_t next_sorted_ = 0;
  std::vector<Candidate> heap_; // later candidates, a min-heap
  std::vector<Pruned> order_;
  int64_t alive_ = 0;
};

} // namespace hoct
