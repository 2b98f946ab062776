// The processes of a run and what they say to each other: MPI when the binary is built with it
// (RBCSIM_MPI) and started by an MPI launcher (mpirun, mpiexec), otherwise one process that talks
// to itself. Everything above this file runs the same code on one process and on many (the
// waLBerla way): a one-process communicator copies where MPI would send.
//
// Determinism: nothing here adds floating-point values across processes. gather_to_root hands
// rank 0 every rank's values in rank order, so a sum over them is taken in one order whatever the
// rank count; max and any are exact in any order.
#pragma once

#include <memory>
#include <span>
#include <vector>

namespace rbcsim::parallel {

// Whether this binary was built with MPI (the CMake option RBCSIM_MPI).
bool built_with_mpi();

// Whether an MPI launcher started this process (it sets OMPI_COMM_WORLD_SIZE, PMI_SIZE or
// PMIX_RANK). Only then is MPI initialised: a plain `rbcsim ...` does not pay MPI's start-up (a
// third of a second here) and never depends on a launcher being installed.
bool launched_by_mpi();

// The process count an MPI launcher announced (OMPI_COMM_WORLD_SIZE or PMI_SIZE), 1 without one.
// A binary built without MPI checks it: started by `mpirun -np 4` it would otherwise run four
// independent copies of the same run.
int launcher_process_count();

// MPI for the lifetime of main(): initialised when built with MPI and launched by mpirun,
// finalised at the end. At most one per process.
class MpiSession {
 public:
  MpiSession(int& argc, char**& argv);
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;
  // Whether MPI was initialised (and not yet finalised).
  static bool active();
};

// For main()'s failure path (an exception that ended a command on this process): whether every
// process of the run reaches this call within `timeout_s` seconds of the first. Then the failure
// was the same everywhere (results are identical on every process), and each can exit with its
// code; otherwise one process failed alone and the run must be aborted. A non-blocking barrier on
// a communicator of its own, created by MpiSession, so it never meets another collective. Without
// a session: true at once.
bool every_process_fails_together(double timeout_s);

class Communicator {
 public:
  // Every process of the run (MPI_COMM_WORLD), or this process alone without an active session.
  static Communicator world();
  // This process alone, even within an MPI run (a baseline measured beside the distributed run).
  static Communicator self();

  int rank() const { return rank_; }
  int size() const { return size_; }
  bool is_root() const { return rank_ == 0; }

  // Sends `send` to rank `destination` and receives receive.size() values from rank `source`,
  // both with `tag`; deadlock-free in a ring (MPI_Sendrecv). On one process (destination and
  // source are this rank) a copy. Throws rbcsim::RuntimeFailure if MPI reports an error or the
  // received count differs.
  void send_receive(std::span<const double> send, int destination, std::span<double> receive,
                    int source, int tag) const;
  // Rank 0: every rank's values concatenated in rank order; other ranks: empty.
  std::vector<double> gather_to_root(std::span<const double> values) const;
  // Every rank: every rank's values concatenated in rank order (copies, one collective).
  std::vector<double> gather_to_all(std::span<const double> values) const;
  // Rank 0 gives per_rank[r] (ignored elsewhere) to rank r, which expects `count` values. Throws
  // rbcsim::RuntimeFailure when a count disagrees.
  std::vector<double> scatter_from_root(const std::vector<std::vector<double>>& per_rank,
                                        std::size_t count) const;
  // Rank 0's values on every rank (values.size() must agree).
  void broadcast_from_root(std::span<double> values) const;
  // Whether any rank passed true.
  bool any(bool local) const;
  // The largest of the ranks' values (exact, order-independent).
  double max(double local) const;
  void barrier() const;
  // The processes that pass the same colour, in rank order (collective; MPI_Comm_split).
  Communicator split(int colour) const;
  // Stops every process of the run with this exit code (MPI_Abort); on one process, std::exit.
  [[noreturn]] void abort(int exit_code) const;
  // The MPI communicator (points to an MPI_Comm) for a library that takes one, such as parallel
  // HDF5; null on one process without MPI.
  const void* mpi_comm() const;

 private:
  struct Handle;
  Communicator(std::shared_ptr<const Handle> handle, int rank, int size);
  std::shared_ptr<const Handle> handle_;  // null: one process without MPI
  int rank_ = 0;
  int size_ = 1;
};

}  // namespace rbcsim::parallel
