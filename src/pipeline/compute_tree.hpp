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

// The method's name in results and messages: "exact", "linear", "refine k=4".
std::string method_name(const TreeRequest &request);

} // namespace hoct
