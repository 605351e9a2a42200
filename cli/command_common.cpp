// cli/command_common.cpp: see command_common.hpp.
#include "command_common.hpp"

#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <sstream>

#include "drange/errors.hpp"

namespace drange::cli {
namespace {

// How many duplicates the report lists by index before it abbreviates.
constexpr std::size_t kDuplicatesListed = 10;

std::string word_of(double value) {
  std::ostringstream text;
  text << value;
  return text.str();
}

// --OPTION NAME, NAME one of `names` (comma-separated), or `fallback` when absent.
std::string named_option(const Arguments& arguments, const char* option, const char* fallback, const char* names) {
  const std::string name = arguments.value_or(option, fallback);
  if ((std::string(", ") + names + ", ").find(", " + name + ", ") == std::string::npos)
    throw UsageError(std::string("--") + option + ": unknown " + option + " '" + name + "' (expected one of: " + names + ")");
  return name;
}

}  // namespace

int threads_option(const Arguments& arguments) {
  if (!arguments.has("threads")) return 0;
  return static_cast<int>(parse_integer_argument("--threads", arguments.value_or("threads", ""), 0, 1024));
}

std::string variant_option(const Arguments& arguments) {
  return named_option(arguments, "variant", "full", variant_names());
}

std::string algorithm_option(const Arguments& arguments) {
  return named_option(arguments, "algorithm", "auto", algorithm_names());
}

bool standard_input_has_points() {
  return !isatty(STDIN_FILENO) && std::cin.peek() != std::char_traits<char>::eof();
}

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

Box parse_box(const std::string& text, int dim) {
  std::vector<double> values;
  std::size_t start = 0;
  for (;;) {
    const std::size_t comma = text.find(',', start);
    const std::string word = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    char* end = nullptr;
    errno = 0;
    const double value = std::strtod(word.c_str(), &end);
    if (word.empty() || end != word.c_str() + word.size() || errno == ERANGE || !std::isfinite(value))
      throw UsageError("--box: '" + word + "' is not a finite number (in '" + text + "')");
    values.push_back(value);
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  const auto d = static_cast<std::size_t>(dim);
  if (values.size() != 2 * d)
    throw UsageError("--box needs " + std::to_string(2 * d) + " numbers for dimension " + std::to_string(dim) +
                     " (lower corner, then upper corner), got " + std::to_string(values.size()));
  Box box{{values.begin(), values.begin() + dim}, {values.begin() + dim, values.end()}};
  for (std::size_t k = 0; k < d; ++k)
    if (!(box.lower[k] < box.upper[k]))
      throw UsageError("--box: the lower corner must be below the upper one on every axis (axis " + std::to_string(k) +
                       ": " + word_of(box.lower[k]) + " >= " + word_of(box.upper[k]) + ")");
  return box;
}

void expect_svg_dimension(const Arguments& arguments, int dim) {
  if (arguments.has("svg") && dim != 2)
    throw UsageError("SVG pictures are 2D only, the points have dimension " + std::to_string(dim));
}

void expect_distinct_outputs(const Arguments& arguments, const std::vector<const char*>& options,
                             const std::string& main_output) {
  std::vector<std::pair<std::string, std::string>> seen{{"--output", main_output}};
  for (const char* option : options) {
    if (!arguments.has(option)) continue;
    const std::string path = arguments.value_or(option, "");
    for (const auto& [name, other] : seen)
      if (path == other)
        throw UsageError(path == "-" ? name + " and --" + option + " cannot both go to standard output"
                                     : name + " and --" + option + " name the same file '" + path + "'");
    seen.emplace_back(std::string("--") + option, path);
  }
}

}  // namespace drange::cli
