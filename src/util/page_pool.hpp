// Large buffers whose pages are reused within a computation. On this kind of machine (a virtual
// machine) first touching a fresh 4 KiB page costs as much as the work done in it, and the C
// library returns every large block to the system when it is freed, so each phase of a tree on
// millions of cells would pay again for pages an earlier phase had just given back.
//
// Blocks of kPooledBytes and more are anonymous mappings. While a PageReuseScope is open anywhere
// in the process, freed blocks are kept: a later request takes the smallest kept block that fits
// (the rest of it stays kept), or grows the largest one (mremap: its pages stay, only the growth
// is new). When the last scope closes, the kept blocks go back to the system except up to 64 MiB
// of them (as the C library keeps up to 64 MiB of its heap), which serve the next computation;
// outside scopes, freed blocks are kept only up to those 64 MiB.
// New blocks of 2 MiB and more ask for transparent huge pages (where the system allows them on
// request): one first touch then maps 2 MiB, where it would map 4 KiB.
// Kept pages are pages the computation used before, so the peak memory does not grow as long as
// its large arrays come from here.
#pragma once

#include <cstddef>

namespace hoct {

inline constexpr std::size_t kPooledBytes = std::size_t{1} << 20;

// Memory for `bytes` bytes (>= kPooledBytes), aligned to 64 bytes, contents unspecified; throws
// std::bad_alloc when the system has none.
void *allocate_pages(std::size_t bytes);
// Gives back a block from allocate_pages (the same byte count).
void free_pages(void *p, std::size_t bytes) noexcept;

// Maps the pages of [p, p + bytes) that lie wholly inside it for writing, in one call (Linux
// 5.14 and later; elsewhere nothing): for memory about to be written whole, such as the target of
// a large read, cheaper than faulting the pages in one at a time. Never fails.
void populate_for_write(void *p, std::size_t bytes) noexcept;

// Bytes kept for reuse right now (for tests and diagnostics).
std::size_t kept_page_bytes();

class PageReuseScope {
public:
  PageReuseScope();
  ~PageReuseScope();
  PageReuseScope(const PageReuseScope &) = delete;
  PageReuseScope &operator=(const PageReuseScope &) = delete;
};

} // namespace hoct
