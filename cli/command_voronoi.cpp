// cli/command_voronoi.cpp: `drange voronoi`, the Voronoi diagram of a point file: by default
// in the `qvoronoi o` layout, so that scripts written for Qhull keep working; with the
// cells clipped to a box (2D/3D) for ParaView, and an SVG picture in 2D.
#include <iostream>
#include <string>
#include <vector>

#include "args.hpp"
#include "command_common.hpp"
#include "commands.hpp"
#include "drange/errors.hpp"
#include "drange/formats.hpp"
#include "drange/io.hpp"
#include "drange/svg.hpp"
#include "drange/voronoi.hpp"
#include "exit_codes.hpp"
#include "only_ids.hpp"
#include "progress.hpp"

namespace drange::cli {
namespace {

const std::vector<OptionSpec> kOptions = {
    {"output", 'o', true}, {"format", 0, true},    {"ridges", 0, true}, {"cells", 0, true},
    {"box", 0, true},      {"svg", 0, true},       {"circles", 0, false}, {"no-volumes", 0, false},
    {"stats", 0, false},   {"variant", 0, true},   {"threads", 0, true}, {"algorithm", 0, true}, {"quiet", 'q', false},
    {"only", 0, true},     {"cell-vertices", 0, false},
};

// --only: the cells of the given points, from their stars (drange::voronoi_cells).
int cells_of_file(const PointCloud& points, const std::vector<std::int64_t>& ids, const VoronoiOptions& options,
                  const Arguments& arguments) {
  const std::string output = arguments.value_or("output", "-");
  const OutputFormat format = arguments.has("format") ? output_format_from_name(arguments.value_or("format", ""))
                                                      : output_format_from_path(output, OutputFormat::Qhull);
  const Voronoi diagram = voronoi_cells(points, ids, options);
  write_voronoi(output, format, points, diagram, nullptr);
  if (arguments.has("ridges"))
    write_file_atomically(arguments.value_or("ridges", ""), [&](std::ostream& out) { write_qvoronoi_fv(out, diagram); });
  if (arguments.has("stats"))
    std::cerr << "voronoi_vertices=" << diagram.num_vertices() << " ridges=" << diagram.num_ridges()
              << " regions=" << diagram.regions.size() << '\n';
  return kExitSuccess;
}

bool needs_cells(OutputFormat format) { return format == OutputFormat::Vtu || format == OutputFormat::Off; }

// --cells FILE.txt: the clipped cells streamed a batch at a time from the points' Delaunay
// stars (drange::stream_clipped_cells), one line per cell, without the whole diagram.
void write_text_cells(const PointCloud& points, const Options& options, const Arguments& arguments,
                      bool report_duplicates) {
  const Box box = arguments.has("box") ? parse_box(arguments.value_or("box", ""), points.dim) : default_clip_box(points);
  const bool vertices = arguments.has("cell-vertices");
  CellStreamReport report;
  write_file_atomically(arguments.value_or("cells", ""), [&](std::ostream& out) {
    report = stream_clipped_cells(
        points, box, options, [&](const ClippedCells& cell, std::int32_t point, std::string& text) {
          append_cell_text(text, cell, 0, point, vertices);
        },
        [&](const std::string& text) { out.write(text.data(), static_cast<std::streamsize>(text.size())); });
  });
  if (report_duplicates && !report.duplicates.empty())
    std::cerr << "drange: " << duplicates_message(report.duplicates) << '\n';
  if (arguments.has("stats"))
    std::cerr << "cells=" << report.cells << " star_simplices=" << report.star_simplices << " batches=" << report.batches
              << " threads=" << report.threads << '\n';
}

int diagram_of_file(const std::string& input, const Arguments& arguments) {
  const std::string output = arguments.value_or("output", "-");
  expect_distinct_outputs(arguments, {"ridges", "cells", "svg"}, output);
  const OutputFormat format = arguments.has("format") ? output_format_from_name(arguments.value_or("format", ""))
                                                      : output_format_from_path(output, OutputFormat::Qhull);
  const std::string cells_path = arguments.value_or("cells", "");
  // A cell format by the extension; VTU on standard output. Qhull's layouts have no cells.
  // A .txt file is streamed (write_text_cells); without -o, --format, --ridges or --svg the
  // whole diagram is not computed at all.
  const bool text_cells = arguments.has("cells") && is_cells_text_path(cells_path);
  const OutputFormat cells_format =
      cells_path == "-" ? OutputFormat::Vtu : output_format_from_path(cells_path, OutputFormat::Qhull);
  if (arguments.has("cells") && !text_cells && cells_format == OutputFormat::Qhull)
    throw UsageError("--cells: Qhull's layouts hold no clipped cells; name a .vtu, .off, .json, .npz or .txt file");
  if (arguments.has("cell-vertices") && !text_cells)
    throw UsageError("--cell-vertices adds the corners to the lines of a text cells file: add --cells FILE.txt");
  const bool diagram_wanted =
      !text_cells || arguments.has("output") || arguments.has("format") || arguments.has("ridges") || arguments.has("svg");
  if (arguments.has("box") && !arguments.has("cells") && format == OutputFormat::Qhull)
    throw UsageError("--box clips the cells, which Qhull's layout does not hold: add --cells FILE, or choose "
                     "--format json, npz, vtu or off");
  // --only holds some cells, not the whole diagram: only the layouts that name each region's
  // point (json, npz) can hold it, and there is nothing to clip or draw.
  const bool only = arguments.has("only");
  if (only) {
    if (format != OutputFormat::Json && format != OutputFormat::Npz)
      throw UsageError("--only writes json or npz (the other layouts need every point's cell): choose --format json "
                       "or npz, or an output file ending in .json or .npz");
    for (const char* option : {"cells", "box", "svg"})
      if (arguments.has(option)) throw UsageError(std::string("--") + option + " cannot be used with --only");
  }
  const std::vector<std::int64_t> ids = only ? parse_only_ids(arguments.value_or("only", "")) : std::vector<std::int64_t>{};
  const bool quiet = arguments.has("quiet");
  VoronoiOptions options;
  options.delaunay.variant = variant_option(arguments);
  options.delaunay.algorithm = algorithm_option(arguments);
  options.delaunay.threads = threads_option(arguments);
  options.cell_volumes = !arguments.has("no-volumes");

  const PointCloud points = read_points(input);
  expect_svg_dimension(arguments, points.dim);
  if (only) return cells_of_file(points, ids, options, arguments);
  if (!diagram_wanted) {
    write_text_cells(points, options.delaunay, arguments, !quiet);
    return kExitSuccess;
  }
  options.delaunay.progress = make_progress_reporter(points.size(), points.dim, quiet);
  const Triangulation triangulation = delaunay(points, options.delaunay);
  if (!triangulation.duplicates.empty() && !quiet)
    std::cerr << "drange: " << duplicates_message(triangulation.duplicates) << '\n';
  const Voronoi diagram = voronoi(points, triangulation, options);

  // Clipped cells when asked for (--cells, --box, or an output format that draws them).
  const bool want_cells =
      (arguments.has("cells") && !text_cells) || (arguments.has("box") && format != OutputFormat::Qhull) || needs_cells(format);
  ClippedCells cells;
  if (want_cells) {
    const Box box = arguments.has("box") ? parse_box(arguments.value_or("box", ""), points.dim) : default_clip_box(points);
    cells = clip_cells(points, diagram, box);
  }
  const ClippedCells* clipped = want_cells ? &cells : nullptr;

  write_voronoi(output, format, points, diagram, clipped);
  if (arguments.has("ridges"))
    write_file_atomically(arguments.value_or("ridges", ""), [&](std::ostream& out) { write_qvoronoi_fv(out, diagram); });
  if (arguments.has("cells") && !text_cells) write_voronoi(cells_path, cells_format, points, diagram, clipped);
  if (arguments.has("svg")) {
    SvgOptions svg;
    svg.circumcircles = arguments.has("circles");
    write_file_atomically(arguments.value_or("svg", ""),
                          [&](std::ostream& out) { write_svg(out, points, triangulation, &diagram, svg); });
  }
  if (arguments.has("stats"))
    std::cerr << triangulation.stats.summary() << " voronoi_vertices=" << diagram.num_vertices()
              << " ridges=" << diagram.num_ridges() << '\n';
  if (text_cells) write_text_cells(points, options.delaunay, arguments, false);
  return kExitSuccess;
}

}  // namespace

std::string voronoi_help() {
  return std::string(
             "Usage: drange voronoi [INPUT] [OPTIONS]\n"
             "\n"
             "Computes the Voronoi diagram of the points in INPUT (a file, or - for standard input;\n"
             "without INPUT, points piped or redirected into standard input) from their Delaunay\n"
             "triangulation, and writes it.\n"
             "\n"
             "Options:\n"
             "  -o, --output FILE     where to write the diagram (default -, standard output)\n"
             "      --format NAME     the output format: ") +
         output_format_names() +
         "\n"
         "                        (default: from FILE's extension .json .npz .vtu .off,\n"
         "                        otherwise qhull, the `qvoronoi o` layout)\n"
         "      --ridges FILE     also write the ridges in the `qvoronoi Fv` layout\n"
         "      --cells FILE      also write the cells clipped to the box (2D/3D), as .vtu, .off,\n"
         "                        .json, .npz or .txt (by FILE's extension; - is VTU on standard\n"
         "                        output), with each cell's area/volume. A .txt file is made\n"
         "                        cell by cell from the points' Delaunay stars, without the\n"
         "                        whole diagram (which is not computed unless -o, --format,\n"
         "                        --ridges or --svg asks for it): one line per distinct point,\n"
         "                        \"ID VOLUME\", the point's input index and its cell's area or\n"
         "                        volume (0 when the cell misses the box), in the kd-tree's\n"
         "                        order of the points, the same for every --threads\n"
         "      --cell-vertices   with --cells FILE.txt: each line goes on with the cell's\n"
         "                        corner count K and its corners, \"x y\" (2D, counter-clockwise)\n"
         "                        or \"x y z\" (3D, the cell is their convex hull)\n"
         "      --box LIST        the clipping box: x0,y0[,z0],x1,y1[,z1] (default: the points'\n"
         "                        bounding box enlarged by 10% of its size on every side);\n"
         "                        for --cells, or the cells in json, npz, vtu and off output\n"
         "      --svg FILE        also draw the points, triangulation and diagram (2D) as SVG\n"
         "      --circles         draw the circumcircles too (with --svg)\n"
         "      --only IDS        only the cells of these points (zero-based input indices,\n"
         "                        3,17,42, or @FILE, a file of them), from their Delaunay stars\n"
         "                        without the rest of the triangulation; json or npz output\n"
         "                        only (the qhull layout needs every point's region), no\n"
         "                        --cells, --box or --svg; point_region is -1 for the other\n"
         "                        points, and the ridges are those of the given points\n"
         "      --no-volumes      skip the volumes of the bounded cells (costly for d >= 6)\n"
         "      --stats           print the run's statistics (key=value) to standard error\n"
         "      --variant NAME    an ablation variant of the Delaunay search, for measurements\n"
         "                        (see drange delaunay --help)\n"
         "      --algorithm NAME  the triangulation's construction: auto, direct or incremental\n"
         "                        (see drange delaunay --help)\n"
         "      --threads N       threads for the triangulation and the diagram (default 0: one\n"
         "                        per core); the output is the same for every N\n"
         "  -q, --quiet           no progress line, no report of duplicate points\n"
         "  -h, --help            show this text\n"
         "\n"
         "The diagram uses scipy.spatial.Voronoi's names and meaning: vertices (the circumcentres\n"
         "of the Delaunay simplices), ridge_points (pairs of points whose cells share a face of\n"
         "dimension d-1), ridge_vertices, regions and point_region, with -1 for the point at\n"
         "infinity, plus volumes (the volume of each bounded cell, any d). Simplices with the\n"
         "same circumsphere (cospherical points, as in every integer grid) share one vertex:\n"
         "that is decided exactly, never with a tolerance, so a grid cell is a square or cube.\n"
         "In 2D each region lists its vertices counter-clockwise; in 3D each ridge lists its\n"
         "polygon in cyclic order. Duplicate points share the region of their original.\n"
         "\n"
         "Output: qhull is the `qvoronoi o` layout (dimension; vertex count + 1, region count, 1;\n"
         "the point at infinity; the vertices; then for each input point its region: the count\n"
         "and the vertex numbers, 0 meaning infinity). json holds scipy's names; npz is NumPy's\n"
         "archive of the same arrays; vtu (ParaView) and off draw the clipped cells.\n"
         "\n"
         "Examples:\n"
         "  drange generate uniform 1000 2 -o points.txt\n"
         "  drange voronoi points.txt -o diagram.json --svg diagram.svg\n"
         "  drange voronoi points.txt --cells cells.vtu --box 0,0,1,1\n"
         "  drange voronoi points.txt --cells cells.txt --box 0,0,1,1 --threads 2\n"
         "  rbox 100 D3 | drange voronoi > diagram.txt\n"
         "\n" +
         exit_codes_help();
}

int run_voronoi(const std::vector<std::string>& args) {
  const Arguments arguments = parse_arguments(args, kOptions);
  expect_positionals(arguments, {"INPUT"}, 0);
  if (!arguments.positionals.empty()) return diagram_of_file(arguments.positionals[0], arguments);
  if (standard_input_has_points()) return diagram_of_file("-", arguments);
  throw UsageError("missing argument INPUT (a point file, or points on standard input)");
}

}  // namespace drange::cli
