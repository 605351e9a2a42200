// cli/delaunay_demo.cpp: `drange delaunay` without INPUT: triangulates a fixed random set
// and prints what a user wants to know first (size, speed, memory), then how to run it on
// their own points.
#include <cstdint>
#include <cstdio>
#include <iostream>
#include <string>

#include "commands.hpp"
#include "drange/delaunay.hpp"
#include "drange/generate.hpp"
#include "exit_codes.hpp"

namespace drange::cli {
namespace {

constexpr std::size_t kDemoPoints = 100000;
constexpr int kDemoDimension = 3;
constexpr std::uint64_t kDemoSeed = 1;

std::string format(const char* pattern, double value) {
  char text[64];
  std::snprintf(text, sizeof text, pattern, value);
  return text;
}

void print_row(const char* label, const std::string& value) {
  std::printf("  %-14s %s\n", label, value.c_str());
}

void print_summary(const Statistics& stats) {
  const double simplices = static_cast<double>(stats.simplices);
  print_row("points", std::to_string(stats.points) + " (" + std::to_string(stats.distinct_points) + " distinct)");
  print_row("simplices", std::to_string(stats.simplices));
  print_row("hull facets", std::to_string(stats.hull_facets));
  print_row("threads", std::to_string(stats.threads));
  print_row("algorithm", stats.algorithm + format("  (chosen in %.3f s; --algorithm)", stats.seconds_choice));
  print_row("kd-tree", format("%.3f s", stats.seconds_kdtree));
  print_row("first facet", format("%.3f s", stats.seconds_first_facet));
  print_row("search", format("%.3f s", stats.seconds_search) + "  (with the neighbours)");
  print_row("total", format("%.3f s", stats.seconds_total) +
                         (stats.seconds_total > 0 ? format("  (%.0f simplices per second)", simplices / stats.seconds_total)
                                                  : std::string()));
  print_row("search calls", format("%.1f per simplex", stats.calls_per_simplex()));
  print_row("peak memory", format("%.1f MiB", static_cast<double>(stats.peak_rss_bytes) / (1024.0 * 1024.0)) +
                               (simplices > 0 ? format("  (%.0f bytes per simplex)",
                                                       static_cast<double>(stats.peak_rss_bytes) / simplices)
                                              : std::string()));
}

}  // namespace

int run_delaunay_demo(const std::string& variant, int threads, bool print_stats) {
  Options options;
  options.variant = variant;
  options.threads = threads;
  options.compute_neighbors = true;
  std::printf("No INPUT given: triangulating %zu uniform random points in the unit cube, %dD, seed %llu.\n\n",
              kDemoPoints, kDemoDimension, static_cast<unsigned long long>(kDemoSeed));
  std::fflush(stdout);  // shown while the triangulation runs

  const PointCloud points = generate_points(Distribution::Uniform, kDemoPoints, kDemoDimension, kDemoSeed);
  const Triangulation triangulation = delaunay(points, options);
  print_summary(triangulation.stats);
  std::printf(
      "\nTo triangulate your own points:  drange delaunay POINTS -o SIMPLICES\n"
      "Their Voronoi diagram:           drange voronoi POINTS -o DIAGRAM.json [--svg PICTURE.svg]\n"
      "(drange generate uniform 1000 3 -o points.txt writes a test file; drange delaunay --help\n"
      "and drange voronoi --help list the formats and options.)\n");
  std::fflush(stdout);
  if (print_stats) std::cerr << triangulation.stats.summary() << '\n';
  return kExitSuccess;
}

}  // namespace drange::cli
