// A contour tree laid out as VTK PolyData, whatever writes it (io/tree_vtp_writer as .vtp, the
// ParaView plugin as vtkPolyData): the nodes are points 0..n-1 (one vertex each), the arcs are
// lines (the polylines of TreeResult::arc_paths when present, drawn on the surface; else
// straight) whose interior points follow the nodes.
#pragma once

#include "tree/tree_result.hpp"

#include <cstdint>
#include <vector>

namespace hoct {

struct TreePolyData {
  std::size_t num_nodes = 0;  // points [0, num_nodes) are the nodes, one vertex each
  std::vector<double> points; // x, y, z of every point
  // Point attributes. On the interior points of a polyline: type Regular, value interpolated
  // along it, the arc's persistence, node_id and cell -1, location Unknown, fallback false.
  std::vector<NodeType> type;
  std::vector<double> value;
  std::vector<double> persistence; // the largest persistence of a pair the node is in (0: none)
  std::vector<int64_t> node_id, cell;
  std::vector<NodeLocation> location;
  std::vector<uint8_t> fallback; // 1 where a degenerate cell fell back to the PL rule
  // Lines in VTK's layout: the points of line a are
  // line_connectivity[line_offsets[a-1] .. line_offsets[a]) (from 0 for a = 0).
  std::vector<int64_t> line_connectivity, line_offsets;
  // Cell attributes: per node (its persistence) and per arc (the smaller of its ends').
  std::vector<double> node_persistence, arc_persistence;

  std::size_t num_points() const { return value.size(); }
  std::size_t num_lines() const { return line_offsets.size(); }
};

TreePolyData tree_polydata(const TreeResult &tree);

} // namespace hoct
