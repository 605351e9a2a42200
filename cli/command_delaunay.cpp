// cli/command_delaunay.cpp: `drange delaunay`, the triangulation of a point file, written in
// the `qdelaunay i` layout so that scripts written for Qhull keep working.
#include <iostream>
#include <string>
#include <vector>

#include "args.hpp"
#include "command_common.hpp"
#include "commands.hpp"
#include "drange/delaunay.hpp"
#include "drange/errors.hpp"
#include "drange/formats.hpp"
#include "drange/incremental.hpp"
#include "drange/io.hpp"
#include "drange/svg.hpp"
#include "exit_codes.hpp"
#include "only_ids.hpp"
#include "processes.hpp"
#include "progress.hpp"

namespace drange::cli {
namespace {

const std::vector<OptionSpec> kOptions = {
    {"output", 'o', true}, {"format", 0, true},  {"neighbors", 0, true}, {"svg", 0, true},
    {"circles", 0, false}, {"stats", 0, false}, {"variant", 0, true},   {"threads", 0, true},
    {"quiet", 'q', false}, {"algorithm", 0, true}, {"only", 0, true}, {"furthest-site", 0, false},
};

int triangulate_file(const std::string& input, const Arguments& arguments) {
  const std::string output = arguments.value_or("output", "-");
  expect_distinct_outputs(arguments, {"neighbors", "svg"}, output);
  const OutputFormat format = arguments.has("format") ? output_format_from_name(arguments.value_or("format", ""))
                                                      : output_format_from_path(output, OutputFormat::Qhull);
  const bool quiet = arguments.has("quiet");
  Options options;
  options.variant = variant_option(arguments);
  options.algorithm = algorithm_option(arguments);
  options.threads = threads_option(arguments);
  options.compute_neighbors = arguments.has("neighbors") || format != OutputFormat::Qhull;
  const bool only = arguments.has("only");
  const std::vector<std::int64_t> ids = only ? parse_only_ids(arguments.value_or("only", "")) : std::vector<std::int64_t>{};
  const bool furthest = arguments.has("furthest-site");
  if (furthest && (only || arguments.has("variant") || arguments.has("algorithm")))
    throw UsageError("--furthest-site is built by insertion alone: it takes no --only, --variant or --algorithm");

  if (processes().count() > 1) return triangulate_across_processes(input, arguments, output, format, options);
  const PointCloud points = read_points(input);
  expect_svg_dimension(arguments, points.dim);
  options.progress = make_progress_reporter(points.size(), points.dim, quiet);
  const Triangulation triangulation = furthest ? IncrementalDelaunay(points, true).triangulation(options.compute_neighbors)
                                      : only   ? delaunay_stars(points, ids, options)
                                               : delaunay(points, options);

  write_delaunay_outputs(output, format, points, triangulation, arguments);
  if (arguments.has("stats")) std::cerr << triangulation.stats.summary() << '\n';
  return kExitSuccess;
}

}  // namespace

void write_delaunay_outputs(const std::string& output, OutputFormat format, const PointCloud& points,
                            const Triangulation& triangulation, const Arguments& arguments) {
  if (!triangulation.duplicates.empty() && !arguments.has("quiet"))
    std::cerr << "drange: " << duplicates_message(triangulation.duplicates) << '\n';
  write_delaunay(output, format, points, triangulation);
  if (arguments.has("neighbors")) {
    write_file_atomically(arguments.value_or("neighbors", ""), [&](std::ostream& out) {
      write_index_rows(out, triangulation.neighbors, triangulation.dim + 1);
    });
  }
  if (arguments.has("svg")) {
    SvgOptions svg;
    svg.circumcircles = arguments.has("circles");
    svg.voronoi = false;
    write_file_atomically(arguments.value_or("svg", ""),
                          [&](std::ostream& out) { write_svg(out, points, triangulation, nullptr, svg); });
  }
}

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
             "      --format NAME     the output format: ") + output_format_names() + std::string(
             "\n"
             "                        (default: from FILE's extension .json .npz .vtu .off,\n"
             "                        otherwise qhull, the `qdelaunay i` layout)\n"
             "      --neighbors FILE  also write each simplex's neighbours: the simplex opposite\n"
             "                        vertex k of simplex s is in row s, column k; -1 on the hull\n"
             "      --only IDS        only the stars of these points: every simplex incident to\n"
             "                        one of them (the same as in the whole triangulation), found\n"
             "                        without the rest; IDS is a comma-separated list of zero-based\n"
             "                        input indices (3,17,42) or @FILE, a file of them; --neighbors\n"
             "                        then links the simplices written, -1 for any other; a\n"
             "                        duplicate's index gives the star of the point it copies\n"
             "      --furthest-site   the furthest-site triangulation instead (Qhull's Qu): the\n"
             "                        simplices whose circumspheres hold every point, of the\n"
             "                        extreme points alone; by insertion, one thread\n"
             "      --svg FILE        also draw the triangulation (2D) as an SVG picture\n"
             "      --circles         draw the circumcircles too (with --svg)\n"
             "      --stats           print the run's statistics (key=value) to standard error\n"
             "      --variant NAME    an ablation variant of the search, to measure what each of\n"
             "                        its steps gains: one of\n"
             "                        ") +
         variant_names() +
         "\n"
         "                        (default full). Every variant gives the same simplices;\n"
         "                        fifo and spatial fix the order in which open facets are\n"
         "                        searched (the paper's FIFO, or the spatial order that full\n"
         "                        uses in 3D to 5D), and scan, kdtree and paper use FIFO:\n"
         "                        these number and list the simplices in another order\n"
         "      --algorithm NAME  the construction: direct (the D-Range search of each open\n"
         "                        facet), incremental (randomized insertion, whose speed does\n"
         "                        not depend on the points' shape; one thread) or auto (the\n"
         "                        default: incremental in 2D and 3D when the direct search,\n"
         "                        probed on a sample, is slow, as on surfaces; else direct).\n"
         "                        The same simplices, listed in another order; --stats names\n"
         "                        the one that ran\n"
         "      --threads N       threads to use (default 0: one per core); the output is the\n"
         "                        same for every N\n"
         "  -q, --quiet           no progress line, no report of duplicate points\n"
         "  -h, --help            show this text\n"
         "\n"
         "Input: Qhull's format (dimension, count, then one point per line: what rbox and\n"
         "`drange generate` write), or one point per line with coordinates separated by spaces\n"
         "or commas and an optional header row (CSV). Blank lines and '#' comments are ignored.\n"
         "The dimension must be at least 2. Exact duplicates are left out and reported.\n"
         "\n"
         "Output: by default the `qdelaunay i` layout: the number of simplices, then one line of\n"
         "d+1 zero-based point indices per simplex, each simplex positively oriented. json\n"
         "holds scipy's names (simplices, neighbors, coplanar); npz is NumPy's archive of the\n"
         "same arrays (numpy.load); vtu is for ParaView (2D/3D); off is the triangles (2D) or\n"
         "the hull surface (3D). Files are replaced only when complete: a failed run leaves an\n"
         "existing file untouched. Long runs draw a progress line on standard error when it is\n"
         "a terminal.\n"
         "\n"
         "Across processes: mpirun -np P drange delaunay POINTS -o OUT splits the work among P\n"
         "processes (when drange is built with MPI): each reads its share of the file and\n"
         "triangulates a block of space, and the same simplices are written once, in the\n"
         "qhull, json or npz format; see docs/scaling.md. --only, --furthest-site, --svg,\n"
         "--variant and --algorithm run as one process only.\n"
         "\n"
         "Examples:\n"
         "  drange generate uniform 100000 3 -o points.txt\n"
         "  drange delaunay points.txt -o simplices.txt --neighbors neighbors.txt\n"
         "  rbox 1000 D4 | drange delaunay - > simplices.txt\n"
         "  drange delaunay points2d.txt -o mesh.vtu --svg mesh.svg\n"
         "\n" +
         exit_codes_help();
}

int run_delaunay(const std::vector<std::string>& args) {
  const Arguments arguments = parse_arguments(args, kOptions);
  expect_positionals(arguments, {"INPUT"}, 0);
  // Without INPUT, points piped or redirected into standard input are read, as qdelaunay does
  // (`drange delaunay < points.txt`); a terminal or an empty stream gets the demonstration.
  if (processes().count() > 1 && arguments.positionals.empty())
    throw UsageError("across processes (mpirun) drange delaunay needs an INPUT file");
  if (arguments.positionals.empty() && standard_input_has_points()) return triangulate_file("-", arguments);
  if (arguments.positionals.empty()) {
    // The demonstration writes no files: an output option without INPUT is a mistake.
    for (const char* option : {"output", "neighbors", "format", "svg", "circles", "only"}) {
      if (arguments.has(option)) {
        throw UsageError(std::string("--") + option + " needs an INPUT file (without INPUT, a demonstration runs)");
      }
    }
    return run_delaunay_demo(variant_option(arguments), threads_option(arguments), arguments.has("stats"));
  }
  return triangulate_file(arguments.positionals[0], arguments);
}

}  // namespace drange::cli
