// bench/run_one.cpp: one measurement, one process.
//
//   drange_bench_run --peer NAME --input FILE [--threads N] [--variant V]
//
// Reads the points (not timed), builds the triangulation once with the named peer (timed
// around construction only) and prints one line on standard output:
//
//   RESULT peer=NAME status=ok n=N d=D simplices=S seconds=T peak_rss=B input_rss=B [...]
//
// peak_rss is this process's getrusage ru_maxrss (bytes): the input points read by
// drange::read_points, plus whatever the peer allocated. input_rss is the same measure taken
// just before the construction, so peak_rss - input_rss is the peer's own share. status is
// "n/a" when the peer does not handle the dimension, "not-built" when the peer's library was
// not found at configure time, "oom" when the construction threw std::bad_alloc, "error"
// otherwise (with a message on standard error).
#include <sys/resource.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <iostream>
#include <map>
#include <new>
#include <string>

#include "drange/io.hpp"
#include "peer.hpp"

namespace {

using drange::bench::PeerResult;
using drange::bench::RunOptions;
using Runner = PeerResult (*)(const drange::PointCloud&, const RunOptions&);

std::size_t peak_rss_bytes() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<std::size_t>(usage.ru_maxrss) * 1024;  // Linux: kibibytes
}

const std::map<std::string, Runner>& peers() {
  static const std::map<std::string, Runner> table = {
      {"drange", drange::bench::run_drange},
#ifdef DRANGE_BENCH_HAVE_CGAL
      {"cgal2", drange::bench::run_cgal2},
      {"cgal3", drange::bench::run_cgal3},
      {"cgal-dd", drange::bench::run_cgal_dd_static},
      {"cgal-dd-dyn", drange::bench::run_cgal_dd_dynamic},
#endif
#ifdef DRANGE_BENCH_HAVE_CGAL_TBB
      {"cgal3-par", drange::bench::run_cgal3_parallel},
#endif
#ifdef DRANGE_BENCH_HAVE_QHULL
      {"qhull", drange::bench::run_qhull},
#endif
#ifdef DRANGE_BENCH_HAVE_BOOST_POLYGON
      {"fortune", drange::bench::run_boost_voronoi},
#endif
#ifdef DRANGE_BENCH_HAVE_TETGEN
      {"tetgen", drange::bench::run_tetgen},
#endif
  };
  return table;
}

const char* kKnownPeers = "drange cgal2 cgal3 cgal3-par cgal-dd cgal-dd-dyn qhull fortune tetgen";

int usage(const char* why) {
  std::cerr << "drange_bench_run: " << why << "\n"
            << "usage: drange_bench_run --peer NAME --input FILE [--threads N] [--variant V]\n"
            << "peers: " << kKnownPeers << "\nbuilt:";
  for (const auto& entry : peers()) std::cerr << ' ' << entry.first;
  std::cerr << '\n';
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  std::string peer;
  std::string input;
  RunOptions options;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (i + 1 >= argc) return usage(("missing value after " + arg).c_str());
    const std::string value = argv[++i];
    if (arg == "--peer") peer = value;
    else if (arg == "--input") input = value;
    else if (arg == "--threads") options.threads = std::atoi(value.c_str());
    else if (arg == "--variant") options.variant = value;
    else return usage(("unknown option " + arg).c_str());
  }
  if (peer.empty() || input.empty()) return usage("--peer and --input are required");
  if (options.threads < 1) return usage("--threads must be at least 1");

  const auto found = peers().find(peer);
  if (found == peers().end()) {
    if (std::strstr((std::string(" ") + kKnownPeers + " ").c_str(), (" " + peer + " ").c_str())) {
      std::cout << "RESULT peer=" << peer << " status=not-built" << std::endl;
      return 0;
    }
    return usage(("unknown peer " + peer).c_str());
  }

  drange::PointCloud points;
  try {
    points = drange::read_points(input);
  } catch (const std::exception& e) {
    std::cerr << "drange_bench_run: " << e.what() << '\n';
    return 2;
  }
  const std::size_t input_rss = peak_rss_bytes();
  std::cout << "RESULT peer=" << peer;
  try {
    const PeerResult r = found->second(points, options);
    if (!r.applicable) {
      std::cout << " status=n/a n=" << points.size() << " d=" << points.dim << std::endl;
      return 0;
    }
    char seconds[32];
    std::snprintf(seconds, sizeof seconds, "%.4f", r.seconds);
    std::cout << " status=ok n=" << points.size() << " d=" << points.dim << " simplices=" << r.simplices
              << " seconds=" << seconds << " peak_rss=" << peak_rss_bytes() << " input_rss=" << input_rss;
    if (!r.extra.empty()) std::cout << ' ' << r.extra;
    std::cout << std::endl;
    return 0;
  } catch (const std::bad_alloc&) {
    std::cout << " status=oom n=" << points.size() << " d=" << points.dim << " peak_rss=" << peak_rss_bytes() << std::endl;
    return 3;
  } catch (const std::exception& e) {
    std::cout << " status=error n=" << points.size() << " d=" << points.dim << std::endl;
    std::cerr << "drange_bench_run: " << peer << ": " << e.what() << '\n';
    return 1;
  }
}
