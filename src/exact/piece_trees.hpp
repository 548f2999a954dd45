// The exact tree of a mesh partitioned into pieces of contiguous input cells (mesh/mesh_partition),
// computed piece by piece: each piece builds the exact graph of its own cells and keeps of its
// join and split trees only the nodes that matter beyond it (its critical nodes and the nodes
// on vertices and edges it shares with other pieces: sweep_merge_trees); neighbouring groups of
// pieces are merged by sweeping the union of their kept trees, sharing nodes by their key, and
// the last group's trees give the contour tree. That is the thesis' stitching of local join and
// split trees (§3.4), with pieces of the mesh in place of cells. The result is the whole mesh's
// tree: the same nodes, values, places and arcs for any number of pieces (the distributed
// computation, pipeline/distributed_tree, exchanges PieceTrees between MPI ranks).
#pragma once

#include "exact/exact_tree_options.hpp"
#include "mesh/mesh.hpp"
#include "tree/contour_tree.hpp"
#include "tree/tree_result.hpp"

#include <array>
#include <compare>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

namespace hoct {

// A graph node's identity in the whole mesh, ordered as the whole mesh's graph orders its ids
// (vertices, edge nodes, interior nodes, fallback lattice nodes on edges, the fallback cells'
// other sub-vertices): equal values are ordered by it.
struct NodeKey {
  enum Kind : int64_t { Vertex = 0, EdgeNode = 1, Interior = 2, EdgeLattice = 3, SubVertex = 4 };
  int64_t kind = 0;
  int64_t a = 0, b = 0, c = 0; // point; edge's lower and higher point, index; cell, index
  auto operator<=>(const NodeKey &) const = default;
};

struct PieceNode {
  NodeKey key;
  double value = 0;              // relative to the field's reference (mesh/field.hpp)
  std::array<int32_t, 2> span{}; // the lowest and highest piece that may hold the node
  int64_t order_cell = 0;        // the whole mesh's triangle it is placed in (the lowest wins)
  Vec3 position{0, 0, 0};
  int64_t cell = -1; // its input cell in the whole, and (u, v) there
  std::array<double, 2> uv{0, 0};
  NodeLocation location = NodeLocation::Unknown;
  bool fallback = false;
  double slack = -1; // the fallback stand-in's certified distance there, -1 if none
  // A vertex or edge node other pieces may hold: whether its edges (cells) in the group all
  // say it is a strict minimum (bit 0) or maximum (bit 1), cell/strict_extrema; a certain
  // extremum gets no slack. Its slack then counts the stand-in alone.
  uint8_t strict = 0;
  bool shared = false;
};

// The nodes along a mesh edge other pieces may hold, ascending along it from its lower point:
// its vertices, edge nodes and the lattice nodes of fallback cells on either side. Its pieces
// join consecutive nodes in both trees only once every cell of the edge is in the group: a
// piece without the fallback cell beyond the edge does not know its lattice nodes, and a
// segment over them would connect what the whole mesh connects only through them (on
// plateaus, where they tie).
struct ChainNode {
  double t = 0;     // position along the edge
  int64_t node = 0; // index into PieceTrees::nodes
  auto operator<=>(const ChainNode &) const = default;
};
struct SharedChain {
  int64_t lo = 0, hi = 0;        // the edge's points in the whole
  std::array<int32_t, 2> span{}; // the pieces that may hold the edge
  std::vector<ChainNode> nodes;
};

// The kept join and split trees of a group of consecutive pieces.
struct PieceTrees {
  int32_t first_piece = 0, last_piece = 0;
  std::vector<PieceNode> nodes;                   // ascending (value, key)
  std::vector<int64_t> join_parent, split_parent; // indices into nodes, -1 at roots
  std::vector<SharedChain> chains;                // by (lo, hi), not yet in the trees
  ExactCounts counts;                             // over the group's cells and nodes
};

// Where a piece sits in the whole: the whole's index of each of its points, of its first
// input cell and of its first triangle, and each of its points' piece span (the lowest and
// highest piece whose cells use it).
struct PiecePlace {
  int32_t piece = 0;
  std::span<const int64_t> global_point;
  int64_t first_cell = 0, first_triangle = 0;
  std::span<const std::array<int32_t, 2>> point_span; // per point of the piece
};

struct PieceArcGraph; // exact/piece_arcs

// One piece's kept trees (its mesh built with the whole's scales: MeshBuildOptions::whole_scales;
// options.augmented keeps every node). Fills the exact pipeline's phase times into `time`. With
// `arcs`, also the piece's graph with geometry there, to draw the whole tree's arcs.
PieceTrees piece_trees(const Mesh &piece, const PiecePlace &place, const ExactTreeOptions &options,
                       TreeTimings &time, PieceArcGraph *arcs = nullptr);

// The counts of two groups of pieces together, before the nodes both hold are counted once.
ExactCounts sum_counts(const ExactCounts &x, const ExactCounts &y);

// Groups a (pieces first .. k) and b (k + 1 .. last) as one.
PieceTrees merge_piece_trees(const PieceTrees &a, const PieceTrees &b, bool augmented,
                             int threads = 1);

// A node two pieces both hold (one key and value), as one: placed in the lower cell, a fallback
// node if either says so, the larger slack, a certain extremum if both say so.
PieceNode one_node(const PieceNode &x, const PieceNode &y);

// The result of a tree or graph over PieceNodes (`node`: a graph node id's): the fallback
// stand-in's arcs contracted in `ct` as exact_contour_tree contracts them, the nodes placed,
// values absolute (`reference` added back), `counts` the statistics.
TreeResult piece_graph_result(ContourTree &ct, const ExactCounts &counts, bool augmented,
                              double reference, const std::function<PieceNode(int64_t)> &node);

// The tree of the whole mesh from the group of all its pieces: values absolute (`reference`
// added back), the fallback stand-in's arcs contracted as exact_contour_tree does.
TreeResult tree_of_pieces(const PieceTrees &all, bool augmented, double reference);

} // namespace hoct
