// MPI for the command line: whether this process was started by mpirun (or another MPI
// launcher), and MPI initialised for as long as a session object lives. A process not started
// by a launcher never initialises MPI (a singleton MPI_Init costs time and may warn).
#pragma once

namespace hoct {

// Started as one of several processes by an MPI launcher: Open MPI's OMPI_COMM_WORLD_SIZE (PMI's
// PMI_SIZE, MPICH's MPI_LOCALNRANKS) above 1, and the launcher (mpirun, orted, hydra_pmi_proxy,
// slurmstepd, ...) as the parent process, not an MPI program that runs hoct as a tool. HOCT_MPI=1
// or 0 in the environment decides instead. `mpirun -np 1` runs as one process without MPI: the
// same tree.
bool launched_by_mpi();

class MpiSession {
public:
  MpiSession();  // MPI_Init (once per process)
  ~MpiSession(); // MPI_Finalize
  MpiSession(const MpiSession &) = delete;
  MpiSession &operator=(const MpiSession &) = delete;
  int rank() const { return rank_; }
  int size() const { return size_; }

private:
  int rank_ = 0, size_ = 1;
};

} // namespace hoct
