// util/huge_pages.hpp: asks the kernel to back a large fresh array with 2 MiB pages.
//
// Each 4 KiB page of a fresh array costs a page fault when first touched: a run on a million
// points makes tens of thousands. 2 MiB pages for the arrays of the prepared points, the
// kd-tree, the seeds and the input text and coordinates remove most of those faults and
// measurably shorten the preparation. Not for the simplices and neighbours: the kernel zeroes
// each 2 MiB page at once, in the middle of the search, which made the 3D search slower. Linux
// backs memory with them where a program asks when /sys/kernel/mm/transparent_hugepage/enabled
// says "madvise", everywhere when it says "always", and never when it says
// "never". The advice is a hint: where it is refused or unknown, nothing changes but the count
// of faults.
#pragma once

#include <cstddef>
#include <cstdint>
#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace drange::util {

inline void advise_huge_pages(const void* data, std::size_t bytes) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  constexpr std::uintptr_t kHuge = std::uintptr_t{2} << 20;
  if (bytes < 2 * kHuge) return;  // only the whole 2 MiB pages inside the array can be huge
  const auto start = reinterpret_cast<std::uintptr_t>(data);
  const std::uintptr_t begin = (start + kHuge - 1) & ~(kHuge - 1), end = (start + bytes) & ~(kHuge - 1);
  if (end > begin) madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
#else
  (void)data;
  (void)bytes;
#endif
}

}  // namespace drange::util
