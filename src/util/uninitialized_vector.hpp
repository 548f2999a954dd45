// A std::vector whose resize() leaves new elements of trivial types uninitialised: for large
// arrays that a parallel loop fills completely right after, so that their memory is first
// touched (and its pages faulted in) by the threads writing it, not zeroed by one thread first.
// Its large buffers come from the page pool (util/page_pool.hpp): inside a PageReuseScope they
// reuse pages that earlier large arrays gave back (not with AddressSanitizer, which checks
// heap buffers only). PooledVector: the same buffers, ordinary construction.
#pragma once

#include "util/page_pool.hpp"

#include <cstddef>
#include <memory>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

namespace hoct {

// Large buffers from the page pool, small ones from the heap; elements constructed as by
// std::allocator (value-initialised on resize).
template <class T> struct PooledAllocator : std::allocator<T> {
  template <class U> struct rebind { using other = PooledAllocator<U>; };
  PooledAllocator() = default;
  template <class U> PooledAllocator(const PooledAllocator<U> &) noexcept {}
  T *allocate(std::size_t n) {
    if (pooled(n))
      return static_cast<T *>(allocate_pages(n * sizeof(T)));
    return std::allocator<T>::allocate(n);
  }
  void deallocate(T *p, std::size_t n) noexcept {
    if (pooled(n))
      free_pages(p, n * sizeof(T));
    else
      std::allocator<T>::deallocate(p, n);
  }

private:
  static bool pooled(std::size_t n) {
#if defined(__SANITIZE_ADDRESS__)
    (void)n;
    return false;
#else
    static_assert(alignof(T) <= 64, "page pool blocks are aligned to 64 bytes");
    return n >= kPooledBytes / sizeof(T);
#endif
  }
};
template <class T, class U>
bool operator==(const PooledAllocator<T> &, const PooledAllocator<U> &) noexcept {
  return true;
}

// The same, but default construction is default-initialisation (nothing, for trivial types).
template <class T> struct UninitializedAllocator : PooledAllocator<T> {
  template <class U> struct rebind { using other = UninitializedAllocator<U>; };
  UninitializedAllocator() = default;
  template <class U> UninitializedAllocator(const UninitializedAllocator<U> &) noexcept {}
  template <class U> void construct(U *p) noexcept(std::is_nothrow_default_constructible_v<U>) {
    ::new (static_cast<void *>(p)) U;
  }
  template <class U, class... Args> void construct(U *p, Args &&...args) {
    ::new (static_cast<void *>(p)) U(std::forward<Args>(args)...);
  }
};
template <class T, class U>
bool operator==(const UninitializedAllocator<T> &, const UninitializedAllocator<U> &) noexcept {
  return true;
}

// An ordinary vector (elements value-initialised) whose large buffers come from the page pool:
// for large arrays built by appending or filled in order.
template <class T> using PooledVector = std::vector<T, PooledAllocator<T>>;

template <class T>
requires std::is_trivially_default_constructible_v<T>
using UninitializedVector = std::vector<T, UninitializedAllocator<T>>;

} // namespace hoct
