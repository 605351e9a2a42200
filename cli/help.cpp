// cli/help.cpp: the overview printed by `drange --help`, and the exit codes every help text
// ends with. Each command's own help lives with the command.
#include <string>

#include "commands.hpp"

namespace drange::cli {

std::string exit_codes_help() {
  return "Exit codes:\n"
         "  0   success\n"
         "  1   the triangulation is not valid (drange check)\n"
         "  2   usage error: unknown option, missing or extra argument, bad value\n"
         "  3   input error: a file cannot be read or is malformed, or the output cannot be written\n"
         "  4   degenerate input: fewer than d+1 distinct points, or all points in one hyperplane\n"
         "  5   out of memory\n"
         "  70  internal error (a bug in drange: please report it)\n";
}

std::string general_help() {
  return std::string(
             "Usage: drange COMMAND [ARGUMENTS] [OPTIONS]\n"
             "\n"
             "Delaunay triangulations, Voronoi diagrams and convex hulls in any dimension (the\n"
             "D-Range direct algorithm, exact predicates).\n"
             "\n"
             "Commands:\n"
             "  delaunay [INPUT] [-o OUTPUT]    triangulate points (no INPUT: a demonstration)\n"
             "  voronoi [INPUT] [-o OUTPUT]     the Voronoi diagram, cells clipped to a box, volumes\n"
             "  check POINTS SIMPLICES          validate a triangulation exactly (ours or anyone's)\n"
             "  hull [INPUT] [-o OUTPUT]        the exact convex hull's facets (qconvex i layout)\n"
             "  generate DIST N D [-o FILE]     write random or grid test points\n"
             "  help [COMMAND]                  show this text, or a command's options\n"
             "\n"
             "Options:\n"
             "  -h, --help       show help (also after a command: drange delaunay --help)\n"
             "      --version    print the version\n"
             "\n"
             "Formats (text: blank lines and lines starting with '#' are ignored):\n"
             "  points     Qhull's input format: the dimension, the number of points, then one point\n"
             "             per line (what rbox and `drange generate` write); or one point per line,\n"
             "             coordinates separated by spaces or commas (CSV), with an optional header\n"
             "             row of column names; or a NumPy .npy array (n x d, float64 or float32).\n"
             "  simplices  `qdelaunay i` output: the number of simplices, then one line per simplex\n"
             "             of d+1 zero-based point indices.\n"
             "  results    delaunay and voronoi also write json (scipy's names), npz (numpy.load),\n"
             "             vtu (ParaView) and off, by --format or the output's extension, and SVG\n"
             "             pictures of 2D results with --svg.\n"
             "\n") +
         exit_codes_help() + "\nRun 'drange help COMMAND' for the options of a command.\n";
}

}  // namespace drange::cli
