// The process's worker threads, started on first use and kept for the next parallel loop:
// starting a thread is not cheap, and a fresh thread's per-thread buffers (root isolation, box
// search, path fields) start cold, which on small meshes would eat most of what a second thread
// gains.
#pragma once

#include <functional>

namespace hoct {

// Calls work(t) for t = 0 .. threads - 1, work(0) on the calling thread and the others on pool
// workers, and returns when all have returned (rethrowing the first exception). Called from
// inside a pool worker (a nested loop), from a second thread while the pool runs another loop,
// or in a child process after fork(), the calls run one after another on the calling thread:
// the bodies must not depend on running concurrently (parallel_chunks' bodies take every chunk
// that remains in any share, so work(0) alone completes the loop).
void run_on_workers(int threads, const std::function<void(int)> &work);

} // namespace hoct
