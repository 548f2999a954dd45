#include "distributed/mpi_session.hpp"

#include <mpi.h>

#include <cstdlib>
#include <fstream>
#include <string>

#include <unistd.h>

namespace hoct {

namespace {

// The name of this process's parent (Linux), empty if unknown.
std::string parent_name() {
  std::ifstream comm("/proc/" + std::to_string(getppid()) + "/comm");
  std::string name;
  std::getline(comm, name);
  return name;
}

} // namespace

bool launched_by_mpi() {
  if (const char *forced = std::getenv("HOCT_MPI"))
    return std::string(forced) == "1";
  // The size, not the variables' presence: a process that an MPI program (pvpython, a DOLFINx
  // script: a singleton of size 1) starts inherits them; and the launcher's daemon as the parent,
  // not a rank of an MPI job that runs hoct as a tool (pvbatch under mpirun).
  bool several = false;
  for (const char *name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "MPI_LOCALNRANKS"})
    if (const char *v = std::getenv(name); v && std::atoi(v) > 1)
      several = true;
  if (!several)
    return false;
  const std::string parent = parent_name();
  if (parent.empty())
    return true;
  for (const char *launcher : {"mpirun", "mpiexec", "orterun", "orted", "prted", "prterun",
                               "hydra_pmi_proxy", "slurmstepd"})
    if (parent == launcher)
      return true;
  return false;
}

MpiSession::MpiSession() {
  int initialized = 0;
  MPI_Initialized(&initialized);
  if (!initialized)
    MPI_Init(nullptr, nullptr);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
}

MpiSession::~MpiSession() {
  int finalized = 0;
  MPI_Finalized(&finalized);
  if (!finalized)
    MPI_Finalize();
}

} // namespace hoct
