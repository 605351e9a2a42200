// util/cache_size.hpp: the size of a core's level-2 cache, as the system reports it.
//
// The driver prefetches the facet table's slots only once the table outgrows this cache
// (delaunay/frontier.hpp): a fixed size, right for one machine, would leave a table that
// outgrows a smaller L2 unprefetched, where its lookups miss.
#pragma once

#include <cstddef>

#if defined(__unix__) || defined(__APPLE__)
#include <unistd.h>
#endif

namespace drange::util {

// The L2 size in bytes, or `fallback` where the system does not say (sysconf's
// _SC_LEVEL2_CACHE_SIZE is glibc's; it may also report 0).
inline std::size_t level2_cache_bytes(std::size_t fallback) {
#if defined(_SC_LEVEL2_CACHE_SIZE)
  const long bytes = sysconf(_SC_LEVEL2_CACHE_SIZE);
  if (bytes > 0) return static_cast<std::size_t>(bytes);
#endif
  return fallback;
}

}  // namespace drange::util
