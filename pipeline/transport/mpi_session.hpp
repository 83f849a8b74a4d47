#pragma once
// MPI for the farm: initialised only when an MPI launcher started this
// process (mpirun, mpiexec, srun), recognised by the environment it sets.
// A plain run skips MPI_Init altogether: that is what an MPI singleton
// would be (one rank, threads only) without the ~0.3 s Open MPI spends
// starting one.  Only the thread that made the session calls MPI
// (MPI_THREAD_FUNNELED).

#include <string>

namespace lc::farm {

// "MPI: Open MPI 4.1.4 (built against; loaded: Open MPI v4.1.4)": the MPI
// this binary was compiled with and the library it loaded, for `lightcone
// --version`.  Needs no MPI_Init (MPI_Get_library_version may precede it).
std::string mpi_description();

class MpiSession {
 public:
  MpiSession();
  ~MpiSession();  // MPI_Finalize
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;

  bool active() const { return active_; }
  int rank() const { return rank_; }
  int size() const { return size_; }
  // Workers sharing this node (the master, rank 0, does not count: it
  // sleeps while it waits), at least 1.
  int workers_on_node() const { return workers_on_node_; }

  // Rank 0's `value` on every rank (`value` itself without MPI): how the
  // master tells workers whether a multi-step job (the showcase) goes on.
  bool broadcast_from_master(bool value) const;

  // Whether the environment says an MPI launcher started us.
  static bool launched();

  // A worker was lost (transport/mpi_master.hpp): MPI_Finalize would wait for it
  // forever, so the session ends the job with MPI_Abort(`code`) instead,
  // and the master broadcasts nothing more.
  // Const like the rest: it changes nothing but how the session ends.
  void end_with_abort(int code) const { abort_code_ = code; }

 private:
  mutable int abort_code_ = -1;
  bool active_ = false;
  int rank_ = 0, size_ = 1, workers_on_node_ = 1;
};

}  // namespace lc::farm
