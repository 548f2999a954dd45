// The arcs of a partitioned mesh's tree drawn on the surface by its pieces (docs/ALGORITHM.md
// §8, "The arcs' paths by pieces"): no piece holds the whole graph, so an arc whose path leaves
// the piece of its ends is drawn in stretches, one per piece it crosses, between nodes two
// pieces share.
//
// Each arc is drawn, as one process draws it, through graph nodes within its values if any
// path there joins its ends; else below its upper end's value (the join tree joins its ends
// there); else above its lower end's; else anywhere. Parallel arcs avoid their lower levels'
// paths (ArcEnds). The rounds are run over all pieces by exact/piece_arc_rounds. In each round:
//  1. a piece that holds both ends searches there (draw_local_arcs; below, a short search, as
//     one process's first pass does);
//  2. for each arc no piece drew, each piece finds the components of its graph within the
//     round's values that hold two or more of its ends and shared nodes (piece_components),
//     tells each neighbour the components of the nodes they share (neighbour_labels; the keys
//     of those nodes were exchanged once, border_offers), and reports to rank 0 only its
//     components, their ends and the neighbours' components they touch (component_report):
//     what rank 0 receives grows with the components, not with the pieces' borders;
//  3. rank 0 finds a route from end to end through the fewest components (exact/arc_routes),
//     a stretch per piece, between nodes two pieces share;
//  4. each piece draws its stretches within the round's values (draw_stretches), and rank 0
//     joins them end to end (exact/arc_routes).
// An arc no round routes is drawn straight and counted.
#pragma once

#include "exact/arc_records.hpp"
#include "exact/arc_routes.hpp"
#include "exact/piece_trees.hpp"
#include "tree/geometric_graph.hpp"
#include "util/vec.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <unordered_map>
#include <vector>

namespace hoct {

// A piece's graph with geometry, and how its kept nodes (exact/piece_trees) are found in it.
struct PieceArcGraph {
  std::shared_ptr<const GeometricGraph> graph;
  // The kept nodes ascending (value, key): graph node, key, value (relative, as the pieces'
  // trees hold them), whether other pieces may hold it, and the kept join and split trees.
  std::vector<int64_t> ids;
  std::vector<NodeKey> keys;
  std::vector<double> values;
  std::vector<uint8_t> shared;
  std::vector<int64_t> join_parent, split_parent;
  // Consecutive nodes along the edges other pieces hold (indices into ids): the kept trees do
  // not have them (the group with all the edge's cells joins them).
  std::vector<std::array<int64_t, 2>> chain_links;
  // The piece's number, the pieces that may hold each kept node (PieceKeys::span), and (set by
  // meet_neighbours) the kept nodes it holds with each piece, in key order (both list them so).
  int32_t piece = 0;
  std::vector<std::array<int32_t, 2>> spans;
  std::vector<std::vector<int64_t>> common;

  // The kept nodes of the piece `piece`'s trees, at graph nodes `ids` (in the trees' order):
  // keys, values, spans, parents, and the copies of one point (one key, next to each other: a
  // piece cut into disks) joined in chain_links; indexed for find.
  void set_kept(int32_t piece, const PieceTrees &trees, std::vector<int64_t> ids);
  // The kept node with this key (index into ids), or -1.
  int64_t find(const NodeKey &key) const;
  // Sorted copy of keys with their indices (built by index_keys).
  std::vector<std::pair<NodeKey, int64_t>> by_key;
  void index_keys();
};

// The graph nodes of a piece that its parallel arcs' paths went through, by arc: what the
// higher levels of their groups avoid.
using ArcTrail = std::unordered_map<int64_t, std::vector<int64_t>>;

// 1. Of arcs `which`, those whose ends this piece both holds and joins by a search within the
// round's values visiting at most max_visits nodes (avoiding the lower levels' nodes in
// `trail`): paths[k] (for which[k]) non-empty where drawn, and (`nodes`) their graph nodes.
std::vector<std::vector<Vec3>> draw_local_arcs(const PieceArcGraph &piece,
                                               std::span<const ArcEnds> arcs,
                                               std::span<const int64_t> which, ArcRound round,
                                               int64_t max_visits, int threads,
                                               const ArcTrail *trail = nullptr,
                                               std::vector<std::vector<int64_t>> *nodes = nullptr);

// 0. Once: the keys of the piece's shared nodes each other piece may hold, as bytes (by piece),
// and from what every piece offered this one (by piece), PieceArcGraph::common.
std::vector<std::vector<std::byte>> border_offers(const PieceArcGraph &piece, int pieces);
void meet_neighbours(PieceArcGraph &piece, std::span<const std::vector<std::byte>> offers);

// 2. The piece's components for arcs `which` in `round`: of each arc, the components of the
// piece's graph within the round's values that hold two or more of its ends and shared nodes
// (by a search within the arc's values, visiting at most max_visits nodes, past which the piece
// has none for that arc; below or above by its kept join or split tree and its shared edges'
// chains: two kept nodes are joined below h where their climbs up the join tree below h meet).
struct ArcComponents {
  std::vector<std::vector<std::pair<int64_t, int32_t>>> label; // per arc: (kept node, component)
  std::vector<int32_t> count;                                  // per arc: its components
  std::vector<std::array<int32_t, 2>> ends;                    // per arc: the ends' (-1: none)
};
// An arc with nodes to avoid is searched in every round (the kept trees know nothing of them).
ArcComponents piece_components(const PieceArcGraph &piece, std::span<const ArcEnds> arcs,
                               std::span<const int64_t> which, ArcRound round,
                               const ArcTrail *trail = nullptr,
                               int64_t max_visits = GeometricGraph::kMaxVisits);
// 2b. The components of the nodes the piece holds with each other piece (within each arc's
// values, in key order), as bytes for that piece (by piece).
std::vector<std::vector<std::byte>>
neighbour_labels(const PieceArcGraph &piece, const ArcComponents &components,
                 std::span<const ArcEnds> arcs, std::span<const int64_t> which, ArcRound round);
// 2c. From its neighbours' labels (by piece): the piece's components, their ends, and which of
// its neighbours' components each touches (at which node), as bytes for route_arcs.
std::vector<std::byte> component_report(const PieceArcGraph &piece, const ArcComponents &components,
                                        std::span<const ArcEnds> arcs,
                                        std::span<const int64_t> which, ArcRound round,
                                        std::span<const std::vector<std::byte>> labels);

// 4. The piece's stretches drawn within the round's values (avoiding their lower levels' nodes
// in `trail`, where the parallel arcs' nodes are added), as bytes for join_stretches.
std::vector<std::byte> draw_stretches(const PieceArcGraph &piece, std::span<const ArcEnds> arcs,
                                      std::span<const Stretch> stretches, ArcRound round,
                                      ArcTrail *trail = nullptr);

} // namespace hoct
