// cli/command_delaunay.cpp: `drange delaunay`, the triangulation of a point file, written in
// the `qdelaunay i` layout so that scripts written for Qhull keep working.
#include <unistd.h>

#include <iostream>
#include <string>
#include <vector>

#include "args.hpp"
#include "commands.hpp"
#include "drange/delaunay.hpp"
#include "drange/errors.hpp"
#include "drange/io.hpp"
#include "exit_codes.hpp"

namespace drange::cli {
namespace {

const std::vector<OptionSpec> kOptions = {
    {"output", 'o', true}, {"neighbors", 0, true}, {"stats", 0, false},
    {"variant", 0, true},  {"quiet", 'q', false},
};

// How many duplicates the report lists by index before it abbreviates.
constexpr std::size_t kDuplicatesListed = 10;

// "3 duplicate points left out (point 17 = point 4, point 20 = point 4, point 21 = point 9)".
std::string duplicates_message(const std::vector<Duplicate>& duplicates) {
  std::string message = std::to_string(duplicates.size()) +
                        (duplicates.size() == 1 ? " duplicate point left out (" : " duplicate points left out (");
  for (std::size_t i = 0; i < duplicates.size() && i < kDuplicatesListed; ++i) {
    if (i > 0) message += ", ";
    message += "point " + std::to_string(duplicates[i].index) + " = point " + std::to_string(duplicates[i].original);
  }
  if (duplicates.size() > kDuplicatesListed) message += ", ...";
  return message + ")";
}

void check_outputs(const std::string& output, const Arguments& arguments) {
  if (!arguments.has("neighbors")) return;
  const std::string neighbors = arguments.value_or("neighbors", "");
  if (neighbors == output) {
    throw UsageError(output == "-" ? "the simplices and --neighbors cannot both go to standard output"
                                   : "--output and --neighbors name the same file '" + output + "'");
  }
}

int triangulate_file(const std::string& input, const Arguments& arguments) {
  const std::string output = arguments.value_or("output", "-");
  check_outputs(output, arguments);
  Options options;
  options.search = search_variant(arguments.value_or("variant", "full"));
  options.compute_neighbors = arguments.has("neighbors");

  const PointCloud points = read_points(input);
  const Triangulation triangulation = delaunay(points, options);
  const int per_row = triangulation.dim + 1;

  if (!triangulation.duplicates.empty() && !arguments.has("quiet")) {
    std::cerr << "drange: " << duplicates_message(triangulation.duplicates) << '\n';
  }
  write_file_atomically(output, [&](std::ostream& out) { write_index_rows(out, triangulation.simplices, per_row); });
  if (options.compute_neighbors) {
    write_file_atomically(arguments.value_or("neighbors", ""),
                          [&](std::ostream& out) { write_index_rows(out, triangulation.neighbors, per_row); });
  }
  if (arguments.has("stats")) std::cerr << triangulation.stats.summary() << '\n';
  return kExitSuccess;
}

}  // namespace

std::string delaunay_help() {
  return std::string(
             "Usage: drange delaunay [INPUT] [OPTIONS]\n"
             "\n"
             "Computes the Delaunay triangulation of the points in INPUT (a file, or - for standard\n"
             "input) and writes its simplices. Without INPUT, reads standard input when points are\n"
             "piped or redirected into it (drange delaunay < points.txt, as with qdelaunay);\n"
             "otherwise triangulates a demonstration set (100000 uniform random points in 3D) and\n"
             "prints a summary of the run.\n"
             "\n"
             "Options:\n"
             "  -o, --output FILE     where to write the simplices (default -, standard output)\n"
             "      --neighbors FILE  also write each simplex's neighbours: the simplex opposite\n"
             "                        vertex k of simplex s is in row s, column k; -1 on the hull\n"
             "      --stats           print the run's statistics (key=value) to standard error\n"
             "      --variant NAME    the search variant, to measure each optimisation: one of\n"
             "                        ") +
         search_variant_names() +
         " (default full)\n"
         "  -q, --quiet           do not report duplicate points\n"
         "  -h, --help            show this text\n"
         "\n"
         "Input: Qhull's format (dimension, count, then one point per line: what rbox and\n"
         "`drange generate` write), or one point per line with coordinates separated by spaces\n"
         "or commas and an optional header row (CSV). Blank lines and '#' comments are ignored.\n"
         "The dimension must be at least 2. Exact duplicates are left out and reported.\n"
         "\n"
         "Output: the `qdelaunay i` layout: the number of simplices, then one line of d+1\n"
         "zero-based point indices per simplex, each simplex positively oriented. Files are\n"
         "replaced only when complete: a failed run leaves an existing file untouched.\n"
         "\n"
         "Examples:\n"
         "  drange generate uniform 100000 3 -o points.txt\n"
         "  drange delaunay points.txt -o simplices.txt --neighbors neighbors.txt\n"
         "  rbox 1000 D4 | drange delaunay - > simplices.txt\n"
         "\n" +
         exit_codes_help();
}

int run_delaunay(const std::vector<std::string>& args) {
  const Arguments arguments = parse_arguments(args, kOptions);
  expect_positionals(arguments, {"INPUT"}, 0);
  // Without INPUT, points piped or redirected into standard input are read, as qdelaunay does
  // (`drange delaunay < points.txt`); a terminal or an empty stream gets the demonstration.
  if (arguments.positionals.empty() && !isatty(STDIN_FILENO) && std::cin.peek() != std::char_traits<char>::eof())
    return triangulate_file("-", arguments);
  if (arguments.positionals.empty()) {
    // The demonstration writes no files: an output option without INPUT is a mistake.
    for (const char* option : {"output", "neighbors"}) {
      if (arguments.has(option)) {
        throw UsageError(std::string("--") + option + " needs an INPUT file (without INPUT, a demonstration runs)");
      }
    }
    return run_delaunay_demo(arguments.value_or("variant", "full"), arguments.has("stats"));
  }
  return triangulate_file(arguments.positionals[0], arguments);
}

}  // namespace drange::cli
