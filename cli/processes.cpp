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

long long Processes::sum(long long value) const {
  long long result = value;
#ifdef DRANGE_HAVE_MPI
  if (joined_) MPI_Allreduce(&value, &result, 1, MPI_LONG_LONG, MPI_SUM, MPI_COMM_WORLD);
#endif
  return result;
}

long long Processes::sum_before(long long value) const {
  long long result = 0;
#ifdef DRANGE_HAVE_MPI
  if (joined_) MPI_Exscan(&value, &result, 1, MPI_LONG_LONG, MPI_SUM, MPI_COMM_WORLD);
  if (rank_ == 0) result = 0;  // MPI_Exscan leaves rank 0's result undefined
#endif
  (void)value;
  return result;
}

std::vector<double> Processes::reduce(std::vector<double> values, Reduction how) const {
#ifdef DRANGE_HAVE_MPI
  if (joined_) {
    const MPI_Op op = how == Reduction::Min ? MPI_MIN : how == Reduction::Max ? MPI_MAX : MPI_SUM;
    MPI_Allreduce(MPI_IN_PLACE, values.data(), static_cast<int>(values.size()), MPI_DOUBLE, op, MPI_COMM_WORLD);
  }
#endif
  (void)how;
  return values;
}

namespace {

int checked_count(std::size_t n, const Processes& group) {
  // Every process learns whether any count is too large, so that all refuse together.
  const int too_large = group.max(n > static_cast<std::size_t>(INT32_MAX) ? 1 : 0);
  if (too_large != 0) throw UsageError("a message between processes exceeds 2^31 - 1 values: use more processes");
  return static_cast<int>(n);
}

}  // namespace

std::vector<double> Processes::all_gather(const std::vector<double>& values) const {
#ifdef DRANGE_HAVE_MPI
  if (joined_) {
    const int mine = checked_count(values.size(), *this);
    std::vector<int> sizes(static_cast<std::size_t>(count_)), offsets(static_cast<std::size_t>(count_));
    MPI_Allgather(&mine, 1, MPI_INT, sizes.data(), 1, MPI_INT, MPI_COMM_WORLD);
    long long total = 0;
    for (int r = 0; r < count_; ++r) {
      offsets[static_cast<std::size_t>(r)] = static_cast<int>(total);
      total += sizes[static_cast<std::size_t>(r)];
    }
    checked_count(static_cast<std::size_t>(total), *this);
    std::vector<double> all(static_cast<std::size_t>(total));
    MPI_Allgatherv(values.data(), mine, MPI_DOUBLE, all.data(), sizes.data(), offsets.data(), MPI_DOUBLE,
                   MPI_COMM_WORLD);
    return all;
  }
#endif
  return values;
}

std::vector<double> Processes::exchange(const std::vector<std::vector<double>>& to_each,
                                        std::vector<std::size_t>& from_each) const {
  from_each.assign(static_cast<std::size_t>(count_), 0);
#ifdef DRANGE_HAVE_MPI
  if (joined_) {
    const auto n = static_cast<std::size_t>(count_);
    std::vector<int> send_sizes(n), send_offsets(n), receive_sizes(n), receive_offsets(n);
    std::size_t send_total = 0;
    for (std::size_t r = 0; r < n; ++r) send_total += to_each[r].size();
    checked_count(send_total, *this);
    std::vector<double> sending;
    sending.reserve(send_total);
    for (std::size_t r = 0; r < n; ++r) {
      send_sizes[r] = static_cast<int>(to_each[r].size());
      send_offsets[r] = static_cast<int>(sending.size());
      sending.insert(sending.end(), to_each[r].begin(), to_each[r].end());
    }
    MPI_Alltoall(send_sizes.data(), 1, MPI_INT, receive_sizes.data(), 1, MPI_INT, MPI_COMM_WORLD);
    std::size_t receive_total = 0;
    for (std::size_t r = 0; r < n; ++r) {
      receive_offsets[r] = static_cast<int>(std::min<std::size_t>(receive_total, INT32_MAX));
      receive_total += static_cast<std::size_t>(receive_sizes[r]);
      from_each[r] = static_cast<std::size_t>(receive_sizes[r]);
    }
    checked_count(receive_total, *this);
    std::vector<double> received(receive_total);
    MPI_Alltoallv(sending.data(), send_sizes.data(), send_offsets.data(), MPI_DOUBLE, received.data(),
                  receive_sizes.data(), receive_offsets.data(), MPI_DOUBLE, MPI_COMM_WORLD);
    return received;
  }
#endif
  from_each[0] = to_each[0].size();
  return to_each[0];
}

std::string Processes::write_in_rank_order(const std::string& path, const std::string& text) const {
#ifdef DRANGE_HAVE_MPI
  if (joined_) {
    const long long offset = sum_before(static_cast<long long>(text.size()));
    MPI_File file;
    int failed = MPI_File_open(MPI_COMM_WORLD, path.c_str(), MPI_MODE_CREATE | MPI_MODE_WRONLY, MPI_INFO_NULL, &file);
    if (max(failed != MPI_SUCCESS ? 1 : 0) != 0) return "cannot create '" + path + "'";
    failed = MPI_File_set_size(file, 0);
    // Pieces of at most 1 GiB: MPI's counts are ints.
    constexpr std::size_t kPiece = std::size_t{1} << 30;
    for (std::size_t at = 0; failed == MPI_SUCCESS && at < text.size(); at += kPiece) {
      const int count = static_cast<int>(std::min(kPiece, text.size() - at));
      MPI_Status status;
      failed = MPI_File_write_at(file, static_cast<MPI_Offset>(offset + static_cast<long long>(at)), text.data() + at,
                                 count, MPI_CHAR, &status);
    }
    if (MPI_File_close(&file) != MPI_SUCCESS) failed = 1;
    if (max(failed != MPI_SUCCESS ? 1 : 0) != 0) return "cannot write '" + path + "'";
    return std::string();
  }
#endif
  (void)path;
  (void)text;
  return "no processes to write with";
}

const Processes& processes() { return *the_processes; }

}  // namespace drange::cli
