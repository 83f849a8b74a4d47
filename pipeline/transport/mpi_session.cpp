#include "transport/mpi_session.hpp"

#include <algorithm>
#include <cstdlib>
#include <stdexcept>
#include <string>

#include <fmt/format.h>
#include <mpi.h>

namespace lc::farm {

std::string mpi_description() {
#ifdef OMPI_MAJOR_VERSION
  const std::string built = fmt::format("Open MPI {}.{}.{}", OMPI_MAJOR_VERSION, OMPI_MINOR_VERSION, OMPI_RELEASE_VERSION);
#else
  const std::string built = fmt::format("an MPI {}.{} library", MPI_VERSION, MPI_SUBVERSION);
#endif
  // The loaded library's own name and version: its text up to the first
  // comma ("Open MPI v4.1.4, package: ...").
  char text[MPI_MAX_LIBRARY_VERSION_STRING] = {};
  int length = 0;
  std::string loaded = "unknown";
  if (MPI_Get_library_version(text, &length) == MPI_SUCCESS) {
    const std::string all(text, static_cast<std::size_t>(std::clamp(length, 0, MPI_MAX_LIBRARY_VERSION_STRING)));
    loaded = all.substr(0, all.find_first_of(",\n"));
  }
  return fmt::format("MPI: {} (built against; loaded: {}); mpirun or srun --mpi=pmix makes a render a farm", built, loaded);
}

// Open MPI's mpirun sets OMPI_COMM_WORLD_SIZE; PMIx and PMI launchers
// (srun, MPICH's hydra) set PMIX_RANK or PMI_RANK / PMI_SIZE.
bool MpiSession::launched() {
  for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK", "PMI_SIZE"})
    if (const char* s = std::getenv(v); s && *s) return true;
  return false;
}

MpiSession::MpiSession() {
  if (!launched()) return;
  int provided = 0;
  if (MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided) != MPI_SUCCESS)
    throw std::runtime_error("MPI_Init_thread failed");
  active_ = true;
  if (provided < MPI_THREAD_FUNNELED) {
    MPI_Finalize();
    active_ = false;
    throw std::runtime_error("this MPI library cannot run a threaded process (MPI_THREAD_FUNNELED)");
  }
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
  // Ranks on this node: a communicator of those sharing memory with us;
  // subtract the master if it is one of them.
  MPI_Comm node;
  MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &node);
  int node_size = 1;
  MPI_Comm_size(node, &node_size);
  MPI_Group world_group, node_group;
  MPI_Comm_group(MPI_COMM_WORLD, &world_group);
  MPI_Comm_group(node, &node_group);
  int zero = 0, zero_here = MPI_UNDEFINED;
  MPI_Group_translate_ranks(world_group, 1, &zero, node_group, &zero_here);
  MPI_Group_free(&world_group);
  MPI_Group_free(&node_group);
  MPI_Comm_free(&node);
  workers_on_node_ = node_size - (zero_here != MPI_UNDEFINED && size_ > 1 ? 1 : 0);
  if (workers_on_node_ < 1) workers_on_node_ = 1;
}

bool MpiSession::broadcast_from_master(bool value) const {
  if (!active_) return value;
  // A lost rank would never join the broadcast: the master goes on to end
  // the job with its abort, which takes the waiting workers with it.
  if (abort_code_ >= 0) return false;
  int v = value ? 1 : 0;
  MPI_Bcast(&v, 1, MPI_INT, 0, MPI_COMM_WORLD);
  return v != 0;
}

MpiSession::~MpiSession() {
  if (!active_) return;
  if (abort_code_ >= 0) MPI_Abort(MPI_COMM_WORLD, abort_code_);
  MPI_Finalize();
}

}  // namespace lc::farm
