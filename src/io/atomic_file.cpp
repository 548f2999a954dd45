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

} // namespace

void install_interrupt_cleanup() {
  struct sigaction sa {};
  sa.sa_handler = remove_temporaries_and_exit;
  sigemptyset(&sa.sa_mask);
  sigaddset(&sa.sa_mask, SIGINT);
  sigaddset(&sa.sa_mask, SIGTERM);
  sigaddset(&sa.sa_mask, SIGHUP);
  for (int sig : {SIGINT, SIGTERM, SIGHUP})
    sigaction(sig, &sa, nullptr);
}

void write_file_atomic(const std::string &path, const std::function<void(std::ostream &)> &write,
                       bool binary) {
  namespace fs = std::filesystem;
  const fs::path target(path);
  if (target.filename().empty())
    throw Error(path + ": not a file name");
  std::random_device rd;
  // Built with append: GCC 12 warns falsely (-Wrestrict) on "." + std::string.
  std::string name(1, '.');
  name.append(target.filename().string());
  name.append(".tmp-");
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
