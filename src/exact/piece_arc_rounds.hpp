// The steps of exact/piece_arcs run over all pieces: the arcs drawn by pieces that may sit in
// different processes (one per MPI rank: distributed/distributed_arc_paths) or all in this one
// (InProcessLinks: the unit tests). `PieceLinks` carries the steps' bytes between
// the pieces; the root (rank 0) routes the arcs and gets their paths.
#pragma once

#include "exact/piece_arcs.hpp"

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace hoct {

// The collective steps between the pieces this process holds (`local`, in order) and all
// pieces (numbered 0 .. pieces() - 1; piece p's bytes at index p).
class PieceLinks {
public:
  using Bytes = std::vector<std::byte>;
  virtual ~PieceLinks() = default;
  virtual int pieces() const = 0;
  virtual bool root() const = 0; // this process routes the arcs
  // out[h][p]: what local piece h sends piece p; returns in[h][p]: what piece p sent it.
  virtual std::vector<std::vector<Bytes>> exchange(std::vector<std::vector<Bytes>> out) = 0;
  // Each local piece's bytes; on the root every piece's, elsewhere none.
  virtual std::vector<Bytes> gather(std::vector<Bytes> own) = 0;
  // The root's parts (one per piece; ignored elsewhere): each local piece's.
  virtual std::vector<Bytes> scatter(std::vector<Bytes> parts) = 0;
  // Per item, the least of every local piece's value (on every process).
  virtual std::vector<int32_t> least(std::vector<std::vector<int32_t>> own) = 0;
  // The root's list on every process.
  virtual void broadcast(std::vector<int64_t> &list) = 0;
  // The largest of every process's value (on the root).
  virtual int64_t largest(int64_t own) = 0;
};

// How the arcs were drawn, and what the root received and sent for them.
struct ArcPathCounts {
  int64_t arcs = 0;
  int64_t local = 0;               // by a piece holding both ends
  int64_t routed[kArcRounds] = {}; // across pieces: within the values, below, above, anywhere
  int64_t straight = 0;            // no round found a route: drawn straight
  int64_t bytes_received = 0, bytes_sent = 0; // on the root, from and to other processes
  int64_t component_bytes = 0; // of bytes_received: the components' reports (the rest: paths)
  int64_t neighbour_bytes = 0; // the most a process sent the others: shared keys, labels
  double seconds = 0;
};

// Every process passes its pieces (their neighbours are set here) and the same arcs; on the
// root, each arc's path from its lower end to its upper end (empty where none was found: the
// caller draws it straight) and `counts`; elsewhere nothing. Parallel arcs (one group, levels
// 0, 1, ...) are drawn level after level, each avoiding its lower levels' paths.
// `how` (the root's, optional): per arc, the round that drew it, and whether across pieces.
struct ArcDrawn {
  int32_t round = kArcRounds; // kArcRounds: straight
  bool across = false;
};
std::vector<std::vector<Vec3>> draw_arcs_by_pieces(std::span<PieceArcGraph *const> local,
                                                   std::span<const ArcEnds> arcs, PieceLinks &links,
                                                   int threads, ArcPathCounts *counts = nullptr,
                                                   std::vector<ArcDrawn> *how = nullptr);

// The arcs of `tree` to draw (its nodes' graph_node indexing `nodes`, the group of all pieces'
// nodes: PieceTrees::nodes, ReebGroup::nodes), parallel arcs grouped, by level in the order one
// process draws them (compute_arc_paths); groups numbered from `groups` on, which advances.
std::vector<ArcEnds> tree_arc_ends(const TreeResult &tree, std::span<const PieceNode> nodes,
                                   int32_t &groups);

// All pieces in this process (it is the root).
class InProcessLinks final : public PieceLinks {
public:
  explicit InProcessLinks(int pieces) : pieces_(pieces) {}
  int pieces() const override { return pieces_; }
  bool root() const override { return true; }
  std::vector<std::vector<Bytes>> exchange(std::vector<std::vector<Bytes>> out) override;
  std::vector<Bytes> gather(std::vector<Bytes> own) override { return own; }
  std::vector<Bytes> scatter(std::vector<Bytes> parts) override { return parts; }
  std::vector<int32_t> least(std::vector<std::vector<int32_t>> own) override;
  void broadcast(std::vector<int64_t> &) override {}
  int64_t largest(int64_t own) override { return own; }

private:
  int pieces_;
};

} // namespace hoct
