// The page pool (util/page_pool.hpp): blocks handed out never overlap a live block, kept blocks
// are reused (split when larger, grown when smaller) only while a scope is open, and at most
// 64 MiB stays kept after the last scope closes.
#include "mesh/mesh_input.hpp"
#include "util/page_pool.hpp"
#include "util/uninitialized_vector.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <random>
#include <thread>
#include <vector>

namespace hoct {
namespace {

constexpr std::size_t kMiB = std::size_t{1} << 20;

struct Live {
  unsigned char *p;
  std::size_t bytes;
  unsigned char tag;
};

// Every byte of every live block still holds its block's tag.
bool intact(const std::vector<Live> &live) {
  for (const Live &b : live)
    for (std::size_t i = 0; i < b.bytes; i += 509)
      if (b.p[i] != b.tag || b.p[b.bytes - 1] != b.tag)
        return false;
  return true;
}

void churn(unsigned seed, int rounds, bool *ok) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<std::size_t> size(kMiB, 9 * kMiB + 12345);
  std::vector<Live> live;
  unsigned char tag = static_cast<unsigned char>(seed * 37);
  for (int r = 0; r < rounds; ++r) {
    if (live.size() < 6 && (live.empty() || rng() % 3 != 0)) {
      const std::size_t bytes = size(rng);
      auto *p = static_cast<unsigned char *>(allocate_pages(bytes));
      ASSERT_EQ(reinterpret_cast<std::uintptr_t>(p) % 64, 0u);
      ++tag;
      std::memset(p, tag, bytes);
      live.push_back({p, bytes, tag});
    } else {
      const std::size_t k = rng() % live.size();
      free_pages(live[k].p, live[k].bytes);
      live.erase(live.begin() + static_cast<std::ptrdiff_t>(k));
    }
    if (!intact(live)) {
      *ok = false;
      return;
    }
  }
  for (const Live &b : live)
    free_pages(b.p, b.bytes);
  *ok = true;
}

TEST(PagePool, LiveBlocksNeverOverlapOnTwoThreads) {
  const PageReuseScope scope;
  bool ok0 = false, ok1 = false;
  std::thread a(churn, 1u, 400, &ok0), b(churn, 2u, 400, &ok1);
  a.join();
  b.join();
  EXPECT_TRUE(ok0);
  EXPECT_TRUE(ok1);
}

TEST(PagePool, ReusesSplitsAndGrowsKeptBlocksInsideAScope) {
  {
    const PageReuseScope scope;
    void *a = allocate_pages(8 * kMiB);
    const std::size_t in_use = kept_page_bytes();
    free_pages(a, 8 * kMiB);
    const std::size_t kept = kept_page_bytes();
    EXPECT_GE(kept, in_use + 8 * kMiB);
    // A smaller request takes the front of a kept block; the rest of it stays kept.
    void *b = allocate_pages(3 * kMiB);
    EXPECT_LT(kept_page_bytes(), kept);
    EXPECT_GE(kept_page_bytes(), kept - 5 * kMiB);
    // A larger one than anything kept grows a kept block: nothing is left kept afterwards when
    // that block was the only one.
    free_pages(b, 3 * kMiB);
    void *c = allocate_pages(kept + 16 * kMiB);
    EXPECT_LT(kept_page_bytes(), kept);
    std::memset(c, 7, kept + 16 * kMiB);
    free_pages(c, kept + 16 * kMiB);
  }
  // At most 64 MiB stays after the scope.
  EXPECT_LE(kept_page_bytes(), 64 * kMiB);
  {
    const PageReuseScope scope;
    std::vector<void *> blocks;
    for (int i = 0; i < 12; ++i)
      blocks.push_back(allocate_pages(10 * kMiB));
    for (void *p : blocks)
      free_pages(p, 10 * kMiB);
    EXPECT_GE(kept_page_bytes(), 120 * kMiB);
  }
  EXPECT_LE(kept_page_bytes(), 64 * kMiB);
}

TEST(PagePool, AtMost64MiBIsKeptOutsideAScope) {
  // Larger than the 64 MiB kept outside scopes: given back, not kept.
  const std::size_t before = kept_page_bytes();
  void *a = allocate_pages(80 * kMiB);
  free_pages(a, 80 * kMiB);
  EXPECT_LE(kept_page_bytes(), before);
  EXPECT_LE(kept_page_bytes(), 64 * kMiB);
  // Small blocks are kept (for the next computation) up to the 64 MiB.
  std::vector<void *> blocks;
  for (int i = 0; i < 20; ++i)
    blocks.push_back(allocate_pages(5 * kMiB));
  for (void *p : blocks)
    free_pages(p, 5 * kMiB);
  EXPECT_GE(kept_page_bytes(), 55 * kMiB);
  EXPECT_LE(kept_page_bytes(), 64 * kMiB);
}

TEST(PagePool, UninitializedVectorsGrowThroughThePool) {
  const PageReuseScope scope;
  UninitializedVector<int64_t> v;
  for (int64_t i = 0; i < 3'000'000; ++i) // 24 MB: several pooled reallocations
    v.push_back(i * 3);
  for (int64_t i = 0; i < 3'000'000; i += 997)
    ASSERT_EQ(v[static_cast<std::size_t>(i)], i * 3);
  UninitializedVector<int64_t> copy = v;
  v.clear();
  v.shrink_to_fit();
  EXPECT_EQ(copy[2'999'999], 2'999'999 * 3);
}

TEST(PagePool, PooledVectorsAreValueInitialisedOnReusedPages) {
  // A kept block holds what its last user wrote; a PooledVector taking it must still zero its
  // elements (an UninitializedVector would not).
  const PageReuseScope scope;
  for (int round = 0; round < 3; ++round) {
    {
      UninitializedVector<double> dirty;
      dirty.resize(1'000'000);
      std::fill(dirty.begin(), dirty.end(), -7.5);
    }
    const PooledVector<double> clean(1'000'000);
    for (std::size_t i = 0; i < clean.size(); i += 331)
      ASSERT_EQ(clean[i], 0.0) << i;
  }
}

TEST(PagePool, MeshInputArraysComeFromThePool) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "under AddressSanitizer large buffers come from the heap";
#else
  // The arrays of an input the mesh build consumes are kept for what is allocated after them.
  const PageReuseScope scope;
  MeshInput in;
  in.points.resize(200'000);
  in.values.resize(200'000);
  in.cell_nodes.resize(300'000);
  const std::size_t before = kept_page_bytes();
  const std::size_t bytes = 200'000 * (sizeof(Vec3) + sizeof(double)) + 300'000 * sizeof(int64_t);
  in = MeshInput{};
  EXPECT_GE(kept_page_bytes(), before + bytes);
#endif
}

} // namespace
} // namespace hoct
