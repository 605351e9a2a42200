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
  // The Laplace expansion of each subset of size r along its last row, flattened: for the
  // subsets of of_size(r) in that order, r terms each, one per member column in increasing
  // order, with the subset less that column and the cofactor's sign (-1)^(r - 1 + position).
  struct Term {
    std::uint16_t sub;
    std::uint8_t column;
    std::uint8_t negative;
  };
  const std::vector<Term>& terms_of_size(int r) const { return terms_[static_cast<std::size_t>(r)]; }

  // The shared table for n columns (n <= kMaxColumns), built once.
  static const SubsetTable& get(int columns);
  static constexpr int kMaxColumns = 12;

 private:
  int columns_;
  std::vector<std::vector<std::uint32_t>> by_size_;
  std::vector<std::vector<Term>> terms_;
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
    // The terms in a flat table (SubsetTable::terms_of_size): the same products, summed in the
    // same order, as walking each subset's bits (v - term is v + (-term) exactly), without
    // the bit loop and the sign branch (8D 150 points: time_search 3.63 -> 3.27 s).
    double row_abs[SubsetTable::kMaxColumns];
    for (int j = 0; j < columns(); ++j) row_abs[j] = std::fabs(row[j]);
    const SubsetTable::Term* t = subsets_->terms_of_size(r + 1).data();
    constexpr double kSign[2] = {1.0, -1.0};  // -1 * term is -term exactly
    for (std::uint32_t mask : subsets_->of_size(r + 1)) {
      double v = 0.0, a = 0.0;
      for (int p = 0; p <= r; ++p, ++t) {
        const double term = row[t->column] * value_[t->sub];
        v += kSign[t->negative] * term;
        a += row_abs[t->column] * abs_[t->sub];
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
