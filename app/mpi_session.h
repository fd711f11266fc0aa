#pragma once
// MPI for the duration of a sweep started by mpirun/mpiexec (their environment says so); a
// plain start runs serially without touching MPI. MPI itself is the plugin libgearbench_mpi.so
// (mpi_plugin.cpp), loaded only then: Open MPI's libraries (hwloc, libevent, PMIx: a dozen
// shared objects, ~3 ms and ~2 MiB) would otherwise be loaded by every run of gearbench.
#include <string>
#include <vector>

namespace gearbench::app {

/// The plugin's functions (mpi_plugin.cpp), over MPI_COMM_WORLD.
struct MpiBackend {
  void (*init)(int& rank, int& size) = nullptr;  ///< MPI_Init, then this rank and the size
  void (*finalize)() = nullptr;
  /// Every rank's text on rank 0, in rank order (elsewhere: empty).
  std::vector<std::string> (*gather)(const std::string& mine) = nullptr;
  long (*broadcast)(long value) = nullptr;  ///< rank 0's value on every rank
};

class MpiSession {
 public:
  MpiSession();  ///< MPI_Init when started by an MPI launcher (PluginError if MPI is not built)
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;
  [[nodiscard]] int rank() const { return rank_; }
  [[nodiscard]] int size() const { return size_; }
  /// Every rank's text on rank 0, in rank order (elsewhere: empty); serially {mine}.
  [[nodiscard]] std::vector<std::string> gather(const std::string& mine) const;
  /// Rank 0's value on every rank.
  [[nodiscard]] long broadcast(long value) const;

 private:
  const MpiBackend* mpi_ = nullptr;  ///< null: a serial run
  int rank_ = 0;
  int size_ = 1;
};

}  // namespace gearbench::app

/// The plugin's entry point (mpi_plugin.cpp).
extern "C" const gearbench::app::MpiBackend* gearbench_mpi_backend();
