// cli/processes.hpp: the processes a run is split among. `mpirun -np P drange delaunay ...`
// starts P of them; with MPI built in (CMake finds it) they join one MPI world, otherwise a
// launch of more than one is refused. A plain `drange` run is one process and never touches MPI.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace drange::cli {

class Processes {
 public:
  // Joins the launch's world when the environment says that mpirun started more than one
  // process (OMPI_COMM_WORLD_SIZE, PMI_SIZE); throws UsageError then if MPI is not built in.
  Processes(int* argc, char*** argv);
  ~Processes();
  Processes(const Processes&) = delete;
  Processes& operator=(const Processes&) = delete;

  int count() const { return count_; }
  int rank() const { return rank_; }

  // Every process calls these, in the same order.
  // The largest `value` over the processes, on every process.
  int max(int value) const;
  // Process 0 gets every process's `values`, in rank order; the others an empty vector.
  std::vector<std::int32_t> gather(const std::vector<std::int32_t>& values) const;
  std::vector<double> gather(const std::vector<double>& values) const;

  // The sum of `value` over all processes; over the processes of lower rank (0 on rank 0).
  long long sum(long long value) const;
  long long sum_before(long long value) const;
  // Element by element over the processes, on every process.
  enum class Reduction { Min, Max, Sum };
  std::vector<double> reduce(std::vector<double> values, Reduction how) const;
  // Every process's `values`, in rank order, on every process.
  std::vector<double> all_gather(const std::vector<double>& values) const;
  // Sends to_each[r] to process r; returns what the processes sent to this one, in rank order,
  // and the number of values from each in `from_each`. Throws UsageError (on every process)
  // where a count exceeds MPI's int.
  std::vector<double> exchange(const std::vector<std::vector<double>>& to_each, std::vector<std::size_t>& from_each) const;
  // Writes every process's `text` into the file `path` (created or emptied), in rank order, all
  // together (MPI-IO). Returns the system's message for the first failure on any process, on
  // every process; empty when all wrote.
  std::string write_in_rank_order(const std::string& path, const std::string& text) const;

 private:
  int count_ = 1;
  int rank_ = 0;
  bool joined_ = false;
};

// The run's processes (main() makes them before any command runs).
const Processes& processes();

// The number of processes the environment says mpirun started (1 without mpirun), and this
// one's rank among them (0 without mpirun): known before, and without, MPI.
int launched_processes();
int launched_rank();

}  // namespace drange::cli
