// io/text_points.hpp: the text layouts of read_points in two steps, so that a reader may parse
// a part of a file alone (the processes of a split run each read a byte range of the input):
// first what the start of the text says (the layout, the dimension, where the point rows
// begin), then the rows of any run of whole lines after that, with their true line numbers.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

#include "drange/points.hpp"

namespace drange::io {

inline constexpr std::size_t kNoRow = static_cast<std::size_t>(-1);

struct TextLayout {
  bool complete = false;         // the text given sufficed to tell (see detect_text_layout)
  bool qhull = false;            // Qhull's format, else rows
  int dim = 0;                   // Qhull: the header's; rows: the first data row's (0: no row)
  std::size_t count = 0;         // Qhull: the header's count
  std::size_t rows_begin = 0;    // byte offset of the line after the header (Qhull's, or a CSV header row)
  std::size_t lines_before = 0;  // physical lines before rows_begin
  std::size_t first_row = kNoRow;  // byte offset of the first data row
  // Added to a wrong-count message: Qhull: for the first data row only; rows: for every row.
  std::string hint;
};

// The layout, from the start of the text. With `whole` false, `text` may end anywhere: only its
// complete lines are read, and `complete` is false when they are fewer than the three content
// lines the detection may need (then read more). Throws InputError for a malformed header.
TextLayout detect_text_layout(std::string_view text, bool whole, const std::string& name);

// The points of `part`: whole lines of the text from byte `offset` (at or after rows_begin),
// whose first physical line is line `first_line`. Throws InputError naming `name` and the line.
PointCloud parse_text_rows(std::string_view part, std::size_t offset, std::size_t first_line, const TextLayout& layout,
                           const std::string& name);

// Throws InputError when `found` points contradict the layout: a Qhull count that does not
// match, or no point at all.
void check_text_point_count(const TextLayout& layout, std::size_t found, const std::string& name);

}  // namespace drange::io
