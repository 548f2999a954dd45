// The one library call from a mesh and a request to a tree: the domain check, the tree by the
// requested method, the contraction of flat regions, simplification, branches, arcs' paths and
// the statistics. The command line, the Python module, the ParaView filter and the benchmark
// each translate their inputs into a TreeRequest and the TreeOutcome into their outputs.
#pragma once

#include "mesh/mesh.hpp"
#include "pipeline/tree_request.hpp"

namespace hoct {

// `input` (the mesh's nodes as read) is needed by TreeMethod::Linear only. Throws hoct::Error
// for a domain the request cannot be computed on, or a request that is not consistent.
TreeOutcome compute_tree(const Mesh &mesh, const TreeRequest &request,
                         const MeshInput *input = nullptr);

// The same, consuming the mesh and the input: by TreeMethod::Linear, whose tree needs the input's
// nodes and not the checked mesh, the mesh is released once checked and the input once split into
// linear triangles (the mesh's topology, maps and Bernstein field are most of the memory; the
// peak is then the larger of the mesh build's and the PL tree's, not their sum). Other methods
// release them at the end.
TreeOutcome compute_tree(Mesh &&mesh, const TreeRequest &request, MeshInput &&input);

// What the rest of the pipeline takes from the mesh a tree was computed on (a whole mesh, or
// the pieces of a distributed one: pipeline/distributed_tree).
struct TreeContext {
  std::vector<std::string> warnings; // why the result is forced
  std::optional<InputFingerprint> fingerprint;
  int64_t input_cells = 0;
  MeshBuildTimes build_times;
  bool cells_split = false; // the input had quadrilaterals or Bezier cells
  double precision = 0;     // Field::precision
  // Nodes' cells to the input's (null: they name the input's cells already).
  const CellOrigins *origins = nullptr;
};

// The steps after the tree: flat regions contracted, branches, simplification, the precision,
// arcs' paths and the input's cells.
TreeOutcome finish_tree(TreeResult tree, const TreeRequest &request, const TreeContext &context);

// The method's name in results and messages: "exact", "linear", "refine k=4".
std::string method_name(const TreeRequest &request);

} // namespace hoct
