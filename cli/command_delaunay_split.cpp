// cli/command_delaunay_split.cpp: `mpirun -np P drange delaunay POINTS -o OUT`: the
// triangulation split among P processes (cli/processes.hpp), written once, by process 0.
//
// Each process reads its share of the file (cli/split_read.hpp), the points go to P blocks of
// space, and each process finds the simplices whose smallest vertex is one of its own points,
// fetching the other processes' points where its stars need them (cli/split_rounds.hpp): no
// process holds every point. Process 0 gathers the simplices (input indices) and writes the file
// as a single process would (the same simplices as vertex sets; the neighbours linked
// afterwards). A failure on any process stops them all with one message and one exit code
// (cli/agreement.hpp), and nothing is written.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <charconv>
#include <string>
#include <vector>

#include <sys/resource.h>

#include "agreement.hpp"
#include "command_common.hpp"
#include "commands.hpp"
#include "drange/delaunay.hpp"
#include "drange/errors.hpp"
#include "drange/formats.hpp"
#include "drange/io.hpp"
#include "exit_codes.hpp"
#include "processes.hpp"
#include "split_read.hpp"
#include "split_rounds.hpp"

namespace drange::cli {
namespace {

using Clock = std::chrono::steady_clock;

// The figures each process sends for --stats, in this order.
enum Figure {
  kRead, kOwned, kGhosts, kRounds, kSimplices, kTimeRead, kTimeSearch, kTimeTotal, kMemory, kBytes, kFigures
};

void print_stats(const Processes& group, const std::vector<double>& figures) {
  double largest = 0.0, sum = 0.0, simplices = 0.0, bytes = 0.0;
  for (int r = 0; r < group.count(); ++r) {
    const double* f = &figures[static_cast<std::size_t>(r) * kFigures];
    std::fprintf(stderr,
                 "rank=%d points_read=%.0f points_owned=%.0f ghost_points=%.0f rounds=%.0f simplices=%.0f "
                 "time_read=%.3fs time_search=%.3fs time_total=%.3fs peak_rss=%.1fMiB\n",
                 r, f[kRead], f[kOwned], f[kGhosts], f[kRounds], f[kSimplices], f[kTimeRead], f[kTimeSearch],
                 f[kTimeTotal], f[kMemory] / (1 << 20));
    largest = std::max(largest, f[kTimeSearch]);
    sum += f[kTimeSearch];
    simplices += f[kSimplices];
    bytes += f[kBytes];
  }
  // exchange_bytes: the points and requests the processes sent one another (not the gathering).
  std::fprintf(stderr, "ranks=%d simplices=%.0f balance=%.3f exchange_bytes=%.0f\n", group.count(), simplices,
               sum > 0 ? largest / (sum / group.count()) : 1.0, bytes);
}

double peak_rss_bytes() {
  struct rusage usage {};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) * 1024.0;  // Linux: KiB
}

// Exact copies as delaunay() lists them: by input index.
std::vector<Duplicate> ordered_duplicates(const std::vector<double>& pairs) {
  std::vector<Duplicate> duplicates;
  for (std::size_t i = 0; i + 1 < pairs.size(); i += 2)
    duplicates.push_back(Duplicate{static_cast<std::int64_t>(pairs[i]), static_cast<std::int64_t>(pairs[i + 1])});
  std::sort(duplicates.begin(), duplicates.end(), [](const Duplicate& a, const Duplicate& b) { return a.index < b.index; });
  return duplicates;
}

// The qhull layout written by all the processes together: each formats its own simplices, and
// MPI-IO writes them at offsets from a prefix sum into a temporary file next to `output`,
// which process 0 renames over it once every process has written (or removes).
void write_qhull_together(const Processes& group, const Agreement& agree, const std::string& output,
                          const std::vector<std::int32_t>& simplices, int dim, const std::vector<double>& duplicates,
                          const std::vector<double>& figures, const Arguments& arguments) {
  const auto width = static_cast<std::size_t>(dim) + 1;
  const long long total = group.sum(static_cast<long long>(simplices.size() / width));
  std::string text;
  agree.run([&] {
    // write_index_rows' layout: process 0 writes the count line, every process its rows.
    if (group.rank() == 0) text = std::to_string(total) + "\n";
    text.reserve(text.size() + simplices.size() * 12);
    char digits[16];
    for (std::size_t i = 0; i < simplices.size(); ++i) {
      const auto end = std::to_chars(digits, digits + sizeof digits, simplices[i]).ptr;
      text.append(digits, end);
      text.push_back((i + 1) % width == 0 ? '\n' : ' ');
    }
  });
  const std::string temporary = output + ".drange-split.tmp";
  const std::string failed = group.write_in_rank_order(temporary, text);
  std::string().swap(text);
  agree.run([&] {
    if (group.rank() != 0) return;
    if (!failed.empty() || std::rename(temporary.c_str(), output.c_str()) != 0) {
      std::remove(temporary.c_str());
      throw InputError("cannot write '" + output + "'" + (failed.empty() ? std::string() : " (" + failed + ")"));
    }
    const std::vector<Duplicate> copies = ordered_duplicates(duplicates);
    if (!copies.empty() && !arguments.has("quiet")) std::fprintf(stderr, "drange: %s\n", duplicates_message(copies).c_str());
    if (arguments.has("stats")) print_stats(group, figures);
  });
}

}  // namespace

