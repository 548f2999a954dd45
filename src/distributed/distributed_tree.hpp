// The exact tree over MPI: every rank of MPI_COMM_WORLD (or of a given communicator) holds the
// whole input (each reads the file), builds and checks the mesh of its own piece of contiguous
// cells (mesh/mesh_partition) with the whole mesh's scales; the pieces check the whole mesh
// together (mesh/piece_surface: seams and shape; distributed/distributed_checks: duplicate
// vertices), computes its piece's kept join and split trees (exact/piece_trees) and the ranks
// merge them in a binary reduction tree; rank 0 finishes the tree (flat regions, branches,
// simplification) as compute_tree does, and the pieces draw its arcs on the surface
// (distributed_arc_paths) where asked. Where the pieces find a problem, rank 0 checks the whole
// mesh alone, so that the report is the one a run without MPI gives. The tree is the one `hoct
// tree` computes without MPI, for any number of ranks. Every rank must call it; errors on any rank
// are thrown on all.
#pragma once

#include "distributed/distributed_arc_paths.hpp"
#include "mesh/mesh_input.hpp"
#include "mesh/mesh_partition.hpp"
#include "pipeline/tree_request.hpp"
#include "util/error.hpp"

#include <mpi.h>

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace hoct {

// What one rank did.
struct RankReport {
  int64_t cells = 0;      // its share of the input cells
  int64_t kept_nodes = 0; // its piece's kept nodes (what it passes on)
  int64_t bytes_sent = 0, bytes_received = 0, messages = 0; // in the reduction
  double piece_seconds = 0; // building its piece's mesh and kept trees
  int64_t peak_bytes = 0;   // the process's peak resident memory
};

struct DistributedOutcome {
  TreeOutcome outcome; // on rank 0; elsewhere an empty tree
  int rank = 0, ranks = 1;
  std::vector<RankReport> reports; // on rank 0: every rank's, by rank
  // On rank 0: empty when the pieces checked the whole mesh together (their seams, shape and
  // duplicate vertices); else why rank 0 checked the whole mesh alone (for the report a run
  // without MPI gives).
  std::string whole_check;
  // On rank 0: empty when the pieces computed the tree; else why rank 0 computed it from the
  // whole mesh alone (a Reeb graph whose seams between pieces the gluing could not follow; what
  // the PL methods' pieces do not compute).
  std::string whole_tree;
  // On rank 0: how the pieces drew the arcs on the surface (when asked to and they did).
  ArcPathCounts arc_paths;
};

// One rank's share of a mesh no rank holds whole (a partitioned file each rank reads its pieces
// of: distributed/distributed_read): its input cells, a contiguous range of the whole's, and the
// points they use, numbered as the whole numbers them.
struct RankInput {
  MeshPiece piece;            // with its points' spans over the ranks (MeshPiece::point_span)
  int64_t first_triangle = 0; // the whole's triangles before its first cell (mesh_partition)
  int64_t whole_cells = 0, whole_points = 0;
  bool cells_split = false; // the whole has cells other than Lagrange triangles
  std::string source, field_name;
  std::optional<InputFingerprint> fingerprint; // the whole's, on rank 0
  // The ranks' way to the whole mesh on rank 0 (the others get an empty one), for the report of
  // a mesh the pieces found a problem in and a Reeb graph the pieces cannot glue: collective,
  // every rank calls it together.
  std::function<MeshInput()> read_whole;
};

DistributedOutcome distributed_tree(const MeshInput &whole, const TreeRequest &request);
// The same over the ranks of `comm` (every one of them must call it; rank 0 of `comm` gets the
// tree). The library works on its own duplicate of `comm`: no message of the caller's is seen.
DistributedOutcome distributed_tree(const MeshInput &whole, const TreeRequest &request,
                                    MPI_Comm comm);
// The same from each rank's share alone.
DistributedOutcome distributed_tree(RankInput input, const TreeRequest &request, MPI_Comm comm);

// An error every rank throws together (at one collective step), with the message of the lowest
// rank that failed: each rank may then end normally (rank 0 reports it). Any other exception is
// one rank's alone: that rank must abort the job (MPI_Abort), as the others wait for it.
class AgreedError : public Error {
public:
  using Error::Error;
};

// A collective step (every rank calls it): throws AgreedError on every rank if any rank's
// `failure` is not empty.
void agree_on_failure(const std::string &failure);
// The same over the ranks of `comm`.
void agree_on_failure(const std::string &failure, MPI_Comm comm);

} // namespace hoct
