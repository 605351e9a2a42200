// io/write_cells_text.cpp: clipped cells as text lines (formats.hpp, "Text cells").
#include <cctype>
#include <charconv>
#include <string>
#include <vector>

#include "drange/formats.hpp"
#include "io/cell_parts.hpp"

namespace drange {

void append_cell_text(std::string& text, const ClippedCells& cells, std::size_t c, std::int32_t point, bool vertices) {
  const auto dim = static_cast<std::size_t>(cells.dim);
  std::vector<std::int32_t> corners;
  if (vertices && cells.cell_faces[c + 1] > cells.cell_faces[c]) {
    const auto first = static_cast<std::size_t>(cells.cell_faces[c]);
    if (dim == 2) corners.assign(cells.faces.row(first), cells.faces.row(first) + cells.faces.row_size(first));
    else corners = io::cell_corners(cells, c);
  }
  // Formatted straight into room made at the end of `text` (appending number by number would
  // cost more than the formatting): at most 24 characters per number and a separator.
  constexpr std::size_t kRoom = 25;
  const std::size_t used = text.size();
  text.resize(used + kRoom * (3 + corners.size() * dim) + 1);
  char* at = &text[used];
  char* const end = &text[0] + text.size();
  at = std::to_chars(at, end, point).ptr;
  *at++ = ' ';
  at = std::to_chars(at, end, cells.volumes[c]).ptr;
  if (vertices) {
    *at++ = ' ';
    at = std::to_chars(at, end, corners.size()).ptr;
    for (const std::int32_t corner : corners)
      for (std::size_t k = 0; k < dim; ++k) {
        *at++ = ' ';
        at = std::to_chars(at, end, cells.points[static_cast<std::size_t>(corner) * dim + k]).ptr;
      }
  }
  *at++ = '\n';
  text.resize(static_cast<std::size_t>(at - text.data()));
}

bool is_cells_text_path(const std::string& path) {
  const std::string suffix = ".txt";
  if (path.size() < suffix.size()) return false;
  for (std::size_t i = 0; i < suffix.size(); ++i)
    if (std::tolower(static_cast<unsigned char>(path[path.size() - suffix.size() + i])) != suffix[i]) return false;
  return true;
}

}  // namespace drange
