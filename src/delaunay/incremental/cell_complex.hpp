// delaunay/incremental/cell_complex.hpp: the simplices of a triangulation under construction,
// closed into a sphere by one vertex at infinity.
//
// Every facet of the convex hull is the facet of one *infinite* cell, whose other vertex is
// kInfinite; so every cell has d + 1 neighbours and the insertion of a point outside the hull
// is the same operation as one inside. Cell c's vertices and neighbours are rows of width d + 1;
// neighbour k is the cell across the facet opposite vertex k. Invariants: finite cells are
// positively oriented; an infinite cell becomes positively oriented when a point strictly
// beyond its hull facet takes kInfinite's place; neighbours are mutual. Removed cells are kept
// for reuse.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace drange::engine {

class CellComplex {
 public:
  static constexpr std::int32_t kInfinite = -1;
  static constexpr std::int32_t kRemoved = -2;  // in a removed cell's first vertex

  explicit CellComplex(int d) : width_(d + 1) {}

  int width() const { return width_; }
  std::size_t capacity() const { return mark_.size(); }

  std::int32_t* vertices(std::int32_t c) { return &vertex_[row(c)]; }
  const std::int32_t* vertices(std::int32_t c) const { return &vertex_[row(c)]; }
  std::int32_t* neighbors(std::int32_t c) { return &neighbor_[row(c)]; }
  const std::int32_t* neighbors(std::int32_t c) const { return &neighbor_[row(c)]; }
  std::uint64_t& mark(std::int32_t c) { return mark_[static_cast<std::size_t>(c)]; }

  bool removed(std::int32_t c) const { return vertex_[row(c)] == kRemoved; }
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
    const auto c = static_cast<std::int32_t>(mark_.size());
    vertex_.resize(vertex_.size() + static_cast<std::size_t>(width_));
    neighbor_.resize(neighbor_.size() + static_cast<std::size_t>(width_));
    mark_.push_back(0);
    return c;
  }
  void remove(std::int32_t c) {
    vertex_[row(c)] = kRemoved;
    free_.push_back(c);
  }
  void reserve(std::size_t cells) {
    vertex_.reserve(cells * static_cast<std::size_t>(width_));
    neighbor_.reserve(cells * static_cast<std::size_t>(width_));
    mark_.reserve(cells);
  }

 private:
  std::size_t row(std::int32_t c) const { return static_cast<std::size_t>(c) * static_cast<std::size_t>(width_); }

  int width_;
  std::vector<std::int32_t> vertex_;
  std::vector<std::int32_t> neighbor_;
  std::vector<std::uint64_t> mark_;  // Insertion's stamps (conflict, outside, new), per insertion
  std::vector<std::int32_t> free_;
};

}  // namespace drange::engine
