// `mpirun -np N hoct tree FILE ...`: the distributed tree (distributed/distributed_tree). Every
// rank reads the file, or its pieces of a .pvtu; rank 0 writes the outputs and the summary.
#pragma once

#include "io/field_selection.hpp"
#include "pipeline/tree_request.hpp"

#include <string>

namespace hoct::cli {

struct DistributedTreeRun {
  std::string file, json, svg, vtp;
  FieldSelection field;
  double merge_tolerance = -1;
  bool no_timings = false, quiet = false, branches = false;
};

// Whether hoct was started by an MPI launcher and built with MPI (then run_tree_mpi applies).
bool under_mpi();
void run_tree_mpi(const DistributedTreeRun &run, TreeRequest request);

} // namespace hoct::cli
