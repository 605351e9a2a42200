// cli/processes.cpp: see processes.hpp. The MPI calls are compiled in with DRANGE_HAVE_MPI.
#include "processes.hpp"

#include <algorithm>
#include <cstdlib>
#include <initializer_list>
#include <new>
#include <string>

#include "drange/errors.hpp"

#ifdef DRANGE_HAVE_MPI
#include <mpi.h>
#endif

namespace drange::cli {
namespace {

const Processes* the_processes = nullptr;

}  // namespace

namespace {

int from_environment(std::initializer_list<const char*> names, int otherwise) {
  for (const char* name : names) {
    const char* value = std::getenv(name);
    if (value != nullptr && std::atoi(value) >= 0 && *value != '\0') return std::atoi(value);
  }
  return otherwise;
}

}  // namespace

int launched_processes() { return std::max(1, from_environment({"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"}, 1)); }

int launched_rank() { return from_environment({"OMPI_COMM_WORLD_RANK", "PMI_RANK"}, 0); }

Processes::Processes(int* argc, char*** argv) {
  the_processes = this;
  if (launched_processes() <= 1) return;
#ifdef DRANGE_HAVE_MPI
  MPI_Init(argc, argv);
  joined_ = true;
  MPI_Comm_size(MPI_COMM_WORLD, &count_);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
#else
  (void)argc;
  (void)argv;
  throw UsageError("started as " + std::to_string(launched_processes()) +
                   " processes (mpirun), but this drange is built without MPI (install libopenmpi-dev and rebuild)");
#endif
}

Processes::~Processes() {
#ifdef DRANGE_HAVE_MPI
  if (joined_) MPI_Finalize();
#endif
  the_processes = nullptr;
}

int Processes::max(int value) const {
  int result = value;
#ifdef DRANGE_HAVE_MPI
  if (joined_) MPI_Allreduce(&value, &result, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
#endif
  return result;
}

namespace {

#ifdef DRANGE_HAVE_MPI
template <class T>
std::vector<T> gather_to_first(const std::vector<T>& values, MPI_Datatype type, int count, int rank) {
  // MPI counts are ints: every process learns the total first, so that all refuse together.
  const long long mine_long = static_cast<long long>(values.size());
  long long total = 0;
  MPI_Allreduce(&mine_long, &total, 1, MPI_LONG_LONG, MPI_SUM, MPI_COMM_WORLD);
  if (total > INT32_MAX)
    throw UsageError("the result (" + std::to_string(total) + " values) is too large to gather in one process");
  const int mine = static_cast<int>(values.size());
  std::vector<int> sizes(static_cast<std::size_t>(count)), offsets(static_cast<std::size_t>(count));
  MPI_Gather(&mine, 1, MPI_INT, sizes.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
  std::vector<T> all;
  int room = 1;  // whether process 0 could make room for everything; all learn it before Gatherv
  if (rank == 0) {
    int at = 0;
    for (int r = 0; r < count; ++r) {
      offsets[static_cast<std::size_t>(r)] = at;
      at += sizes[static_cast<std::size_t>(r)];
    }
    try {
      all.resize(static_cast<std::size_t>(total));
    } catch (const std::bad_alloc&) {
      room = 0;
    }
  }
  MPI_Bcast(&room, 1, MPI_INT, 0, MPI_COMM_WORLD);
  if (room == 0) throw std::bad_alloc();
  MPI_Gatherv(values.data(), mine, type, all.data(), sizes.data(), offsets.data(), type, 0, MPI_COMM_WORLD);
  return all;
}
#endif

}  // namespace

std::vector<std::int32_t> Processes::gather(const std::vector<std::int32_t>& values) const {
#ifdef DRANGE_HAVE_MPI
  if (joined_) return gather_to_first(values, MPI_INT32_T, count_, rank_);
#endif
  return values;
}

std::vector<double> Processes::gather(const std::vector<double>& values) const {
#ifdef DRANGE_HAVE_MPI
  if (joined_) return gather_to_first(values, MPI_DOUBLE, count_, rank_);
#endif
  return values;
}

const Processes& processes() { return *the_processes; }

}  // namespace drange::cli
