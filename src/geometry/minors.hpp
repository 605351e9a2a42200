// geometry/minors.hpp: determinants by Laplace expansion with memoised minors, carrying the
// absolute-value tree that bounds their rounding error (error_bound.hpp).
//
// Rows are added one at a time. After r rows, minor(mask) for every column set `mask` of r
// columns is the determinant of those r rows restricted to those columns; abs_minor(mask) is
// the same expansion on absolute values. Adding a row r+1 only writes the minors of r+1
// columns, so a caller can add row r+1 again and again for different rows (the kd-tree search
// does: one facet, many candidate points) without recomputing the first r levels.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

namespace drange::geometry {

// Column subsets of {0..n-1} grouped by size, with their members in increasing order.
class SubsetTable {
 public:
  explicit SubsetTable(int columns);
  int columns() const { return columns_; }
  const std::vector<std::uint32_t>& of_size(int r) const { return by_size_[static_cast<std::size_t>(r)]; }

  // The shared table for n columns (n <= kMaxColumns), built once.
  static const SubsetTable& get(int columns);
  static constexpr int kMaxColumns = 12;

 private:
  int columns_;
  std::vector<std::vector<std::uint32_t>> by_size_;
};

// Up to kInlineColumns columns the minors live in the object itself (no allocation: the
// predicates build one table per call); beyond, on the heap.
class MinorTable {
 public:
  static constexpr int kInlineColumns = 7;

  explicit MinorTable(int columns) : subsets_(&SubsetTable::get(columns)) { attach(columns); }
  MinorTable(const MinorTable& other) : subsets_(other.subsets_), heap_(other.heap_) {
    attach(other.columns());
    copy_from(other);
  }
  MinorTable& operator=(const MinorTable& other) {
    if (this != &other) {
      subsets_ = other.subsets_;
      heap_ = other.heap_;
      attach(other.columns());
      copy_from(other);
    }
    return *this;
  }

  int columns() const { return subsets_->columns(); }

  // Sets row `r` (0-based; rows 0..r-1 must be set): computes every minor of r+1 columns.
  void set_row(int r, const double* row) {
    for (std::uint32_t mask : subsets_->of_size(r + 1)) {
      double v = 0.0, a = 0.0;
      int position = 0;  // index of column j within mask: gives the cofactor sign
      for (std::uint32_t rest = mask; rest; rest &= rest - 1, ++position) {
        const int j = __builtin_ctz(rest);
        const std::uint32_t sub = mask & ~(std::uint32_t{1} << j);
        const double term = row[j] * value_[sub];
        // Sign of the cofactor of entry (r, j) in the minor: (-1)^(r + position).
        if ((r + position) & 1) v -= term; else v += term;
        a += std::fabs(row[j]) * abs_[sub];
      }
      value_[mask] = v;
      abs_[mask] = a;
    }
  }

  double minor(std::uint32_t mask) const { return value_[mask]; }
  double abs_minor(std::uint32_t mask) const { return abs_[mask]; }

 private:
  // Points value_ and abs_ at the storage; only the empty minor needs a value before set_row.
  void attach(int columns) {
    const std::size_t size = std::size_t{1} << columns;
    if (columns > kInlineColumns) {
      heap_.resize(2 * size);
      value_ = heap_.data();
    } else {
      value_ = inline_;
    }
    abs_ = value_ + size;
    value_[0] = 1.0;
    abs_[0] = 1.0;
  }
  void copy_from(const MinorTable& other) {
    if (columns() > kInlineColumns) return;  // heap_ was copied
    const std::size_t size = std::size_t{1} << columns();
    std::copy(other.value_, other.value_ + size, value_);
    std::copy(other.abs_, other.abs_ + size, abs_);
  }

  const SubsetTable* subsets_;
  std::vector<double> heap_;
  double* value_ = nullptr;
  double* abs_ = nullptr;
  double inline_[2 << kInlineColumns];
};

}  // namespace drange::geometry
