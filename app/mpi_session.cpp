#include "mpi_session.h"

#include <cstdlib>

#include "model/plugin.h"

namespace gearbench::app {
namespace {

bool launched_by_mpi() {
  for (const char* var : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK"})
    if (std::getenv(var) != nullptr) return true;
  return false;
}

const MpiBackend& mpi_backend() {
  static const MpiBackend& backend = *reinterpret_cast<decltype(&gearbench_mpi_backend)>(plugin_symbol(
      {GEARBENCH_MPI_FILE, GEARBENCH_MPI_BUILD_PATH, "a sweep under mpirun (MPI)"}, "gearbench_mpi_backend"))();
  return backend;
}

}  // namespace

MpiSession::MpiSession() {
  if (!launched_by_mpi()) return;
  mpi_ = &mpi_backend();
  mpi_->init(rank_, size_);
}

MpiSession::~MpiSession() {
  if (mpi_ != nullptr) mpi_->finalize();
}

std::vector<std::string> MpiSession::gather(const std::string& mine) const {
  if (mpi_ == nullptr) return {mine};
  return mpi_->gather(mine);
}

long MpiSession::broadcast(long value) const { return mpi_ != nullptr ? mpi_->broadcast(value) : value; }

}  // namespace gearbench::app
