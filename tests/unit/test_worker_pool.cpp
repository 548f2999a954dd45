// The kept worker threads behind parallel_for: every index runs once, loops nest and run from
// several threads without deadlock, exceptions reach the caller, and a forked child still works.
#include "util/parallel_for.hpp"
#include "util/worker_pool.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <numeric>
#include <stdexcept>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>
#include <vector>

namespace hoct {
namespace {

TEST(WorkerPool, RunsEveryIndexOnceAndReusesItsThreads) {
  for (int threads : {1, 2, 3, 5}) {
    std::vector<std::atomic<int>> calls(threads);
    std::vector<std::thread::id> ids(threads);
    run_on_workers(threads, [&](int t) {
      ++calls[t];
      ids[t] = std::this_thread::get_id();
    });
    for (int t = 0; t < threads; ++t)
      EXPECT_EQ(calls[t].load(), 1) << threads << " threads, index " << t;
    EXPECT_EQ(ids[0], std::this_thread::get_id()); // index 0 runs on the caller
    // The same workers serve the next loop.
    std::vector<std::thread::id> again(threads);
    run_on_workers(threads, [&](int t) { again[t] = std::this_thread::get_id(); });
    EXPECT_EQ(again, ids);
  }
}

TEST(WorkerPool, ParallelForCoversTheRangeWithNestedLoops) {
  const int64_t n = 10000;
  std::vector<int> hits(n, 0);
  parallel_for(100, 2, [&](int64_t b, int64_t e, int) {
    for (int64_t i = b; i < e; ++i)
      parallel_for(100, 2, [&](int64_t b2, int64_t e2, int) { // nested: runs on this thread
        for (int64_t j = b2; j < e2; ++j)
          ++hits[i * 100 + j];
      });
  });
  EXPECT_EQ(std::accumulate(hits.begin(), hits.end(), 0), n);
  EXPECT_EQ(*std::min_element(hits.begin(), hits.end()), 1);
}

TEST(WorkerPool, ParallelChunksRunsEveryChunkOnceFromEachThreadsShare) {
  for (int threads : {2, 3, 5}) {
    for (int64_t chunks : {1, 2, 7, 32, 100}) {
      const int64_t n = 1000;
      // With many chunks, thread 0 stalls 50 ms on the first chunk it runs: the others, done with
      // their own shares, take over the rest of its share. (Which thread runs which chunk is
      // otherwise up to the scheduler: threads may start late, and on fewer cores than threads, in
      // any order.)
      const bool stall = chunks >= 32;
      std::vector<std::atomic<int>> calls(static_cast<std::size_t>(chunks));
      std::vector<std::atomic<int>> ran_by(static_cast<std::size_t>(chunks));
      bool stalled = false;    // thread 0's
      int64_t first_of_1 = -1; // the first chunk thread 1 ran
      parallel_chunks(n, chunks, threads, [&](int64_t c, int64_t b, int64_t e, int t) {
        EXPECT_EQ(b, n * c / chunks);
        EXPECT_EQ(e, n * (c + 1) / chunks);
        ran_by[c] = t;
        ++calls[c];
        if (t == 1 && first_of_1 < 0)
          first_of_1 = c;
        if (stall && t == 0 && !stalled) {
          stalled = true;
          std::this_thread::sleep_for(std::chrono::milliseconds(50));
        }
      });
      for (int64_t c = 0; c < chunks; ++c)
        EXPECT_EQ(calls[c].load(), 1) << threads << " threads, chunk " << c;
      if (stall && threads == 2) {
        // Thread 1 started on the first chunk of its own share (thread 0, stalled on its first
        // chunk, cannot have reached it), and took the last of thread 0's share too.
        EXPECT_EQ(first_of_1, chunks / 2);
        EXPECT_EQ(ran_by[chunks / 2 - 1].load(), 1);
      }
    }
  }
}

TEST(WorkerPool, ConcurrentCallersBothComplete) {
  std::atomic<int64_t> sum{0};
  auto job = [&] {
    for (int k = 0; k < 50; ++k)
      parallel_for(1000, 2, [&](int64_t b, int64_t e, int) {
        for (int64_t i = b; i < e; ++i)
          sum += i;
      });
  };
  std::thread a(job), b(job);
  a.join();
  b.join();
  EXPECT_EQ(sum.load(), 2 * 50 * (999 * 1000 / 2));
}

TEST(WorkerPool, ExceptionsReachTheCaller) {
  EXPECT_THROW(run_on_workers(2,
                              [](int t) {
                                if (t == 1)
                                  throw std::runtime_error("worker");
                              }),
               std::runtime_error);
  EXPECT_THROW(parallel_for(64, 2,
                            [](int64_t b, int64_t, int) {
                              if (b > 0)
                                throw std::invalid_argument("chunk");
                            }),
               std::invalid_argument);
  // The pool still works afterwards.
  std::atomic<int> calls{0};
  run_on_workers(2, [&](int) { ++calls; });
  EXPECT_EQ(calls.load(), 2);
}

TEST(WorkerPool, AForkedChildRunsItsLoops) {
  run_on_workers(2, [](int) {}); // workers exist in the parent
  const pid_t pid = fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    alarm(20); // a child waiting for workers it does not have fails instead of hanging
    std::atomic<int> calls{0};
    run_on_workers(2, [&](int) { ++calls; });
    int64_t sum = 0;
    parallel_for(1000, 2, [&](int64_t b, int64_t e, int) {
      for (int64_t i = b; i < e; ++i)
        sum += i;
    });
    _exit(calls.load() == 2 && sum == 999 * 1000 / 2 ? 0 : 1);
  }
  int status = 0;
  ASSERT_EQ(waitpid(pid, &status, 0), pid);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0);
}

} // namespace
} // namespace hoct
