// A checked higher-order triangle mesh: topology, the Bernstein field and the geometry map,
// built from a MeshInput, with every problem found recorded.
#pragma once

#include <functional>
#include <limits>
#include <map>
#include <string>
#include <utility>

#include "mesh/cell_split.hpp"
#include "mesh/field.hpp"
#include "mesh/geometry.hpp"
#include "mesh/mesh_fingerprint.hpp"
#include "mesh/mesh_input.hpp"
#include "mesh/problem_log.hpp"
#include "mesh/topology.hpp"

#include <optional>
#include <span>
#include <string>

namespace hoct {

// Wall time of each step of build_mesh, in seconds (0 for steps not run).
struct MeshBuildTimes {
  double input_checks = 0;       // array sizes, ids, finite values, cell shapes
  double cell_split = 0;         // quadrilaterals and Bezier cells into Lagrange triangles
  double topology = 0;           // vertices, edges, components, manifold checks
  double duplicate_vertices = 0; // distinct vertices at one position
  double geometry = 0;           // the cells' geometric maps
  double field = 0;              // Lagrange -> Bernstein conversion, continuity across edges
  double geometry_checks = 0;    // orientation, zero areas, folds
  double total() const {
    return input_checks + cell_split + topology + duplicate_vertices + geometry + field +
           geometry_checks;
  }
};

struct Mesh {
  std::string source, field_name, field_detail;
  int64_t num_points = 0;
  // Of the input it was built from (mesh/mesh_fingerprint.hpp), for the results to record; unset
  // for a mesh whose field does not come from the input's node values (build_mesh_from_samples).
  std::optional<InputFingerprint> fingerprint;
  Topology topology;
  Field field;
  Geometry geometry;
  ProblemLog problems;
  // False if the input was too broken to build topology, field and geometry.
  bool complete = false;
  // Which input cell each cell comes from: the identity, unless the input had quadrilaterals
  // (each is two cells here: mesh/cell_split). Results report input cells (compute_tree).
  CellOrigins origins;
  // Quadrilaterals and Bezier cells of the input (converted by mesh/cell_split).
  int64_t input_quadrilaterals = 0, input_bezier_cells = 0;
  // The input's cells by kind and degree (order, for a quadrilateral), for the reports: e.g.
  // {(LagrangeQuadrilateral, 3): 9}; empty if the input was too broken to build.
  std::map<std::pair<CellKind, int>, int64_t> input_cell_kinds;
  int64_t num_input_cells() const { return origins.num_input_cells(topology.num_cells()); }
  // "quadrilateral order 3: 9, triangle degree 2: 4" (or "degree 2: 4" for triangles only).
  std::string describe_input_cells() const;
  MeshBuildTimes build_times;
};

// The scales a piece of a partitioned mesh takes from the whole mesh (mesh/mesh_partition): the
// field's range and degree (its reference value, precision and relative tolerances) and the
// points' bounding box (the geometry's tolerances). With them each piece computes, on its cells,
// exactly what the whole mesh computes there.
struct MeshScales {
  double min_value = std::numeric_limits<double>::infinity();
  double max_value = -std::numeric_limits<double>::infinity();
  int max_degree = 0; // of the Lagrange triangles the field is built on (after the split)
  std::array<Vec3, 2> box{
      Vec3{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
           std::numeric_limits<double>::infinity()},
      Vec3{-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
           -std::numeric_limits<double>::infinity()}};
  bool empty() const { return !(min_value <= max_value); }
  void include(const MeshScales &other);
};

struct MeshBuildOptions {
  // Throw hoct::Error listing the problems if any error-level problem is found. With false, the
  // mesh is returned with its problems recorded (for `hoct info`), as complete as possible.
  bool throw_on_error = true;
  // Threads for the per-cell work (Lagrange -> Bernstein conversion); same result for any.
  int threads = 1;
  // A piece of a larger mesh: called once by every build (even one that fails) with the piece's
  // own scales (empty if its input is broken), it returns the whole mesh's, which the field and
  // the geometry then use (a collective step of a distributed build).
  std::function<MeshScales(const MeshScales &)> whole_scales = {};
  // A piece of a larger mesh: a flag per input point shared with other pieces, where the
  // topology does not check the fans (Topology::build's open points).
  std::span<const uint8_t> open_points = {};
};

Mesh build_mesh(const MeshInput &input, const MeshBuildOptions &options = {});
// The same mesh (and report) from an input that is consumed: each of its arrays is released as
// soon as the build no longer needs it (the points once the geometry is built, the rest once
// the field is), so that the input and the finished mesh are never all in memory together.
// The input is left empty but for its source and field names.
Mesh build_mesh(MeshInput &&input, const MeshBuildOptions &options = {});

// Values of one cell's polynomial at arbitrary parametric positions (the thesis' general case).
struct CellSamples {
  int degree = 0;
  std::vector<Vec2> positions; // (u, v) in the reference triangle
  std::vector<double> values;
};

// Topology and geometry from `input` (its node values are not used for the field), the field
// from one sample set per cell, fitted exactly (bernstein_from_samples). An ill-conditioned sample
// set or a discontinuity across an edge is an error naming the cell.
Mesh build_mesh_from_samples(const MeshInput &input, const std::vector<CellSamples> &samples,
                             const MeshBuildOptions &options = {});

} // namespace hoct
