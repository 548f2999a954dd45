// Shared by the commands: read a file and build the checked mesh, timing both.
#pragma once

#include "io/field_selection.hpp"
#include "io/file_contents.hpp"
#include "mesh/gll_nodes.hpp"
#include "mesh/mesh.hpp"

#include <CLI/CLI.hpp>

#include <string>

namespace hoct::cli {

struct LoadedMesh {
  // As read (Lagrange nodes), for the commands that need the nodes themselves (keep_input);
  // else empty: the mesh build consumed it.
  MeshInput input;
  Mesh mesh;
  FileContents contents; // the fields the file offers (Gmsh views), where the reader lists them
  double read_seconds = 0, build_seconds = 0;
};

// Reads `path` (any supported format) and builds the mesh. The reader's warnings are printed
// on stderr ("hoct: warning: ..."). With strict = true, any error-level
// problem throws hoct::Error listing them. With merge_tolerance >= 0, points closer than that
// (relative to the bounding-box diagonal) are merged first (mesh/duplicate_points.hpp).
// `threads` (0: all cores) converts the cells to Bernstein form in parallel. Without
// keep_input the build consumes the input (build_mesh(MeshInput &&)): its arrays are released
// as the mesh takes their place (at 4M cubic cells the input is over a third of the memory).
LoadedMesh load_mesh(const std::string &path, const FieldSelection &field, bool strict,
                     double merge_tolerance = -1, int threads = 1, bool keep_input = false);

// The notes on cells read with their nodes at Gauss-Lobatto-Legendre points (mesh/gll_nodes),
// on stderr: "hoct: note: PATH: N cell(s) ...".
void print_gll_notes(const std::string &path, const GllResampling &resampled);

// --merge-duplicates[=TOL] of a command.
struct MergeOption {
  std::string text;
  CLI::Option *option = nullptr;
  // -1 when not given, 1e-9 when given without a value; throws hoct::Error for a bad value.
  double tolerance() const;
};
void add_merge_option(CLI::App *sub, MergeOption &merge);

} // namespace hoct::cli
