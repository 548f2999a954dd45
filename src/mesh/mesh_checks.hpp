// Checks of a mesh's input data and cell geometry. Each records what it finds in a ProblemLog
// with the cell or point index, so the user can find the culprit.
#pragma once

#include <array>

#include "mesh/geometry.hpp"
#include "mesh/mesh_input.hpp"
#include "mesh/problem_log.hpp"
#include "mesh/topology.hpp"

namespace hoct {

// Largest |value| accepted: Lagrange -> Bernstein conversion, derivatives and the products of
// the certification multiply values by factors far below 1e150 for every supported degree.
inline constexpr double kMaxAbsValue = 1e100; // = kMaxMagnitude in mesh_checks.cpp
// Smallest non-zero value range accepted: below it, products of derivatives (Hessian
// determinants, the certification's bounds) underflow and critical points are lost (seen from
// 1e-160 on).
inline constexpr double kMinValueRange = 1e-140;

// Structure of the input: array sizes, node counts per degree, node indices in range, no node
// repeated within a cell, finite point coordinates, finite values of at most kMaxAbsValue
// spanning 0 or at least kMinValueRange. Returns
// false if the input is too broken to build a topology from (the problems say why).
bool check_input(const MeshInput &input, ProblemLog &problems, int threads = 1);

// Distinct vertices (cell corners) at the same position, within 1e-10 of the bounding-box
// diagonal: a crack in the mesh (merge_duplicate_points repairs it). `box`: the points'
// bounding box when the caller has it (else it is computed here).
void check_duplicate_vertices(const MeshInput &input, const Topology &topology,
                              ProblemLog &problems, int threads = 1,
                              const std::array<Vec3, 2> *box = nullptr);

// Gaps between cells: the cells of an edge must trace the same curve along it (compared as
// Bernstein control points, raised to the higher degree and oriented alike, within 1e-6 of the
// bounding-box diagonal plus the coordinates' magnitude: float32 files pass). A curved P2 edge
// next to a straight P1 one, or the shared edge's nodes of two cells at different positions,
// is a GeometricGap. Edges whose cells are all straight-sided are the same segment and skipped.
void check_edge_geometry(const Geometry &geometry, const Topology &topology, ProblemLog &problems,
                         int threads = 1);

// Degenerate (zero-area) and inverted cells. Planar meshes: the Jacobian determinant of each
// cell's map, in Bernstein form (certified where its coefficients share a sign, else sampled), must
// be bounded away from zero and agree in sign with a consistent orientation of the mesh. Surfaces:
// the normal must not vanish and must not flip within a cell.
void check_geometry(const Geometry &geometry, const Topology &topology, ProblemLog &problems,
                    int threads = 1);

} // namespace hoct
