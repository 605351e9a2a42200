// cli/command_check.cpp: `drange check`, the exact validation of a triangulation file
// against its points: our output, Qhull's, or anyone's in the `qdelaunay i` layout.
#include <iostream>
#include <string>
#include <vector>

#include "args.hpp"
#include "commands.hpp"
#include "drange/check.hpp"
#include "drange/errors.hpp"
#include "drange/io.hpp"
#include "exit_codes.hpp"

namespace drange::cli {
namespace {

const std::vector<OptionSpec> kOptions = {{"quiet", 'q', false}};

std::string plural(std::size_t n, const char* singular, const char* plural_form) {
  return std::to_string(n) + " " + (n == 1 ? singular : plural_form);
}

void print_report(const CheckReport& report) {
  if (report.valid) {
    std::cout << "valid: " << plural(report.simplices, "simplex", "simplices") << ", "
              << plural(report.interior_facets, "interior facet", "interior facets") << ", "
              << plural(report.boundary_facets, "boundary facet", "boundary facets") << '\n';
    return;
  }
  for (const std::string& problem : report.problems) std::cout << problem << '\n';
  if (report.problem_count > report.problems.size()) {
    std::cout << "... and " << plural(report.problem_count - report.problems.size(), "more problem", "more problems")
              << '\n';
  }
  std::cout << "invalid: " << plural(report.problem_count, "problem", "problems") << '\n';
}

}  // namespace

std::string check_help() {
  return "Usage: drange check POINTS SIMPLICES [OPTIONS]\n"
         "\n"
         "Checks with exact arithmetic that SIMPLICES is a Delaunay triangulation of POINTS:\n"
         "valid indices, simplices of nonzero volume that cover the convex hull exactly once,\n"
         "every distinct point used, and no point strictly inside any simplex's circumsphere.\n"
         "Prints \"valid: ...\" with the counts of simplices and facets, or one line per problem\n"
         "and \"invalid: K problems\". Either file may be - (standard input), not both.\n"
         "\n"
         "Options:\n"
         "  -q, --quiet    print nothing; the exit code alone tells the result\n"
         "  -h, --help     show this text\n"
         "\n"
         "Formats: POINTS as for drange delaunay (Qhull's format, or rows / CSV); SIMPLICES in the\n"
         "`qdelaunay i` layout: the number of simplices, then d+1 zero-based indices per line, in\n"
         "any orientation. The output of `qdelaunay i Qt` can be checked directly.\n"
         "\n" +
         exit_codes_help();
}

int run_check(const std::vector<std::string>& args) {
  const Arguments arguments = parse_arguments(args, kOptions);
  expect_positionals(arguments, {"POINTS", "SIMPLICES"}, 2);
  const std::string& points_path = arguments.positionals[0];
  const std::string& simplices_path = arguments.positionals[1];
  if (points_path == "-" && simplices_path == "-") throw UsageError("POINTS and SIMPLICES cannot both be standard input");

  const PointCloud points = read_points(points_path);
  const std::vector<std::int32_t> simplices = read_simplices(simplices_path, points.dim + 1);
  const CheckReport report = check_triangulation(points, simplices);
  if (!arguments.has("quiet")) print_report(report);
  return report.valid ? kExitSuccess : kExitInvalid;
}

}  // namespace drange::cli
