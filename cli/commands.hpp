// cli/commands.hpp: the commands of `drange`. Each takes the words after its name, writes
// its results, and returns the exit status; failures are thrown as drange's typed
// exceptions and turned into messages and exit codes by main.cpp.
#pragma once

#include <string>
#include <vector>

#include "args.hpp"
#include "drange/delaunay.hpp"
#include "drange/formats.hpp"

namespace drange::cli {

inline constexpr const char* kVersion = "0.1.0";

int run_delaunay(const std::vector<std::string>& args);
int run_voronoi(const std::vector<std::string>& args);
int run_check(const std::vector<std::string>& args);
int run_hull(const std::vector<std::string>& args);
int run_generate(const std::vector<std::string>& args);

// The help texts, printed by `drange COMMAND --help` and `drange help COMMAND`.
std::string delaunay_help();
std::string voronoi_help();
std::string check_help();
std::string hull_help();
std::string generate_help();
std::string general_help();

// The exit codes paragraph shared by every help text.
std::string exit_codes_help();

// `drange delaunay INPUT` under mpirun with more than one process (command_delaunay_split.cpp).
int triangulate_across_processes(const std::string& input, const Arguments& arguments, const std::string& output,
                                 OutputFormat format, const Options& options);

// What `drange delaunay` writes of a triangulation: the duplicates' report (unless --quiet),
// OUTPUT in `format`, and the --neighbors and --svg files.
void write_delaunay_outputs(const std::string& output, OutputFormat format, const PointCloud& points,
                            const Triangulation& triangulation, const Arguments& arguments);

// Runs the built-in demonstration of `drange delaunay` without INPUT.
int run_delaunay_demo(const std::string& variant, int threads, bool print_stats);

}  // namespace drange::cli
