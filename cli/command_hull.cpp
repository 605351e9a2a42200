// cli/command_hull.cpp: `drange hull`, the exact convex hull of a point file, written in the
// `qconvex i` layout (the facets' vertex indices) so that scripts written for Qhull keep working.
#include <chrono>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "args.hpp"
#include "command_common.hpp"
#include "commands.hpp"
#include "drange/errors.hpp"
#include "drange/hull.hpp"
#include "drange/io.hpp"
#include "exit_codes.hpp"

namespace drange::cli {
namespace {

const std::vector<OptionSpec> kOptions = {
    {"output", 'o', true}, {"neighbors", 0, true}, {"coplanar", 0, true}, {"stats", 0, false}, {"quiet", 'q', false},
};

}  // namespace

std::string hull_help() {
  return "Usage: drange hull [INPUT] [OPTIONS]\n"
         "\n"
         "Computes the convex hull of the points in INPUT (a path, or - for standard input; without\n"
         "INPUT, points redirected into standard input) with exact arithmetic, and writes its\n"
         "facets in the `qconvex i` layout: the number of facets, then d zero-based point indices\n"
         "per line. Each facet is a simplex; its vertices are extreme points only: a facet with more\n"
         "corners (a square of a cube) is split between its corners.\n"
         "\n"
         "Options:\n"
         "  -o, --output FILE      write the facets to FILE (default: standard output)\n"
         "      --neighbors FILE   write, for each facet, the facet across the ridge opposite each\n"
         "                         vertex (the same layout)\n"
         "      --coplanar FILE    write the points on the hull that are not vertices, one line each:\n"
         "                         the point, a facet whose hyperplane holds it, its nearest vertex\n"
         "      --stats            print facets, vertices, coplanar points, area, volume and the time\n"
         "                         to standard error\n"
         "  -q, --quiet            print no messages\n"
         "  -h, --help             show this text\n"
         "\n" +
         exit_codes_help();
}

int run_hull(const std::vector<std::string>& args) {
  const Arguments arguments = parse_arguments(args, kOptions);
  expect_positionals(arguments, {"INPUT"}, 0);
  std::string input = arguments.positionals.empty() ? "" : arguments.positionals[0];
  if (input.empty()) {
    if (!standard_input_has_points()) throw UsageError("no INPUT given and nothing redirected into standard input");
    input = "-";
  }
  const std::string output = arguments.value_or("output", "-");
  expect_distinct_outputs(arguments, {"neighbors", "coplanar"}, output);
  const PointCloud points = read_points(input);
  const auto start = std::chrono::steady_clock::now();
  const ConvexHull hull = convex_hull(points);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  write_file_atomically(output, [&](std::ostream& out) { write_index_rows(out, hull.simplices, hull.dim); });
  if (arguments.has("neighbors"))
    write_file_atomically(arguments.value_or("neighbors", ""), [&](std::ostream& out) { write_index_rows(out, hull.neighbors, hull.dim); });
  if (arguments.has("coplanar"))
    write_file_atomically(arguments.value_or("coplanar", ""), [&](std::ostream& out) { write_index_rows(out, hull.coplanar, 3); });
  if (arguments.has("stats")) {
    const HullGeometry geometry = hull_geometry(points, hull);
    std::ostringstream line;
    line.precision(17);
    line << "points=" << points.size() << " facets=" << hull.size() << " vertices=" << hull.vertices.size()
         << " coplanar=" << hull.coplanar.size() / 3 << " area=" << geometry.area << " volume=" << geometry.volume
         << " time_hull=" << seconds;
    std::cerr << line.str() << '\n';
  }
  return kExitSuccess;
}

}  // namespace drange::cli
