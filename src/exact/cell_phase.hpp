// The cell phase of the exact pipeline, once per cell: its interior critical points (certified
// gradient zeros), whether it is degenerate (and why), and the certified monotone connections
// from every sector of its nodes to a lower and a higher node. Cells go in fixed contiguous
// chunks, each collecting its interior nodes and connections in flat buffers; combined in chunk
// (= cell) order, the result does not depend on the thread count.
#pragma once

#include "cell/certified_path.hpp"
#include "cell/edge_nodes.hpp"
#include "exact/exact_graph.hpp"
#include "exact/exact_tree_options.hpp"
#include "mesh/mesh.hpp"
#include "tree/tree_stats.hpp"

#include <cstdint>
#include <vector>

namespace hoct {

constexpr uint8_t fallback_bit(FallbackReason r) { return uint8_t(1u << static_cast<int>(r)); }

// What the cells of one chunk contribute to the graph. Chunks start on their own cache line:
// neighbouring chunks run on different threads, and their vectors and counters change per cell.
struct alignas(64) CellChunk {
  struct Node {
    int64_t cell;
    Vec2 uv;
    double value;
  };
  UninitializedVector<Node> nodes; // interior critical points of the chunk's cells, in cell order
  // Connections; node refs >= 0 are global ids, -1 - i is the chunk's i-th interior node.
  UninitializedVector<GraphEdge> join, split;
  std::vector<GeoEdge> geo; // with arc geometry: each connection's path (per cell join, split)
  std::vector<int64_t> fallback_cells; // the chunk's cells that fall back, ascending
  int64_t unresolved = 0;              // uncertified interior zeros
  // Degenerate critical points classified by their sectors in the chunk's regular cells, and
  // the largest slack (cell/degenerate_points.hpp), and critical curves (cell/critical_curves.hpp).
  int64_t degenerate_points = 0, critical_corners = 0, critical_curves = 0;
  double degenerate_slack = 0;
  int64_t level_edges = 0; // cell sides on constant edges certified as level edges
  PathCounters counters;
  // Thread time in the two passes over each block of cells (critical points, then connections).
  double critical_seconds = 0, connection_seconds = 0;
};

struct CellPhase {
  UninitializedVector<uint8_t> fallback; // per cell: its FallbackReason bits (0: regular)
  std::vector<CellChunk> chunks;
};

// `threads`: the threads the cells are spread over (the result does not depend on it).
CellPhase run_cell_phase(const Mesh &mesh, const EdgeNodes &edge_nodes,
                         const ExactTreeOptions &options, int threads);

} // namespace hoct
