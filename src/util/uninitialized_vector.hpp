// util/uninitialized_vector.hpp: a std::vector whose new elements are default-initialized, for
// large arrays of plain values that are filled right after they are made.
//
// std::vector<T>(n) and resize(n) write zeros to every element; the kernel has zeroed the fresh
// pages already, so the memory is written twice, and by the calling thread alone, before the
// threads that fill it start (prepare_points.cpp: tens of megabytes of items for a million points).
// Here an element of a trivial type is left as the memory holds it: each page is touched
// first by the thread that fills it. A large array is also backed by 2 MiB pages where the
// system allows (huge_pages.hpp).
#pragma once

#include <memory>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

#include "util/huge_pages.hpp"

namespace drange::util {

template <class T>
struct DefaultInitAllocator : std::allocator<T> {
  template <class U>
  struct rebind {
    using other = DefaultInitAllocator<U>;
  };
  DefaultInitAllocator() = default;
  template <class U>
  DefaultInitAllocator(const DefaultInitAllocator<U>&) noexcept {}

  T* allocate(std::size_t n) {
    T* p = std::allocator<T>::allocate(n);
    advise_huge_pages(p, n * sizeof(T));
    return p;
  }

  template <class U>
  void construct(U* p) noexcept(std::is_nothrow_default_constructible_v<U>) {
    ::new (static_cast<void*>(p)) U;  // default-initialization: nothing for a trivial U
  }
  template <class U, class... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
};

template <class T>
using UninitializedVector = std::vector<T, DefaultInitAllocator<T>>;

}  // namespace drange::util
