// cli/command_common.hpp: what `delaunay` and `voronoi` share: where the points come from,
// the duplicates report, and the --box argument.
#pragma once

#include <string>
#include <vector>

#include "args.hpp"
#include "drange/delaunay.hpp"
#include "drange/voronoi.hpp"

namespace drange::cli {

// True when INPUT was left out but points are piped or redirected into standard input (as
// `qdelaunay < points.txt` reads them); false for a terminal or an empty stream.
bool standard_input_has_points();

// "3 duplicate points left out (point 17 = point 4, point 20 = point 4, point 21 = point 9)".
std::string duplicates_message(const std::vector<Duplicate>& duplicates);

// Parses --box "x0,y0[,z0],x1,y1[,z1]": the lower corner, then the upper, 2*dim numbers.
// Throws UsageError naming the value and what is wrong with it.
Box parse_box(const std::string& text, int dim);

// With --svg, throws write_svg's UsageError for points that are not 2D, before any work is
// done or any file written: a run that cannot draw its picture writes nothing.
void expect_svg_dimension(const Arguments& arguments, int dim);

// The --threads value (Options::threads): 0 (every hardware thread, the default) or a count up
// to 1024. Throws UsageError "--threads must be an integer from 0 to 1024, got 'text'".
int threads_option(const Arguments& arguments);

// The --variant value (Options::variant, default "full"), checked against variant_names()
// before any input is read. Throws UsageError naming the value and the accepted names.
std::string variant_option(const Arguments& arguments);
// --algorithm NAME (default auto), checked against algorithm_names().
std::string algorithm_option(const Arguments& arguments);

// Throws UsageError when two output options name the same file (other than none).
void expect_distinct_outputs(const Arguments& arguments, const std::vector<const char*>& options,
                             const std::string& main_output);

}  // namespace drange::cli