int triangulate_across_processes(const std::string& input, const Arguments& arguments, const std::string& output,
                                 OutputFormat format, const Options& options) {
  const Processes& group = processes();
  if (input == "-") throw UsageError("across processes (mpirun) the input must be a file, not standard input");
  for (const char* option : {"only", "furthest-site", "svg", "variant", "algorithm"})
    if (arguments.has(option)) throw UsageError(std::string("--") + option + " does not run across processes (mpirun)");
  if (format == OutputFormat::Vtu || format == OutputFormat::Off)
    throw UsageError("the vtu and off formats hold the points: across processes (mpirun) write qhull, json or npz");
  const Agreement agree(group);
  try {
    const auto start = Clock::now();
    PointShare share = read_point_share(input, group, agree);
    const double time_read = std::chrono::duration<double>(Clock::now() - start).count();
    const int dim = share.points.dim;
    const std::int64_t total = share.total;
    const double points_read = static_cast<double>(share.points.size());
    const SplitPart part = triangulate_share(std::move(share), group, agree, options);
    const auto width = static_cast<std::size_t>(dim) + 1;
    std::vector<std::int32_t> simplices;
    const bool together = format == OutputFormat::Qhull && output != "-" && !arguments.has("neighbors");
    if (!together) simplices = group.gather(part.simplices);
    const std::vector<double> duplicates = group.gather(part.duplicates);
    const std::vector<double> figures = group.gather(std::vector<double>{
        points_read, static_cast<double>(part.points_owned), static_cast<double>(part.ghost_points),
        static_cast<double>(part.rounds), static_cast<double>(part.simplices.size() / width), time_read,
        part.seconds_search, std::chrono::duration<double>(Clock::now() - start).count(),
        peak_rss_bytes(), part.bytes_sent});
    if (together) {
      write_qhull_together(group, agree, output, part.simplices, dim, duplicates, figures, arguments);
      return kExitSuccess;
    }
    agree.run([&] {
      if (group.rank() != 0) return;
      Triangulation whole;
      whole.dim = dim;
      whole.num_points = static_cast<std::size_t>(total);
      whole.simplices = std::move(simplices);
      whole.duplicates = ordered_duplicates(duplicates);
      whole.stats.points = whole.num_points;
      whole.stats.distinct_points = whole.num_points - whole.duplicates.size();
      whole.stats.simplices = whole.size();
      if (options.compute_neighbors) link_neighbours(whole);
      write_delaunay_outputs(output, format, PointCloud(), whole, arguments);
      if (arguments.has("stats")) print_stats(group, figures);
    });
  } catch (const Stopped& stopped) {
    return stopped.code;
  }
  return kExitSuccess;
}

}  // namespace drange::cli
