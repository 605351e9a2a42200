// cli/command_delaunay_split.cpp: `mpirun -np P drange delaunay POINTS -o OUT`: the
// triangulation split among P processes (cli/processes.hpp), written once, by process 0.
//
// Every process reads the input and computes one block (drange::delaunay_block: the simplices
// whose smallest vertex, in the kd-tree's order, falls in its share of the points); process 0
// gathers the blocks, which hold every simplex exactly once, and writes the file as a single
// process would (the same simplices as vertex sets, in block order; the neighbours linked
// afterwards). A failure on any process stops them all with one message and one exit code, and
// nothing is written.
#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include "commands.hpp"
#include "drange/delaunay.hpp"
#include "drange/errors.hpp"
#include "drange/formats.hpp"
#include "drange/io.hpp"
#include "exit_codes.hpp"
#include "processes.hpp"

namespace drange::cli {
namespace {

// The figures each process sends for --stats, in this order.
enum Figure { kSimplices, kSearch, kTotal, kMemory, kFigures };

void print_stats(const Processes& group, const std::vector<double>& figures, std::size_t points, int dim) {
  double largest = 0.0, sum = 0.0, simplices = 0.0;
  for (int r = 0; r < group.count(); ++r) {
    const double* f = &figures[static_cast<std::size_t>(r) * kFigures];
    std::fprintf(stderr, "rank=%d points_read=%zu ghost_points=0 simplices=%.0f time_search=%.3fs time_total=%.3fs peak_rss=%.1fMiB\n",
                 r, points, f[kSimplices], f[kSearch], f[kTotal], f[kMemory] / (1 << 20));
    largest = std::max(largest, f[kSearch]);
    sum += f[kSearch];
    simplices += f[kSimplices];
  }
  // Every process reads every point, so the only exchange is the gathering of the blocks.
  const double gathered = (simplices - figures[kSimplices]) * (dim + 1) * 4.0;
  std::fprintf(stderr, "ranks=%d simplices=%.0f balance=%.3f exchange_bytes=%.0f\n", group.count(), simplices,
               sum > 0 ? largest / (sum / group.count()) : 1.0, gathered);
}

}  // namespace

int triangulate_across_processes(const std::string& input, const Arguments& arguments, const std::string& output,
                                 OutputFormat format, const Options& options) {
  const Processes& group = processes();
  if (input == "-") throw UsageError("across processes (mpirun) the input must be a file, not standard input");
  for (const char* option : {"only", "furthest-site", "svg", "variant", "algorithm"})
    if (arguments.has(option)) throw UsageError(std::string("--") + option + " does not run across processes (mpirun)");
  PointCloud points;
  Triangulation part;
  std::exception_ptr failure;
  int code = kExitSuccess;
  try {
    points = read_points(input);
    part = delaunay_block(points, group.rank(), group.count(), options);
  } catch (...) {
    failure = std::current_exception();
    code = report_failure(failure, "delaunay", false);
  }
  const int worst = group.max(code);
  if (worst != kExitSuccess) {
    // The lowest process with the worst code speaks (a bad input fails every process the same
    // way), so that the message and the exit status agree.
    const int speaker = -group.max(code == worst ? -group.rank() : -group.count());
    if (group.rank() == speaker) report_failure(failure, "delaunay", true);
    return worst;
  }
  std::vector<std::int32_t> simplices = group.gather(part.simplices);
  const std::vector<double> figures = group.gather(std::vector<double>{
      static_cast<double>(part.size()), part.stats.seconds_search, part.stats.seconds_total,
      static_cast<double>(part.stats.peak_rss_bytes)});
  if (group.rank() != 0) return kExitSuccess;

  Triangulation whole;
  whole.dim = part.dim;
  whole.num_points = part.num_points;
  whole.simplices = std::move(simplices);
  whole.duplicates = part.duplicates;
  whole.stats = part.stats;
  whole.stats.simplices = whole.size();
  if (options.compute_neighbors) link_neighbours(whole);
  write_delaunay_outputs(output, format, points, whole, arguments);
  if (arguments.has("stats")) print_stats(group, figures, points.size(), whole.dim);
  return kExitSuccess;
}

}  // namespace drange::cli
