// Between VTK objects and hoct's: a vtkUnstructuredGrid with a point scalar array becomes a
// MeshInput (vtkio/grid_input converts it), a tree laid out by io/tree_polydata becomes
// vtkPolyData with the arrays ParaView and TTK users know.
#pragma once

#include "io/tree_polydata.hpp"
#include "mesh/mesh_input.hpp"

#include <string>

class vtkDataArray;
class vtkPolyData;
class vtkUnstructuredGrid;

namespace hoct::paraview {

// The point scalar to compute the tree of. `selected` is the filter's input array (null when the
// property names no array, names one the grid lacks, or asks for active scalars there are none
// of); `requested` the name the property gives ("" for none). A named array that is missing is an
// error (hoct::InputError listing the point arrays). With no name, the default: the rule of
// hoct's readers (vtkio::find_point_array): the active point scalars if they have one component,
// else the first one-component floating-point point array, else the first one-component point
// array of another type; never an id, ghost or mask array (vtkGhostType, vtkOriginalPointIds,
// GlobalIds, ..., the GlobalIds / PedigreeIds attributes). None of those: an InputError.
// *by_default says whether the default was taken.
vtkDataArray *point_scalar(vtkUnstructuredGrid *grid, vtkDataArray *selected,
                           const std::string &requested, bool *by_default);

// The grid's points, its triangle cells (vertex and line cells are skipped) and the values of
// `scalar` (one component, one tuple per point), by the conversion the VTK readers share
// (vtkio::grid_piece). Throws hoct::InputError naming the cell or point for anything else (other
// cell types, non-finite values or coordinates, no triangles).
MeshInput mesh_input_from_grid(vtkUnstructuredGrid *grid, vtkDataArray *scalar);

// TTK's critical type codes: 0 minimum, 1 saddle, 3 maximum, 5 regular.
int ttk_critical_type(NodeType type);

// The nodes as vertices with the point arrays CriticalType (TTK codes), TypeName, Value,
// Persistence, NodeId, Cell, Location (0 vertex, 1 edge, 2 interior, 3 unknown), Fallback.
void critical_points_polydata(const TreePolyData &tree, vtkPolyData *out);

// The arcs as polylines (with the nodes as vertices too if with_nodes): point arrays Value,
// Persistence, CriticalType, NodeId (-1 inside a polyline); cell arrays Persistence and ArcId
// (-1 for the vertices).
void arcs_polydata(const TreePolyData &tree, bool with_nodes, vtkPolyData *out);

} // namespace hoct::paraview
