// util/return_free_memory.hpp: hands the allocator's free memory back to the system.
//
// The facet table and queue grow by doubling: each growth frees the old buffer. glibc serves
// large blocks with mmap at first, but every such free raises its mmap threshold (up to
// 32 MiB), after which buffers of that size come from the heap, and a freed one stays resident
// until the heap is trimmed (its top beyond twice the threshold). The peak memory then carries
// freed buffers, markedly so in high dimensions; this call after each growth keeps them out
// of it, as a fixed threshold (MALLOC_MMAP_THRESHOLD_) would. The call is made O(log n) times
// per run.
#pragma once

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace drange::util {

inline void return_free_memory() {
#if defined(__GLIBC__)
  malloc_trim(0);
#endif
}

}  // namespace drange::util
