// io/write_cells_text.cpp: clipped cells as text lines (formats.hpp, "Text cells").
#include <cctype>
#include <charconv>
#include <string>
#include <utility>
#include <vector>

#include "drange/formats.hpp"
#include "io/cell_parts.hpp"

namespace drange {
namespace {

// Text built in a string grown ahead of the writes, so that each number is formatted straight
// into it (appending piece by piece would cost more than the formatting).
class TextBuilder {
 public:
  template <typename Number>
  void number(Number value) {
    reserve();
    used_ = static_cast<std::size_t>(std::to_chars(&text_[used_], &text_[used_] + kRoom, value).ptr - text_.data());
  }
  void put(char c) {
    reserve();
    text_[used_++] = c;
  }
  std::string take() {
    text_.resize(used_);
    return std::move(text_);
  }

 private:
  // A double's shortest form takes at most 24 characters.
  static constexpr std::size_t kRoom = 32;
  void reserve() {
    if (used_ + kRoom > text_.size()) text_.resize(2 * text_.size() + 4096);
  }

  std::string text_;
  std::size_t used_ = 0;
};

}  // namespace

std::string cells_text(const CellBatch& batch, bool vertices) {
  const ClippedCells& cells = batch.cells;
  const auto dim = static_cast<std::size_t>(cells.dim);
  TextBuilder out;
  std::vector<std::int32_t> corners;
  for (std::size_t c = 0; c < cells.size(); ++c) {
    out.number(batch.point[c]);
    out.put(' ');
    out.number(cells.volumes[c]);
    if (vertices) {
      const auto first = static_cast<std::size_t>(cells.cell_faces[c]);
      if (cells.cell_faces[c + 1] == cells.cell_faces[c]) corners.clear();
      else if (dim == 2) corners.assign(cells.faces.row(first), cells.faces.row(first) + cells.faces.row_size(first));
      else corners = io::cell_corners(cells, c);
      out.put(' ');
      out.number(corners.size());
      for (const std::int32_t corner : corners)
        for (std::size_t k = 0; k < dim; ++k) {
          out.put(' ');
          out.number(cells.points[static_cast<std::size_t>(corner) * dim + k]);
        }
    }
    out.put('\n');
  }
  return out.take();
}

bool is_cells_text_path(const std::string& path) {
  const std::string suffix = ".txt";
  if (path.size() < suffix.size()) return false;
  for (std::size_t i = 0; i < suffix.size(); ++i)
    if (std::tolower(static_cast<unsigned char>(path[path.size() - suffix.size() + i])) != suffix[i]) return false;
  return true;
}

}  // namespace drange
