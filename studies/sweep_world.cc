#include "studies/sweep_world.h"

#include <algorithm>
#include <cstdlib>

#ifdef CAMOPT_HAVE_MPI
// The C interface only (no C++ bindings).
#define OMPI_SKIP_MPICXX 1
#define MPICH_SKIP_MPICXX 1
#include <mpi.h>
#endif

// Every call goes to the PMPI_ names of the MPI library (its profiling interface, the same
// functions): Debian's sequential MUMPS (linked for Ipopt) exports stand-ins for MPI_Init,
// MPI_Comm_rank and MPI_Finalize that do nothing and answer rank 0, and it comes before the MPI
// library in the link order, so the plain names would reach those stand-ins.
namespace camopt::studies::sweep {

namespace {

// The number of ranks an MPI launcher started, from its environment (0: not under a launcher).
// Checked before MPI_Init, so that a plain `camopt sweep` never initialises MPI.
int LauncherSize() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_SIZE", "MPI_LOCALNRANKS"}) {
    const char* v = std::getenv(name);
    if (v && *v) return std::max(1, std::atoi(v));
  }
  return std::getenv("PMIX_RANK") ? 1 : 0;
}

}  // namespace

World::~World() { Finish(); }

bool World::Start(std::string& why) {
  const int launched = LauncherSize();
#ifdef CAMOPT_HAVE_MPI
  (void)why;
  if (launched == 0) return true;
  int provided = 0;
  PMPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
  mpi_ = true;
  PMPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  PMPI_Comm_size(MPI_COMM_WORLD, &size_);
  MPI_Comm local;
  PMPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &local);
  PMPI_Comm_size(local, &local_size_);
  PMPI_Comm_free(&local);
  return true;
#else
  if (launched > 1) {
    why = "started as one of " + std::to_string(launched) +
          " MPI ranks, but this camopt was built without MPI (configure with libopenmpi-dev "
          "installed and -DCAMOPT_MPI=ON), so every rank would run every case";
    return false;
  }
  return true;
#endif
}

int World::BroadcastInt(int value) {
#ifdef CAMOPT_HAVE_MPI
  if (mpi_) PMPI_Bcast(&value, 1, MPI_INT, 0, MPI_COMM_WORLD);
#endif
  return value;
}

std::vector<uint64_t> World::BroadcastIndices(const std::vector<uint64_t>& values) {
  std::vector<uint64_t> out = values;
#ifdef CAMOPT_HAVE_MPI
  if (mpi_) {
    unsigned long long n = out.size();
    PMPI_Bcast(&n, 1, MPI_UNSIGNED_LONG_LONG, 0, MPI_COMM_WORLD);
    out.resize(n);
    if (n > 0) PMPI_Bcast(out.data(), static_cast<int>(n), MPI_UINT64_T, 0, MPI_COMM_WORLD);
  }
#endif
  return out;
}

std::string World::GatherToRoot(const std::string& mine) {
#ifdef CAMOPT_HAVE_MPI
  if (mpi_) {
    int length = static_cast<int>(mine.size());
    std::vector<int> lengths(rank_ == 0 ? size_ : 0), offsets(rank_ == 0 ? size_ : 0);
    PMPI_Gather(&length, 1, MPI_INT, lengths.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
    std::string all;
    if (rank_ == 0) {
      long long total = 0;
      for (int r = 0; r < size_; ++r) {
        offsets[r] = static_cast<int>(total);
        total += lengths[r];
      }
      all.resize(static_cast<size_t>(total));
    }
    PMPI_Gatherv(mine.data(), length, MPI_CHAR, all.data(), lengths.data(), offsets.data(), MPI_CHAR,
                0, MPI_COMM_WORLD);
    return all;
  }
#endif
  return mine;
}

void World::Abort(int code) {
#ifdef CAMOPT_HAVE_MPI
  if (mpi_) PMPI_Abort(MPI_COMM_WORLD, code);
#endif
  std::exit(code);
}

void World::Finish() {
#ifdef CAMOPT_HAVE_MPI
  if (mpi_) PMPI_Finalize();
#endif
  mpi_ = false;
}

}  // namespace camopt::studies::sweep
