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

#include <fcntl.h>
#include <sys/stat.h>
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

// The file an output path names: symbolic links followed to their final target (which may not
// exist yet: a dangling link is written through to the file it names), so that the link stays a
// link and its target gets the new content.
std::filesystem::path final_target(const std::string &path) {
  namespace fs = std::filesystem;
  fs::path at(path);
  for (int hops = 0; hops < 40; ++hops) {
    std::error_code ec;
    if (!fs::is_symlink(fs::symlink_status(at, ec)) || ec)
      return at;
    const fs::path next = fs::read_symlink(at, ec);
    if (ec)
      throw Error(path + ": cannot read the symbolic link: " + ec.message());
    at = next.is_absolute() ? next : at.parent_path() / next;
  }
  throw Error(path + ": too many levels of symbolic links");
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
  const fs::path target = final_target(path);
  if (target.filename().empty())
    throw Error(path + ": not a file name");
  const auto mode = binary ? std::ios::binary | std::ios::out : std::ios::out;
  struct stat old {};
  const bool exists = ::stat(target.c_str(), &old) == 0;
  if (exists && S_ISDIR(old.st_mode))
    throw Error(path + ": is a directory");
  if (exists && !S_ISREG(old.st_mode)) {
    // A device or a FIFO (/dev/null, /dev/full, a named pipe): written through, never replaced.
    std::ofstream out(target, mode);
    if (!out)
      throw Error(path + ": cannot open for writing: " + std::strerror(errno));
    write(out);
    out.flush();
    if (!out)
      throw Error(path + ": write failed: " + std::strerror(errno));
    out.close();
    if (!out)
      throw Error(path + ": closing failed: " + std::strerror(errno));
    return;
  }
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
    // Created exclusively; private while it is written when it replaces a file (which may be
    // private), else with the usual mode (0666 less the umask).
    const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC,
                          exists ? S_IRUSR | S_IWUSR : 0666);
    if (fd < 0)
      throw Error(path + ": cannot open for writing: " + std::strerror(errno));
    ::close(fd);
    {
      std::ofstream out(tmp, mode | std::ios::trunc);
      if (!out)
        throw Error(path + ": cannot open for writing: " + std::strerror(errno));
      write(out);
      out.flush();
      if (!out)
        throw Error(path + ": write failed (disk full or I/O error)");
    }
    if (exists) {
      // The replaced file's permissions and owner (the owner where this process may set it:
      // root, or the owner itself; else the group alone if it may, else this process's).
      if (::chown(tmp.c_str(), old.st_uid, old.st_gid) != 0 &&
          ::chown(tmp.c_str(), static_cast<uid_t>(-1), old.st_gid) != 0) {
        // Not ours to give away: the new file is this process's, as any rewrite would be.
      }
      if (::chmod(tmp.c_str(), old.st_mode & 07777) != 0)
        throw Error(path + ": cannot keep the file's permissions: " + std::strerror(errno));
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
