#include "util/page_pool.hpp"

#include <sys/mman.h>
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <mutex>
#include <new>
#include <vector>

namespace hoct {
namespace {

// Each block starts with a header (its size in bytes, header included); the caller's memory
// starts kHeader bytes in.
constexpr std::size_t kHeader = 64;
constexpr std::size_t kMaxKept = 64;
constexpr std::size_t kKeptBetweenScopes = std::size_t{64} << 20;

struct Block {
  char *base;
  std::size_t bytes;
};

struct Pool {
  std::mutex mutex;
  std::vector<Block> kept;
  int scopes = 0;
  std::size_t kept_bytes = 0;
};

Pool &pool() {
  static Pool *p = new Pool; // never destroyed: blocks may be freed during static destruction
  return *p;
}

std::size_t page_size() {
  static const std::size_t size = static_cast<std::size_t>(sysconf(_SC_PAGESIZE));
  return size;
}

std::size_t round_to_pages(std::size_t bytes) {
  const std::size_t page = page_size();
  return (bytes + page - 1) / page * page;
}

void *hand_out(char *base, std::size_t bytes) {
  *reinterpret_cast<std::size_t *>(base) = bytes;
  return base + kHeader;
}

void unmap(const Block &b) { munmap(b.base, b.bytes); }

// Asks for transparent huge pages on a new block of at least one huge page (the kernel aligns
// such anonymous mappings to them): a first touch then maps 2 MiB at once instead of 4 KiB, and
// on a virtual machine each fault costs far more than clearing its page. Where transparent huge
// pages are off ("never"), or the kernel has none free, the block keeps small pages; the
// contents are the same either way (zeroed on first touch).
void ask_huge_pages(void *base, std::size_t bytes) {
#ifdef MADV_HUGEPAGE
  constexpr std::size_t kHugePage = std::size_t{2} << 20;
  if (bytes >= kHugePage)
    madvise(base, bytes, MADV_HUGEPAGE);
#else
  (void)base;
  (void)bytes;
#endif
}

// Takes a kept block of `bytes` (under the lock): the smallest that fits (what it has beyond
// `bytes`, if a pooled size, stays kept), else the largest, grown. A null base when nothing is
// kept or growing fails.
Block take_kept(Pool &p, std::size_t bytes) {
  if (p.kept.empty())
    return {nullptr, 0};
  std::size_t fit = p.kept.size(), largest = 0;
  for (std::size_t i = 0; i < p.kept.size(); ++i) {
    if (p.kept[i].bytes >= bytes && (fit == p.kept.size() || p.kept[i].bytes < p.kept[fit].bytes))
      fit = i;
    if (p.kept[i].bytes > p.kept[largest].bytes)
      largest = i;
  }
  if (fit < p.kept.size()) {
    Block b = p.kept[fit];
    p.kept_bytes -= b.bytes;
    if (b.bytes - bytes >= kPooledBytes) {
      p.kept[fit] = {b.base + bytes, b.bytes - bytes};
      p.kept_bytes += b.bytes - bytes;
    } else {
      p.kept.erase(p.kept.begin() + static_cast<std::ptrdiff_t>(fit));
      bytes = b.bytes;
    }
    return {b.base, bytes};
  }
  const Block b = p.kept[largest];
  void *grown = mremap(b.base, b.bytes, bytes, MREMAP_MAYMOVE);
  if (grown == MAP_FAILED)
    return {nullptr, 0};
  p.kept.erase(p.kept.begin() + static_cast<std::ptrdiff_t>(largest));
  p.kept_bytes -= b.bytes;
  return {static_cast<char *>(grown), bytes};
}

} // namespace

void *allocate_pages(std::size_t bytes) {
  if (bytes > SIZE_MAX / 2)
    throw std::bad_alloc();
  const std::size_t total = round_to_pages(bytes + kHeader);
  Pool &p = pool();
  Block kept;
  {
    std::lock_guard<std::mutex> lock(p.mutex);
    kept = take_kept(p, total);
  }
  if (kept.base != nullptr)
    return hand_out(kept.base, kept.bytes);
  void *m = mmap(nullptr, total, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (m == MAP_FAILED)
    throw std::bad_alloc();
  ask_huge_pages(m, total);
  return hand_out(static_cast<char *>(m), total);
}

void free_pages(void *ptr, std::size_t) noexcept {
  if (ptr == nullptr)
    return;
  char *base = static_cast<char *>(ptr) - kHeader;
  const Block b{base, *reinterpret_cast<std::size_t *>(base)};
  Pool &p = pool();
  std::lock_guard<std::mutex> lock(p.mutex);
  // Outside scopes as much stays as between them (the C library, which these blocks bypass,
  // keeps up to 64 MiB of freed heap too: a loop of small trees would otherwise fault its pages in
  // again every time).
  if (p.scopes == 0 && p.kept_bytes + b.bytes > kKeptBetweenScopes) {
    unmap(b);
    return;
  }
  p.kept.push_back(b);
  p.kept_bytes += b.bytes;
  if (p.kept.size() > kMaxKept) {
    const auto smallest = std::min_element(p.kept.begin(), p.kept.end(),
                                           [](auto &x, auto &y) { return x.bytes < y.bytes; });
    p.kept_bytes -= smallest->bytes;
    unmap(*smallest);
    p.kept.erase(smallest);
  }
}

void populate_for_write(void *p, std::size_t bytes) noexcept {
#ifdef MADV_POPULATE_WRITE
  const std::size_t page = page_size();
  const auto begin = (reinterpret_cast<std::uintptr_t>(p) + page - 1) / page * page;
  const auto end = (reinterpret_cast<std::uintptr_t>(p) + bytes) / page * page;
  if (end > begin)
    madvise(reinterpret_cast<void *>(begin), end - begin, MADV_POPULATE_WRITE);
#else
  (void)p;
  (void)bytes;
#endif
}

std::size_t kept_page_bytes() {
  Pool &p = pool();
  std::lock_guard<std::mutex> lock(p.mutex);
  return p.kept_bytes;
}

PageReuseScope::PageReuseScope() {
  Pool &p = pool();
  std::lock_guard<std::mutex> lock(p.mutex);
  ++p.scopes;
}

PageReuseScope::~PageReuseScope() {
  Pool &p = pool();
  std::lock_guard<std::mutex> lock(p.mutex);
  if (--p.scopes > 0)
    return;
  // The largest blocks that fit in kKeptBetweenScopes stay for the next computation (a loop of
  // trees on small meshes would otherwise fault its pages in again every time); the rest go.
  std::sort(p.kept.begin(), p.kept.end(),
            [](const Block &x, const Block &y) { return x.bytes > y.bytes; });
  std::vector<Block> stay;
  std::size_t stay_bytes = 0;
  for (const Block &b : p.kept)
    if (stay_bytes + b.bytes <= kKeptBetweenScopes) {
      stay.push_back(b);
      stay_bytes += b.bytes;
    } else {
      unmap(b);
    }
  p.kept.swap(stay);
  p.kept_bytes = stay_bytes;
}

} // namespace hoct
