// Small helpers of the benchmark: wall-clock timing, medians, peak resident memory, and a scratch
// directory for the files a run reads and writes.
#pragma once

#include "tree/tree_result.hpp"
#include "util/stopwatch.hpp"

#include <string>
#include <vector>

namespace hoct::bench {

using clock_type = Stopwatch::clock;

inline double seconds_since(clock_type::time_point t0) {
  return seconds_between(t0, clock_type::now());
}

double median(std::vector<double> v);

// Peak resident memory of this process (VmHWM, KiB).
long peak_rss_kib();

// Runs a program (argv[0] is its path) under GNU time with stderr discarded; returns
// its peak resident memory (KiB) and wall time; throws if it cannot run or fails.
struct ProcessPeak {
  long max_rss_kib = 0;
  double seconds = 0;
};
// `stdout_file`, `stderr_file`: where its standard output and error go (else /dev/null).
ProcessPeak run_process(const std::vector<std::string> &argv, const std::string &stdout_file = "",
                        const std::string &stderr_file = "");

// The directory of the running executable (to find the hoct CLI next to hoct_bench).
std::string executable_dir();

// A fresh scratch directory (removed by the destructor).
class ScratchDir {
public:
  ScratchDir();
  ~ScratchDir();
  ScratchDir(const ScratchDir &) = delete;
  ScratchDir &operator=(const ScratchDir &) = delete;
  std::string file(const std::string &name) const { return path_ + "/" + name; }

private:
  std::string path_;
};

} // namespace hoct::bench
