// geometry/minors.cpp: the column-subset tables behind MinorTable.
#include "geometry/minors.hpp"

#include <array>
#include <memory>
#include <mutex>

#include "drange/errors.hpp"

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
  if (columns < 0 || columns > kMaxColumns) throw InternalError("SubsetTable: too many columns");
  // Each column count's table is built on its first use, thread-safely: a 2D run needs the
  // 3-column table (a few hundred bytes), not all of them (241 kB, most of it the 12-column
  // one: a large share of a small run's own heap).
  static std::array<std::once_flag, kMaxColumns + 1> once;
  static std::array<std::unique_ptr<const SubsetTable>, kMaxColumns + 1> tables;
  const auto at = static_cast<std::size_t>(columns);
  std::call_once(once[at], [&] { tables[at] = std::make_unique<const SubsetTable>(columns); });
  return *tables[at];
}

}  // namespace drange::geometry
