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
    // the bit loop and the sign branch, which dominate the search in high dimensions.
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

  // set_row for a table of exactly C columns, with the Laplace terms laid out at compile time
  // (the kd-tree search's facets, d = 2 to 8: C = d + 1): no term table to read, the cofactor
  // signs known, and each minor's address a constant. The same products are summed in the same
  // order as by set_row, so every minor is the same double. (The generic loop spends several
  // times the instructions per term, a visible share of a 5D run.)
  template <int C>
  void set_row_fixed(int r, const double* row) {
    double x[C], x_abs[C];  // locals: the stores to value_ below cannot change them
    for (int j = 0; j < C; ++j) {
      x[j] = row[j];
      x_abs[j] = std::fabs(row[j]);
    }
    expand_size<C, 1>(r + 1, x, x_abs);
  }

  double minor(std::uint32_t mask) const { return value_[mask]; }
  double abs_minor(std::uint32_t mask) const { return abs_[mask]; }

 private:
  template <int C, int S>
  void expand_size(int size, const double* x, const double* x_abs) {
    if constexpr (S <= C) {
      if (size == S) expand_fixed<C, S>(x, x_abs);
      else expand_size<C, S + 1>(size, x, x_abs);
    }
  }
  // Every minor of S columns from those of S - 1, as set_row (SubsetTable's order and signs).
  template <int C, int S>
  void expand_fixed(const double* x, const double* x_abs);

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

// The number of set bits (the columns of a mask), inline and without branches: the build
// targets plain x86-64, where __builtin_popcount is a library call, and the facet search's
// exactness check makes one call per column set (on integer grids this form takes fewer
// instructions than the call, and than a counting loop, which loses in 2D).
constexpr int bit_count(std::uint32_t x) {
  x = x - ((x >> 1) & 0x55555555u);
  x = (x & 0x33333333u) + ((x >> 2) & 0x33333333u);
  return static_cast<int>((((x + (x >> 4)) & 0x0f0f0f0fu) * 0x01010101u) >> 24);
}

namespace minors_detail {

constexpr int binomial(int n, int k) {
  long long b = 1;
  for (int i = 1; i <= k; ++i) b = b * (n - k + i) / i;
  return static_cast<int>(b);
}

// The column subsets of size S of C columns in increasing mask order (SubsetTable::of_size's),
// each with its Laplace expansion along the last row: member column p in increasing order, and
// the subset less that column (SubsetTable::terms_of_size).
template <int C, int S>
struct FixedTerms {
  static constexpr int kSubsets = binomial(C, S);
  std::uint32_t mask[kSubsets];
  std::uint32_t sub[kSubsets][S];
  int column[kSubsets][S];
};

template <int C, int S>
constexpr FixedTerms<C, S> make_fixed_terms() {
  FixedTerms<C, S> terms{};
  int i = 0;
  for (std::uint32_t mask = 0; mask < (std::uint32_t{1} << C); ++mask) {
    if (bit_count(mask) != S) continue;
    terms.mask[i] = mask;
    int p = 0;
    for (int j = 0; j < C; ++j) {
      if (((mask >> j) & 1u) == 0) continue;
      terms.sub[i][p] = mask & ~(std::uint32_t{1} << j);
      terms.column[i][p] = j;
      ++p;
    }
    ++i;
  }
  return terms;
}

}  // namespace minors_detail

template <int C, int S>
void MinorTable::expand_fixed(const double* x, const double* x_abs) {
  static constexpr minors_detail::FixedTerms<C, S> kTerms = minors_detail::make_fixed_terms<C, S>();
#pragma GCC unroll 128
  for (int i = 0; i < kTerms.kSubsets; ++i) {
    double v = 0.0, a = 0.0;
#pragma GCC unroll 16
    for (int p = 0; p < S; ++p) {
      const double term = x[kTerms.column[i][p]] * value_[kTerms.sub[i][p]];
      // The cofactor's sign (-1)^(S - 1 + p): v - term is v + (-1 * term) exactly.
      if ((S - 1 + p) & 1) v -= term;
      else v += term;
      a += x_abs[kTerms.column[i][p]] * abs_[kTerms.sub[i][p]];
    }
    value_[kTerms.mask[i]] = v;
    abs_[kTerms.mask[i]] = a;
  }
}

}  // namespace drange::geometry
