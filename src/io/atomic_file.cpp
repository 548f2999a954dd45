#include "io/atomic_file.hpp"

#include "util/error.hpp"

#include <atomic>
#include <cerrno>
#include <climits>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <unistd.h>

namespace hoct {
namespace {

// The temporary files being written: a slot is claimed (state 1: being filled, 2: live) before
// the file is created and released after it is renamed or removed. The signal handler reads
// only live slots; it never allocates.
constexpr int kSlots = 32;
struct TempSlot {
  std::atomic<int> state{0};
  char path[PATH_MAX];
};
TempSlot g_slots[kSlots];
static_assert(std::atomic<int>::is_always_lock_free, "the signal handler reads the slots");

class TempRegistration {
public:
  explicit TempRegistration(const std::string &path) {
    if (path.size() >= PATH_MAX)
      return;
    for (int i = 0; i < kSlots; ++i) {
      int expected = 0;
      if (g_slots[i].state.compare_exchange_strong(expected, 1)) {
        std::memcpy(g_slots[i].path, path.c_str(), path.size() + 1);
        g_slots[i].state.store(2);
        slot_ = i;
        return;
      }
    }
  }
  ~TempRegistration() {
    if (slot_ >= 0)
      g_slots[slot_].state.store(0);
  }
  TempRegistration(const TempRegistration &) = delete;
  TempRegistration &operator=(const TempRegistration &) = delete;

private:
  int slot_ = -1;
};

extern "C" void remove_temporaries_and_exit(int sig) {
  for (auto &slot : g_slots)
    if (slot.state.load() == 2)
      ::unlink(slot.path);
  ::_exit(128 + sig);
}

// Temporary names: ".NAME.tmp-PID-N" beside the target, or ".hoct.tmp-PID-N" where that would
// pass the file system's name limit (a 250-byte output name must still work).
constexpr const char *kShortPrefix = ".hoct";
constexpr std::size_t kNameMax = 255;

std::string temporary_prefix(const std::string &filename) {
  std::string prefix(1, '.');
  prefix.append(filename);
  prefix.append(".tmp-");
  // Room for the pid and the random number (at most 7 + 1 + 6 characters).
  if (prefix.size() + 14 > kNameMax) {
    prefix.assign(kShortPrefix);
    prefix.append(".tmp-");
  }
  return prefix;
}

// Removes the temporary files of earlier writes of the same output (or short-named ones) whose
// process no longer exists: left by SIGKILL, a crash or a power cut. A live process's files,
// and anything not named like ours, stay.
void remove_stale_temporaries(const std::filesystem::path &dir, const std::string &prefix) {
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::directory_iterator it(dir.empty() ? fs::path(".") : dir, ec), end;
  for (; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (name.compare(0, prefix.size(), prefix) != 0)
      continue;
    // PID-N after the prefix, digits only.
    const std::string rest = name.substr(prefix.size());
    const std::size_t dash = rest.find('-');
    if (dash == 0 || dash == std::string::npos || dash + 1 == rest.size() ||
        rest.find_first_not_of("0123456789-") != std::string::npos ||
        rest.find('-', dash + 1) != std::string::npos || dash > 9)
      continue;
    const long pid = std::stol(rest.substr(0, dash));
    if (pid <= 0 || pid == ::getpid())
      continue;
    if (::kill(static_cast<pid_t>(pid), 0) == 0 || errno != ESRCH)
      continue; // alive (or not ours to judge)
    std::error_code ignored;
    fs::remove(it->path(), ignored);
  }
}

} // namespace

void install_interrupt_cleanup() {
  struct sigaction sa {};
  sa.sa_handler = remove_temporaries_and_exit;
  sigemptyset(&sa.sa_mask);
  sigaddset(&sa.sa_mask, SIGINT);
  sigaddset(&sa.sa_mask, SIGTERM);
  sigaddset(&sa.sa_mask, SIGHUP);
  sigaddset(&sa.sa_mask, SIGQUIT);
  for (int sig : {SIGINT, SIGTERM, SIGHUP, SIGQUIT})
    sigaction(sig, &sa, nullptr);
}

void write_file_atomic(const std::string &path, const std::function<void(std::ostream &)> &write,
                       bool binary) {
  namespace fs = std::filesystem;
  const fs::path target(path);
  if (target.filename().empty())
    throw Error(path + ": not a file name");
  std::random_device rd;
  const std::string prefix = temporary_prefix(target.filename().string());
  remove_stale_temporaries(target.parent_path(), prefix);
  std::string name = prefix;
  name.append(std::to_string(::getpid()));
  name.push_back('-');
  name.append(std::to_string(rd() % 1000000));
  const std::string tmp = (target.parent_path() / name).string();
  // Registered before the file exists, released after it is renamed or removed.
  const TempRegistration registration(tmp);
  try {
    {
      std::ofstream out(tmp, binary ? std::ios::binary | std::ios::trunc : std::ios::trunc);
      if (!out)
        throw Error(path + ": cannot open for writing: " + std::strerror(errno));
      write(out);
      out.flush();
      if (!out)
        throw Error(path + ": write failed (disk full or I/O error)");
    }
    std::error_code ec;
    fs::rename(tmp, target, ec);
    if (ec)
      throw Error(path + ": cannot rename temporary file into place: " + ec.message());
  } catch (...) {
    std::error_code ignored;
    fs::remove(tmp, ignored);
    throw;
  }
}

} // namespace hoct
