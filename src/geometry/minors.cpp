// geometry/minors.cpp: the column-subset tables behind MinorTable.
#include "geometry/minors.hpp"

#include <stdexcept>

namespace drange::geometry {

SubsetTable::SubsetTable(int columns)
    : columns_(columns), by_size_(static_cast<std::size_t>(columns) + 1), terms_(static_cast<std::size_t>(columns) + 1) {
  for (std::uint32_t mask = 0; mask < (std::uint32_t{1} << columns); ++mask)
    by_size_[static_cast<std::size_t>(__builtin_popcount(mask))].push_back(mask);
  for (int size = 1; size <= columns; ++size) {
    for (std::uint32_t mask : by_size_[static_cast<std::size_t>(size)]) {
      int position = 0;
      for (std::uint32_t rest = mask; rest; rest &= rest - 1, ++position) {
        const int j = __builtin_ctz(rest);
        terms_[static_cast<std::size_t>(size)].push_back(Term{static_cast<std::uint16_t>(mask & ~(std::uint32_t{1} << j)),
                                                              static_cast<std::uint8_t>(j),
                                                              static_cast<std::uint8_t>((size - 1 + position) & 1)});
      }
    }
  }
}

const SubsetTable& SubsetTable::get(int columns) {
  // Built once, on first use, thread-safely (static local initialisation).
  static const std::vector<SubsetTable> tables = [] {
    std::vector<SubsetTable> t;
    for (int n = 0; n <= kMaxColumns; ++n) t.emplace_back(n);
    return t;
  }();
  if (columns < 0 || columns > kMaxColumns) throw std::logic_error("SubsetTable: too many columns");
  return tables[static_cast<std::size_t>(columns)];
}

}  // namespace drange::geometry
