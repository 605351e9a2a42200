// io/read_simplices.cpp: reading simplices (or any rows of vertex indices) in the
// `qdelaunay i` layout: the count, then one row of zero-based indices per line. Blank lines
// and '#' comments are skipped, as in every drange text reader (io/text_lines.hpp).
#include <algorithm>
#include <cstdint>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "drange/errors.hpp"
#include "drange/io.hpp"
#include "io/input_error.hpp"
#include "io/parse_number.hpp"
#include "io/read_text.hpp"
#include "io/text_lines.hpp"

namespace drange {
namespace {

using io::NumberStatus;

constexpr std::uint64_t kMaxIndex = INT32_MAX;

std::size_t parse_simplex_count(io::LineScanner& scanner, const std::string& name) {
  std::string_view line;
  std::size_t number = 0;
  if (!scanner.next(line, number)) {
    io::fail_in_file(name, "empty, expected the number of simplices on the first line");
  }
  std::vector<std::string_view> fields;
  io::split_fields(line, fields);
  std::uint64_t count = 0;
  const NumberStatus status = fields.size() == 1 ? io::parse_unsigned(fields[0], SIZE_MAX, count) : NumberStatus::NotANumber;
  if (status == NumberStatus::TooLarge) io::fail_at_line(name, number, "simplex count " + io::quoted(fields[0]) + " is too large");
  if (status != NumberStatus::Ok) io::fail_at_line(name, number, "expected the number of simplices, found " + io::quoted(io::trimmed(line)));
  return static_cast<std::size_t>(count);
}

std::string index_problem(std::size_t k, std::string_view field, NumberStatus status) {
  switch (status) {
    case NumberStatus::Negative: return "negative index: " + io::quoted(field);
    case NumberStatus::TooLarge:
      return "index " + io::quoted(field) + " is too large (at most " + std::to_string(kMaxIndex) + ")";
    default: break;
  }
  if (field.empty()) return "index " + std::to_string(k + 1) + " is empty";
  return "not an integer: " + io::quoted(field);
}

void parse_index_row(const std::string& name, std::size_t line_number, const std::vector<std::string_view>& fields,
                     int per_row, std::vector<std::int32_t>& rows) {
  if (fields.size() != static_cast<std::size_t>(per_row)) {
    io::fail_at_line(name, line_number,
                     "expected " + io::count_of(static_cast<std::size_t>(per_row), "index", "indices") + ", found " +
                         std::to_string(fields.size()));
  }
  for (std::size_t k = 0; k < fields.size(); ++k) {
    std::uint64_t value = 0;
    const NumberStatus status = io::parse_unsigned(fields[k], kMaxIndex, value);
    if (status != NumberStatus::Ok) io::fail_at_line(name, line_number, index_problem(k, fields[k], status));
    rows.push_back(static_cast<std::int32_t>(value));
  }
}

}  // namespace

std::vector<std::int32_t> read_simplices(const std::string& path, int vertices_per_simplex) {
  if (vertices_per_simplex < 1) {
    throw UsageError("read_simplices: vertices per simplex must be at least 1, got " +
                     std::to_string(vertices_per_simplex));
  }
  const std::string name = io::display_name(path);
  const std::string text = io::read_whole_file(path);
  io::LineScanner scanner(text);
  const std::size_t count = parse_simplex_count(scanner, name);

  std::vector<std::int32_t> rows;
  // Capped by the lines present, so that a wrong header cannot trigger a huge allocation.
  const std::size_t per_row = static_cast<std::size_t>(vertices_per_simplex);
  const std::size_t expected_rows = std::min(count, scanner.remaining_lines_bound());
  if (expected_rows <= SIZE_MAX / per_row) rows.reserve(expected_rows * per_row);

  std::vector<std::string_view> fields;
  std::string_view line;
  std::size_t line_number = 0;
  std::size_t found = 0;
  while (scanner.next(line, line_number)) {
    io::split_fields(line, fields);
    parse_index_row(name, line_number, fields, vertices_per_simplex, rows);
    ++found;
  }
  if (found != count) {
    io::fail_in_file(name, "header says " + io::count_of(count, "simplex", "simplices") + ", found " +
                               std::to_string(found));
  }
  return rows;
}

}  // namespace drange
