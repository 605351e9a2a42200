// tests/select_nth_test.cpp: util/select_nth.hpp against std::sort. Under a strict total order
// the element at nth and the sets on each side are unique, so each must be std::sort's; on keys
// with ties (a weak order) the contract alone is checked. The orders cover the partition's
// cases and its fallback: random, sorted, reversed, organ pipe, few distinct keys, all equal.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "util/select_nth.hpp"

namespace {

using drange::util::select_nth;

struct Item {
  double key;
  std::int32_t index;
};
bool by_key_then_index(const Item& a, const Item& b) { return a.key < b.key || (a.key == b.key && a.index < b.index); }
bool by_key(const Item& a, const Item& b) { return a.key < b.key; }

enum class Shape { Random, Sorted, Reversed, OrganPipe, FewKeys, AllEqual };

std::vector<Item> make(Shape shape, std::size_t n, std::mt19937_64& rng) {
  std::vector<Item> items(n);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (std::size_t i = 0; i < n; ++i) {
    double key = 0.0;
    switch (shape) {
      case Shape::Random: key = u(rng); break;
      case Shape::Sorted: key = static_cast<double>(i); break;
      case Shape::Reversed: key = static_cast<double>(n - i); break;
      case Shape::OrganPipe: key = static_cast<double>(std::min(i, n - i)); break;
      case Shape::FewKeys: key = static_cast<double>(rng() % 3); break;
      case Shape::AllEqual: key = 1.0; break;
    }
    items[i] = Item{key, static_cast<std::int32_t>(i)};
  }
  return items;
}

template <class Less>
void expect_selected(const std::vector<Item>& input, std::size_t nth, Less less, bool total, const std::string& at) {
  std::vector<Item> sorted = input;
  std::sort(sorted.begin(), sorted.end(), less);
  std::vector<Item> items = input;
  select_nth(items.data(), items.data() + nth, items.data() + items.size(), less);
  const Item pivot = items[nth];
  ASSERT_EQ(pivot.key, sorted[nth].key) << at;
  if (total) ASSERT_EQ(pivot.index, sorted[nth].index) << at;
  for (std::size_t i = 0; i < nth; ++i) ASSERT_FALSE(less(pivot, items[i])) << at << " left " << i;
  for (std::size_t i = nth + 1; i < items.size(); ++i) ASSERT_FALSE(less(items[i], pivot)) << at << " right " << i;
  // A permutation of the input: every index once.
  std::vector<bool> seen(items.size(), false);
  for (const Item& item : items) {
    ASSERT_FALSE(seen[static_cast<std::size_t>(item.index)]) << at;
    seen[static_cast<std::size_t>(item.index)] = true;
  }
}

TEST(SelectNth, AgreesWithSortOnEveryShapeAndSize) {
  std::mt19937_64 rng(17);
  for (Shape shape : {Shape::Random, Shape::Sorted, Shape::Reversed, Shape::OrganPipe, Shape::FewKeys, Shape::AllEqual}) {
    for (std::size_t n : {1u, 2u, 3u, 15u, 16u, 17u, 100u, 255u, 256u, 257u, 1000u, 4099u, 100000u}) {
      const std::vector<Item> input = make(shape, n, rng);
      for (std::size_t nth : {std::size_t{0}, n / 2, n - 1, static_cast<std::size_t>(rng() % n)}) {
        const std::string at = "shape " + std::to_string(static_cast<int>(shape)) + " n " + std::to_string(n) +
                               " nth " + std::to_string(nth);
        expect_selected(input, nth, by_key_then_index, true, at + " (total order)");
        expect_selected(input, nth, by_key, false, at + " (ties)");
      }
    }
  }
}

}  // namespace
