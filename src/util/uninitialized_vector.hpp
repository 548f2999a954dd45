// A std::vector whose resize() leaves new elements of trivial types uninitialised: for large
// arrays that a parallel loop fills completely right after, so that their memory is first
// touched (and its pages faulted in) by the threads writing it, not zeroed by one thread first.
#pragma once

#include <memory>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

namespace hoct {

template <class T> struct UninitializedAllocator : std::allocator<T> {
  template <class U> struct rebind { using other = UninitializedAllocator<U>; };
  UninitializedAllocator() = default;
  template <class U> UninitializedAllocator(const UninitializedAllocator<U> &) noexcept {}
  // Default construction is default-initialisation (nothing, for trivial types).
  template <class U> void construct(U *p) noexcept(std::is_nothrow_default_constructible_v<U>) {
    ::new (static_cast<void *>(p)) U;
  }
  template <class U, class... Args> void construct(U *p, Args &&...args) {
    ::new (static_cast<void *>(p)) U(std::forward<Args>(args)...);
  }
};

template <class T>
requires std::is_trivially_default_constructible_v<T>
using UninitializedVector = std::vector<T, UninitializedAllocator<T>>;

} // namespace hoct
