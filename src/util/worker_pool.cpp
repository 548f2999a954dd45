#include "util/worker_pool.hpp"

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <exception>
#include <mutex>
#include <thread>
#include <unistd.h>
#include <vector>

namespace hoct {
namespace {

thread_local bool in_worker = false;

// How long a thread waits actively (for the next loop, or for the other threads to finish this
// one) before it sleeps: waking a sleeping worker costs about as much as a second thread gains
// on a loop over 10^4 cells, and the tree runs several loops back to back.
constexpr std::chrono::microseconds kSpin{200};

void cpu_relax() {
#if defined(__x86_64__) || defined(__i386__)
  __builtin_ia32_pause();
#else
  std::this_thread::yield();
#endif
}

// Spins until ready() or kSpin has passed; returns ready().
template <class Ready> bool spin_for(const Ready &ready) {
  const auto until = std::chrono::steady_clock::now() + kSpin;
  for (int i = 0;; ++i) {
    if (ready())
      return true;
    if (i % 64 == 63 && std::chrono::steady_clock::now() >= until)
      return ready();
    cpu_relax();
  }
}

class WorkerPool {
public:
  WorkerPool() : owner_(getpid()) {}

  void run(int threads, const std::function<void(int)> &work) {
    std::unique_lock<std::mutex> busy(busy_, std::try_to_lock);
    if (threads <= 1 || in_worker || !busy.owns_lock() || getpid() != owner_) {
      for (int t = 0; t < threads; ++t)
        work(t);
      return;
    }
    std::exception_ptr first;
    {
      std::lock_guard<std::mutex> lock(m_);
      while (static_cast<int>(workers_.size()) < threads - 1) {
        const int index = static_cast<int>(workers_.size()) + 1;
        workers_.emplace_back([this, index] { loop(index); });
      }
      job_ = &work;
      job_threads_ = threads;
      pending_ = threads - 1;
      errors_.assign(static_cast<std::size_t>(threads), nullptr);
      ++generation_;
    }
    wake_.notify_all();
    try {
      work(0);
    } catch (...) {
      first = std::current_exception();
    }
    spin_for([&] { return pending_.load(std::memory_order_acquire) == 0; });
    std::unique_lock<std::mutex> lock(m_);
    done_.wait(lock, [&] { return pending_ == 0; });
    job_ = nullptr;
    for (const auto &e : errors_)
      if (!first && e)
        first = e;
    lock.unlock();
    if (first)
      std::rethrow_exception(first);
  }

private:
  void loop(int index) {
    in_worker = true;
    uint64_t seen = 0;
    for (;;) {
      spin_for([&] { return generation_.load(std::memory_order_acquire) != seen; });
      std::unique_lock<std::mutex> lock(m_);
      wake_.wait(lock, [&] { return generation_ != seen; });
      seen = generation_;
      if (index >= job_threads_)
        continue;
      const std::function<void(int)> *job = job_;
      lock.unlock();
      std::exception_ptr error;
      try {
        (*job)(index);
      } catch (...) {
        error = std::current_exception();
      }
      lock.lock();
      errors_[static_cast<std::size_t>(index)] = error;
      if (--pending_ == 0)
        done_.notify_one();
    }
  }

  const pid_t owner_; // after fork() the workers do not exist in the child
  std::mutex busy_;   // one loop at a time
  std::mutex m_;
  std::condition_variable wake_, done_;
  std::vector<std::thread> workers_;
  const std::function<void(int)> *job_ = nullptr;
  int job_threads_ = 0;
  // Changed under m_; read without it while spinning.
  std::atomic<int> pending_{0};
  std::atomic<uint64_t> generation_{0};
  std::vector<std::exception_ptr> errors_;
};

} // namespace

void run_on_workers(int threads, const std::function<void(int)> &work) {
  // Never destroyed: the workers wait for work until the process ends (joining them from a
  // static destructor could run after other statics they use are gone).
  static WorkerPool *pool = new WorkerPool;
  pool->run(threads, work);
}

} // namespace hoct
