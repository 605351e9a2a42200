// io/read_points.cpp: reading a point cloud from Qhull's input format or from plain rows
// (whitespace or comma separated, CSV with a header row), or from a NumPy .npy file, which
// is recognised by its magic bytes (io/read_npy.cpp). See drange/io.hpp for the formats
// and io/text_lines.hpp for what counts as a line and a field.
//
// Layout detection: the input is in Qhull's format when its first content line holds an
// unsigned integer, the dimension (possibly followed by a comment, as rbox writes it), and the
// second a single unsigned integer, the count. Everything else is rows.
// A one-dimensional rows file whose first two values are plain integers is therefore read as
// Qhull's format; the message for its first data row says so. Conversely a lone integer on
// line 1 followed by wider rows was most likely meant as a header; that message says so too.
#include <algorithm>
#include <charconv>
#include <climits>
#include <cmath>
#include <cstdint>
#include <istream>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include "drange/io.hpp"
#include "io/input_error.hpp"
#include "io/npy.hpp"
#include "io/parse_number.hpp"
#include "io/read_text.hpp"
#include "io/text_points.hpp"
#include "io/text_lines.hpp"
#include "util/huge_pages.hpp"

namespace drange {
namespace {

using io::NumberStatus;

struct ContentLine {
  std::string_view text;
  std::size_t number = 0;
};

// What the first content lines say about the layout.
struct Layout {
  bool qhull = false;
  int dim = 0;                  // Qhull only: from the header
  std::size_t count = 0;        // Qhull only: from the header
  std::size_t header_line = 0;  // Qhull only: line number of the count
};

// The field is a run of digits (possibly too long for any integer type).
bool is_digits_only(std::string_view field) {
  std::uint64_t ignored = 0;
  const NumberStatus status = io::parse_unsigned(field, UINT64_MAX, ignored);
  return status == NumberStatus::Ok || status == NumberStatus::TooLarge;
}

// Qhull's first line: the dimension, optionally followed by a comment, which is how rbox
// writes it ("3 rbox 1000 D3"). A second number would make it a data row instead.
bool is_dimension_line(std::string_view line, std::vector<std::string_view>& fields) {
  io::split_fields(line, fields);
  if (fields.empty() || !is_digits_only(fields[0])) return false;
  double ignored = 0;
  return fields.size() == 1 || io::parse_double(fields[1], ignored) == NumberStatus::NotANumber;
}

bool is_count_line(std::string_view line, std::vector<std::string_view>& fields) {
  io::split_fields(line, fields);
  return fields.size() == 1 && is_digits_only(fields[0]);
}

int parse_dimension(const std::string& name, std::size_t line_number, std::string_view field) {
  std::uint64_t value = 0;
  if (io::parse_unsigned(field, INT_MAX, value) != NumberStatus::Ok) {
    io::fail_at_line(name, line_number, "dimension " + io::quoted(field) + " is too large");
  }
  if (value < 1) io::fail_at_line(name, line_number, "dimension must be at least 1, found 0");
  return static_cast<int>(value);
}

std::size_t parse_count(const std::string& name, std::size_t line_number, std::string_view field) {
  std::uint64_t value = 0;
  if (io::parse_unsigned(field, SIZE_MAX, value) != NumberStatus::Ok) {
    io::fail_at_line(name, line_number, "point count " + io::quoted(field) + " is too large");
  }
  return static_cast<std::size_t>(value);
}

// Looks at the first two content lines; consumes them from `scanner` only for Qhull's format.
Layout detect_layout(io::LineScanner& scanner, const std::string& name) {
  Layout layout;
  io::LineScanner lookahead = scanner;
  std::vector<std::string_view> fields;
  ContentLine first, second;
  if (!lookahead.next(first.text, first.number) || !is_dimension_line(first.text, fields)) return layout;
  const std::string_view dimension = fields[0];
  if (!lookahead.next(second.text, second.number) || !is_count_line(second.text, fields)) return layout;
  layout.qhull = true;
  layout.dim = parse_dimension(name, first.number, dimension);
  layout.count = parse_count(name, second.number, fields[0]);
  layout.header_line = second.number;
  scanner = lookahead;
  return layout;
}

// A header row of column names: no field reads as a number (NaN and "inf" do read as numbers,
// and are then reported as such).
bool is_header_row(const std::vector<std::string_view>& fields) {
  bool any_name = false;
  for (std::string_view field : fields) {
    if (field.empty()) continue;
    double ignored = 0;
    if (io::parse_double(field, ignored) != NumberStatus::NotANumber) return false;
    any_name = true;
  }
  return any_name;
}

std::string coordinate_problem(std::size_t k, std::string_view field, NumberStatus status) {
  const std::string coordinate = "coordinate " + std::to_string(k + 1);
  switch (status) {
    case NumberStatus::NaN: return coordinate + " is NaN";
    case NumberStatus::Infinite: return coordinate + " is infinite";
    case NumberStatus::TooLarge: return coordinate + " is too large for a double: " + io::quoted(field);
    default: break;
  }
  if (field.empty()) return coordinate + " is empty";
  return "not a number: " + io::quoted(field);
}

// Appends one point; `hint` is added to a wrong-count message (where a header line may be the
// real mistake).
void parse_point_row(const std::string& name, const ContentLine& line, const std::vector<std::string_view>& fields,
                     int dim, const std::string& hint, std::vector<double>& coords) {
  if (fields.size() != static_cast<std::size_t>(dim)) {
    io::fail_at_line(name, line.number,
                     "expected " + io::count_of(static_cast<std::size_t>(dim), "coordinate", "coordinates") +
                         ", found " + std::to_string(fields.size()) + hint);
  }
  for (std::size_t k = 0; k < fields.size(); ++k) {
    double value = 0;
    const NumberStatus status = io::parse_double(fields[k], value);
    if (status != NumberStatus::Ok) io::fail_at_line(name, line.number, coordinate_problem(k, fields[k], status));
    coords.push_back(value);
  }
}

// The common row, read in one pass without splitting it first: `dim` finite numbers with
// separators as split_fields has them, and nothing after them. Appends them and returns true;
// returns false with `coords` unchanged for anything else (a leading '+', NaN, an empty field,
// a wrong count, a value out of range), which parse_point_row then reads or reports. Where
// this accepts a row, each field is what from_chars consumed up to a separator, the very
// characters parse_double would be given, so the values are the same.
// (With a split first, the splitting costs more instructions than from_chars itself.)
bool append_plain_row(std::string_view line, int dim, std::vector<double>& coords) {
  const char* p = line.data();
  const char* const end = p + line.size();
  const std::size_t at = coords.size();
  coords.resize(at + static_cast<std::size_t>(dim));
  double* out = coords.data() + at;
  for (int k = 0; k < dim; ++k) {
    while (p < end && io::is_blank(*p)) ++p;
    if (k > 0 && p < end && *p == ',') {
      ++p;
      while (p < end && io::is_blank(*p)) ++p;
    }
    const auto result = std::from_chars(p, end, out[k]);
    const bool separated = result.ptr == end || io::is_blank(*result.ptr) || *result.ptr == ',';
    if (result.ec != std::errc() || result.ptr == p || !separated || !std::isfinite(out[k])) {
      coords.resize(at);
      return false;
    }
    p = result.ptr;
  }
  while (p < end && io::is_blank(*p)) ++p;
  if (p != end) coords.resize(at);
  return p == end;
}

// Room for the coordinates without regrowing. The lines actually present cap the estimate,
// so that a header claiming 10^15 points cannot make us allocate for them.
void reserve_coordinates(std::vector<double>& coords, std::size_t points_claimed, std::size_t dim,
                         const io::LineScanner& scanner) {
  const std::size_t points = std::min(points_claimed, scanner.remaining_lines_bound());
  if (points <= SIZE_MAX / dim) coords.reserve(points * dim);
  util::advise_huge_pages(coords.data(), coords.capacity() * sizeof(double));
}

std::string qhull_first_row_hint(const Layout& layout) {
  return " (lines 1-" + std::to_string(layout.header_line) + " were read as a Qhull header: dimension " +
         std::to_string(layout.dim) + ", " + io::count_of(layout.count, "point", "points") + ")";
}

// A lone integer on the first row was probably meant as a header (a count, or a dimension
// without the count Qhull's format needs on the next line); wrong-count messages say so.
std::string lone_integer_hint(const ContentLine& line, const std::vector<std::string_view>& fields) {
  if (fields.size() != 1 || !is_digits_only(fields[0])) return std::string();
  return " (line " + std::to_string(line.number) +
         " holds a single integer and was read as a 1-dimensional point; Qhull's format has the dimension "
         "on the first line and the number of points on the second)";
}

// At least `wanted` content lines in `text`.
bool has_content_lines(std::string_view text, int wanted) {
  io::LineScanner scanner(text);
  ContentLine line;
  for (int k = 0; k < wanted; ++k)
    if (!scanner.next(line.text, line.number)) return false;
  return true;
}

PointCloud parse_text(std::string_view text, const std::string& name) {
  if (io::is_numpy_input(text, name)) return io::parse_npy_points(text, name);
  const io::TextLayout layout = io::detect_text_layout(text, true, name);
  PointCloud cloud = io::parse_text_rows(text.substr(layout.rows_begin), layout.rows_begin, layout.lines_before + 1,
                                         layout, name);
  io::check_text_point_count(layout, cloud.size(), name);
  return cloud;
}

}  // namespace

namespace io {

TextLayout detect_text_layout(std::string_view text, bool whole, const std::string& name) {
  TextLayout result;
  // Only complete lines: a line cut short could pass for a header or a row it is not.
  const std::size_t last_newline = text.rfind('\n');
  const std::string_view lines = whole ? text : text.substr(0, last_newline == std::string_view::npos ? 0 : last_newline + 1);
  if (!whole && !has_content_lines(lines, 3)) return result;
  result.complete = true;
  LineScanner scanner(lines);
  const Layout layout = detect_layout(scanner, name);
  ContentLine line;
  std::vector<std::string_view> fields;
  if (layout.qhull) {
    result.qhull = true;
    result.dim = layout.dim;
    result.count = layout.count;
    result.rows_begin = scanner.position();
    result.lines_before = layout.header_line;
    result.hint = qhull_first_row_hint(layout);
    if (scanner.next(line.text, line.number)) result.first_row = static_cast<std::size_t>(line.text.data() - lines.data());
    return result;
  }
  if (!scanner.next(line.text, line.number)) return result;  // no rows: dim 0
  split_fields(line.text, fields);
  if (is_header_row(fields)) {
    result.rows_begin = scanner.position();
    result.lines_before = line.number;
    if (!scanner.next(line.text, line.number)) return result;
    split_fields(line.text, fields);
  }
  result.first_row = static_cast<std::size_t>(line.text.data() - lines.data());
  result.dim = static_cast<int>(fields.size());
  result.hint = lone_integer_hint(line, fields);
  return result;
}

PointCloud parse_text_rows(std::string_view part, std::size_t offset, std::size_t first_line, const TextLayout& layout,
                           const std::string& name) {
  PointCloud cloud;
  cloud.dim = layout.dim;
  LineScanner scanner(part, first_line, offset == 0);
  if (layout.dim == 0) return cloud;  // no data row anywhere in the text
  reserve_coordinates(cloud.coords, layout.qhull ? layout.count : SIZE_MAX, static_cast<std::size_t>(layout.dim),
                      scanner);
  const std::string no_hint;
  std::vector<std::string_view> fields;
  ContentLine line;
  while (scanner.next(line.text, line.number)) {
    if (append_plain_row(line.text, layout.dim, cloud.coords)) continue;
    split_fields(line.text, fields);
    const bool first = offset + static_cast<std::size_t>(line.text.data() - part.data()) == layout.first_row;
    parse_point_row(name, line, fields, layout.dim, layout.qhull && !first ? no_hint : layout.hint, cloud.coords);
  }
  return cloud;
}

void check_text_point_count(const TextLayout& layout, std::size_t found, const std::string& name) {
  if (layout.qhull && found != layout.count) {
    fail_in_file(name, "header says " + count_of(layout.count, "point", "points") + ", found " + std::to_string(found));
  }
  if (found == 0) fail_in_file(name, "no points");
}

}  // namespace io

PointCloud read_points(const std::string& path) {
  const std::string text = io::read_whole_file(path);
  return parse_text(text, io::display_name(path));
}

PointCloud parse_points(std::istream& in, const std::string& name) {
  const std::string text = io::read_whole_stream(in, name);
  return parse_text(text, name);
}

}  // namespace drange
