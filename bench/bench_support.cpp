#include "bench_support.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

extern char **environ;

namespace hoct::bench {

double median(std::vector<double> v) {
  if (v.empty())
    return 0;
  std::sort(v.begin(), v.end());
  return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

namespace {
long status_field_kib(const char *key) {
  std::ifstream f("/proc/self/status");
  std::string line;
  const std::string k = key;
  while (std::getline(f, line))
    if (line.rfind(k, 0) == 0)
      return std::stol(line.substr(k.size()));
  return -1;
}
} // namespace

long peak_rss_kib() { return status_field_kib("VmHWM:"); }

ProcessPeak run_process(const std::vector<std::string> &argv, const std::string &stdout_file,
                        const std::string &stderr_file) {
  // Through GNU time (-f %M: the peak resident set of the program it runs): a child spawned
  // directly from this large process would inherit this process's peak at exec.
  char report[] = "/tmp/hoct-bench-peak-XXXXXX";
  const int fd = mkstemp(report);
  if (fd < 0)
    throw std::runtime_error("cannot create a temporary file");
  close(fd);
  std::vector<std::string> full = {"/usr/bin/time", "-f", "%M", "-o", report};
  full.insert(full.end(), argv.begin(), argv.end());
  std::vector<char *> args;
  for (const auto &a : full)
    args.push_back(const_cast<char *>(a.c_str()));
  args.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1,
                                   stdout_file.empty() ? "/dev/null" : stdout_file.c_str(),
                                   O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&actions, 2,
                                   stderr_file.empty() ? "/dev/null" : stderr_file.c_str(),
                                   O_WRONLY | O_CREAT | O_TRUNC, 0644);
  pid_t pid = 0;
  const auto t0 = clock_type::now();
  const int rc = posix_spawn(&pid, args[0], &actions, nullptr, args.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (rc != 0) {
    std::remove(report);
    throw std::runtime_error("cannot run /usr/bin/time (Debian package 'time')");
  }
  int status = 0;
  const bool ok = waitpid(pid, &status, 0) == pid && WIFEXITED(status) && WEXITSTATUS(status) == 0;
  ProcessPeak peak;
  peak.seconds = seconds_since(t0);
  std::ifstream in(report);
  in >> peak.max_rss_kib;
  std::remove(report);
  if (!ok || !in)
    throw std::runtime_error(argv[0] + " failed");
  return peak;
}

std::string executable_dir() {
  return std::filesystem::read_symlink("/proc/self/exe").parent_path().string();
}

ScratchDir::ScratchDir() {
  const char *base = std::getenv("TMPDIR");
  std::string tmpl = std::string(base && *base ? base : "/tmp") + "/hoct-bench-XXXXXX";
  if (!mkdtemp(tmpl.data()))
    throw std::runtime_error("cannot create a scratch directory under " + tmpl);
  path_ = tmpl;
}

ScratchDir::~ScratchDir() {
  std::error_code ec;
  std::filesystem::remove_all(path_, ec);
}

} // namespace hoct::bench
