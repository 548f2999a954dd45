// The graph a tree was computed from, with geometry: node positions and values, and for each
// edge the polyline it stands for on the surface (a certified monotone path inside a cell, a
// piece of a mesh edge, or a straight sub-triangle edge). Used to draw the contour tree's arcs on
// the surface: each arc becomes the polyline of a path between its two nodes through graph nodes
// whose values lie between theirs.
#pragma once

#include "tree/sublevel_forest.hpp"
#include "util/uninitialized_vector.hpp"
#include "util/vec.hpp"

#include <array>
#include <cstdint>
#include <memory>
#include <mutex>
#include <span>
#include <vector>

namespace hoct {

// Where a graph's nodes lie, and the interior points of its first edges(), computed when a path
// asks for them: the arcs of a tree pass through a few percent of its graph, and placing all of
// its edge pieces beforehand would spend time and memory on pieces no arc uses.
class GraphGeometry {
public:
  virtual ~GraphGeometry() = default;
  virtual Vec3 node(int64_t v) const = 0;
  // Edges [0, edges()) have their interior points here (not in the graph).
  virtual int64_t edges() const = 0;
  // Appends edge e's interior points to out: from its first end to its second, or back.
  virtual void edge_points(int64_t e, bool forward, std::vector<Vec3> &out) const = 0;
};

class GeometricGraph {
public:
  GeometricGraph() = default;
  GeometricGraph(std::vector<Vec3> positions, std::vector<double> values)
      : position_(std::move(positions)), value_(std::move(values)) {}
  // Positions and the first edges' interior points from `geometry`, when a path needs them.
  GeometricGraph(std::vector<double> values, std::shared_ptr<const GraphGeometry> geometry)
      : value_(std::move(values)), geometry_(std::move(geometry)) {}

  // Room for `edges` edges with `points` interior points in all (add_edge then does not
  // reallocate).
  void reserve(std::size_t edges, std::size_t points);
  // An edge from a to b; `interior` are the polyline's points strictly between them, from a to b.
  void add_edge(int64_t a, int64_t b, const std::vector<Vec3> &interior = {}) {
    add_edge(a, b, interior.data(), interior.size());
  }
  void add_edge(int64_t a, int64_t b, const Vec3 *interior, std::size_t count);
  // All edges at once, instead of add_edge: edge i from ends[i][0] to ends[i][1], its interior
  // points points[point_offset[i] .. point_offset[i + 1]) (point_offset: one entry more than
  // ends, from 0). Taken over, not copied. With a GraphGeometry, the first g = edges() of them
  // have their points there, and point_offset covers the others: edge i >= g has
  // points[point_offset[i - g] .. point_offset[i - g + 1]).
  void set_edges(std::vector<std::array<int64_t, 2>> ends, std::vector<int64_t> point_offset,
                 UninitializedVector<Vec3> points);
  // Builds the adjacency (edges from a node to itself left out); call once after the last
  // add_edge.
  void finish();

  int64_t size() const { return static_cast<int64_t>(value_.size()); }
  Vec3 position(int64_t v) const { return geometry_ ? geometry_->node(v) : position_[v]; }

  // Scratch memory of path(): one per thread that searches.
  // On cache lines of its own: the queues' ends change at every step of a search, and the
  // threads' scratches sit side by side (sharing lines, the searching threads would slow each
  // other down).
  struct alignas(64) Search {
    std::vector<uint32_t> stamp;
    std::vector<int64_t> from, queue, queue_b;
    uint32_t generation = 0;
    // Nodes the next searches must not pass through (a flag per node; empty: none), and the
    // nodes of the last path found, in order (ends included).
    std::vector<uint8_t> avoid;
    std::vector<int64_t> nodes;
  };

  // The polyline from a to b through a path of nodes with values within [min, max] of the two
  // ends' values (breadth-first from both ends until they meet, at most kMaxVisits nodes
  // visited); failing that (the graph is sparser than the surface), beyond_path(). Several
  // threads may search at once, each with its scratch.
  static constexpr int64_t kMaxVisits = 2000000;
  std::vector<Vec3> path(int64_t a, int64_t b, Search &scratch,
                         int64_t below_visits = kMaxVisits) const;
  // The path through nodes below the larger of the two values or above the smaller (the join
  // and the split tree connect the ends of an arc of the graph's contour tree or Reeb graph that
  // way): by a search below, at most `below_visits` nodes visited (none: 0), then the shorter
  // path of the two SublevelForests, built at the first such call (not while `avoid` is set:
  // the forests know nothing of it); failing that too, through any path; just {a, b} if there
  // is none.
  std::vector<Vec3> beyond_path(int64_t a, int64_t b, Search &scratch, int64_t below_visits) const;
  // The searches within the values and below them alone (no forest, no path beyond):
  // scratch.nodes is empty where they fail.
  std::vector<Vec3> near_path(int64_t a, int64_t b, Search &scratch, int64_t below_visits) const;

  // The search within explicit values [lo, hi] (a piece of a partitioned mesh draws its stretch
  // of an arc whose band the whole tree gives): scratch.nodes is empty where it fails.
  std::vector<Vec3> band_path(int64_t a, int64_t b, double lo, double hi, int64_t max_visits,
                              Search &scratch) const {
    return search(a, b, lo, hi, max_visits, scratch);
  }
  // The components of the nodes with values within [lo, hi] that hold `sources` (nodes within
  // the values): label[i] is the index of the first source in source i's component. False, and
  // `label` unspecified, when the searches would visit more than max_visits nodes.
  bool band_components(std::span<const int64_t> sources, double lo, double hi, int64_t max_visits,
                       Search &scratch, std::vector<int64_t> &label) const;
  // The forests' path (the sublevel one if it stays at or below hi, else the superlevel one if
  // it stays at or above lo; the shorter if both do): scratch.nodes is empty where neither does.
  std::vector<Vec3> minimax_path(int64_t a, int64_t b, double lo, double hi,
                                 Search &scratch) const {
    return forest_path(a, b, lo, hi, scratch);
  }
  double value(int64_t v) const { return value_[v]; }

private:
  std::vector<Vec3> search(int64_t a, int64_t b, double lo, double hi, int64_t max_visits,
                           Search &s) const;
  // The shorter of the sublevel forest's path from a to b if its nodes stay at or below hi and
  // the superlevel forest's if they stay at or above lo (s.nodes empty if neither does).
  std::vector<Vec3> forest_path(int64_t a, int64_t b, double lo, double hi, Search &s) const;
  // Appends edge e's polyline from its end u to its other end (u excluded) to out; returns that
  // other end.
  int64_t append_edge(int64_t e, int64_t u, std::vector<Vec3> &out) const;

  std::vector<Vec3> position_; // unless geometry_ places the nodes
  std::vector<double> value_;
  std::shared_ptr<const GraphGeometry> geometry_;
  std::vector<std::array<int64_t, 2>> ends_;
  std::vector<int64_t> point_offset_{0};
  UninitializedVector<Vec3> points_;
  std::vector<int64_t> offset_, adj_, adj_edge_;
  // Built by the first path() that needs it (made anew by finish(); shared by the copies of a
  // finished graph, which have its adjacency).
  struct LazyForest {
    std::once_flag built;
    SublevelForest sublevel, superlevel;
  };
  std::shared_ptr<LazyForest> forest_ = std::make_shared<LazyForest>();
};

} // namespace hoct
