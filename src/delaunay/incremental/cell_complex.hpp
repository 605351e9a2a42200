// delaunay/incremental/cell_complex.hpp: the simplices of a triangulation under construction,
// closed into a sphere by one vertex at infinity.
//
// Every facet of the convex hull is the facet of one *infinite* cell, whose other vertex is
// kInfinite; so every cell has d + 1 neighbours and the insertion of a point outside the hull
// is the same operation as one inside. Cell c's vertices and neighbours are rows of width d + 1;
// neighbour k is the cell across the facet opposite vertex k. Invariants: finite cells are
// positively oriented; an infinite cell becomes positively oriented when a point strictly
// beyond its hull facet takes kInfinite's place; neighbours are mutual. Removed cells are kept
// for reuse. A cell's vertices, neighbours and mark share one row of the storage (2d + 3
// ints), so that visiting a cell touches one or two cache lines, not three.
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "drange/errors.hpp"

namespace drange::engine {

class CellComplex {
 public:
  static constexpr std::int32_t kInfinite = -1;
  static constexpr std::int32_t kRemoved = -2;  // in a removed cell's first vertex

  explicit CellComplex(int d) : width_(d + 1), stride_(2 * (d + 1) + 1) {}

  int width() const { return width_; }
  std::size_t capacity() const { return cells_; }

  std::int32_t* vertices(std::int32_t c) { return &data_[row(c)]; }
  const std::int32_t* vertices(std::int32_t c) const { return &data_[row(c)]; }
  std::int32_t* neighbors(std::int32_t c) { return &data_[row(c) + static_cast<std::size_t>(width_)]; }
  const std::int32_t* neighbors(std::int32_t c) const { return &data_[row(c) + static_cast<std::size_t>(width_)]; }
  // A stamp that the insertion writes (Insertion: conflict, outside, new); 0 in a new cell.
  std::int32_t& mark(std::int32_t c) { return data_[row(c) + static_cast<std::size_t>(2 * width_)]; }
  // Sets every cell's mark to 0, before the stamps wrap around.
  void clear_marks() {
    for (std::size_t c = 0; c < cells_; ++c) data_[c * static_cast<std::size_t>(stride_) + static_cast<std::size_t>(2 * width_)] = 0;
  }

  bool removed(std::int32_t c) const { return data_[row(c)] == kRemoved; }
  // The position of kInfinite among c's vertices, or -1 for a finite cell.
  int infinite_position(std::int32_t c) const {
    const std::int32_t* v = vertices(c);
    for (int k = 0; k < width_; ++k)
      if (v[k] == kInfinite) return k;
    return -1;
  }
  int index_of_vertex(std::int32_t c, std::int32_t vertex) const {
    const std::int32_t* v = vertices(c);
    int k = 0;
    while (v[k] != vertex) ++k;  // the caller knows that c has it
    return k;
  }
  int index_of_neighbor(std::int32_t c, std::int32_t other) const {
    const std::int32_t* n = neighbors(c);
    int k = 0;
    while (n[k] != other) ++k;  // the caller knows that they are neighbours
    return k;
  }
  bool has_vertex(std::int32_t c, std::int32_t vertex) const {
    const std::int32_t* v = vertices(c);
    for (int k = 0; k < width_; ++k)
      if (v[k] == vertex) return true;
    return false;
  }

  // A cell whose rows the caller fills (a removed one reused, or a new one).
  std::int32_t create() {
    if (!free_.empty()) {
      const std::int32_t c = free_.back();
      free_.pop_back();
      return c;
    }
    // Cell ids are 32-bit (as the output's simplex numbers): past that, refuse rather than wrap.
    if (cells_ >= static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max()))
      throw InputError("the triangulation would have more than 2^31 - 1 cells, drange's limit");
    const auto c = static_cast<std::int32_t>(cells_++);
    data_.resize(data_.size() + static_cast<std::size_t>(stride_));
    return c;
  }
  void remove(std::int32_t c) {
    data_[row(c)] = kRemoved;
    free_.push_back(c);
  }
  void reserve(std::size_t cells) {
    data_.reserve(cells * static_cast<std::size_t>(stride_));
  }

 private:
  std::size_t row(std::int32_t c) const { return static_cast<std::size_t>(c) * static_cast<std::size_t>(stride_); }

  int width_;
  int stride_;  // vertices, neighbours, mark
  std::size_t cells_ = 0;
  std::vector<std::int32_t> data_;
  std::vector<std::int32_t> free_;
};

}  // namespace drange::engine
