#include "io/file_bytes.hpp"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

namespace hoct {

FileBytes::FileBytes(std::string bytes) : owned_(std::move(bytes)) {
  data_ = owned_.data();
  size_ = owned_.size();
}

FileBytes::FileBytes(FileBytes &&o) noexcept { *this = std::move(o); }

FileBytes &FileBytes::operator=(FileBytes &&o) noexcept {
  if (this == &o)
    return *this;
  release();
  const bool adopted = o.map_ == nullptr;
  owned_ = std::move(o.owned_);
  map_ = o.map_;
  map_length_ = o.map_length_;
  size_ = o.size_;
  data_ = adopted ? owned_.data() : map_;
  o.map_ = nullptr;
  o.map_length_ = 0;
  o.owned_.clear();
  o.data_ = o.owned_.data();
  o.size_ = 0;
  return *this;
}

FileBytes::~FileBytes() { release(); }

void FileBytes::release() {
  if (map_ != nullptr)
    munmap(map_, map_length_);
  map_ = nullptr;
  map_length_ = 0;
  owned_.clear();
  data_ = owned_.data();
  size_ = 0;
}

std::string special_file(const std::string &path) {
  // Named before anything opens it: opening a FIFO would wait for a writer; a device has no size
  // and would read as empty, or as endless zeros.
  struct stat kind {};
  if (::stat(path.c_str(), &kind) != 0 || S_ISREG(kind.st_mode) || S_ISDIR(kind.st_mode))
    return "";
  return S_ISFIFO(kind.st_mode)   ? "is a FIFO (a named pipe), not a file: write the mesh to a "
                                    "regular file first"
         : S_ISCHR(kind.st_mode)  ? "is a character device, not a mesh file"
         : S_ISBLK(kind.st_mode)  ? "is a block device, not a mesh file"
         : S_ISSOCK(kind.st_mode) ? "is a socket, not a mesh file"
                                  : "is not a regular file";
}

bool FileBytes::read(const std::string &path, std::string &error) {
  release();
  auto reason = [](const char *what) {
    return std::string(what) + " (" + std::strerror(errno) + ")";
  };
  error = special_file(path);
  if (!error.empty())
    return false;
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) {
    error = reason("cannot open");
    return false;
  }
  struct stat st {};
  if (::fstat(fd, &st) != 0) {
    error = reason("cannot read");
    ::close(fd);
    return false;
  }
  if (S_ISDIR(st.st_mode)) {
    error = "is a directory";
    ::close(fd);
    return false;
  }
  const std::size_t size = static_cast<std::size_t>(st.st_size);
  if (size > 0) {
    void *p = ::mmap(nullptr, size, PROT_READ | PROT_WRITE,
                     MAP_PRIVATE | MAP_ANONYMOUS | MAP_POPULATE, -1, 0);
    if (p != MAP_FAILED) {
      map_ = static_cast<char *>(p);
      map_length_ = size;
      data_ = map_;
    } else { // address space or overcommit limits: an ordinary allocation
      owned_.resize(size);
      data_ = owned_.data();
    }
  }
  std::size_t got = 0;
  while (got < size) {
    const ssize_t r = ::read(fd, data_ + got, size - got);
    if (r < 0 && errno == EINTR)
      continue;
    if (r <= 0) {
      error = r < 0 ? reason("cannot read")
                    : "cannot read: got " + std::to_string(got) + " of " + std::to_string(size) +
                          " bytes (the file shrank while it was read)";
      ::close(fd);
      release();
      return false;
    }
    got += static_cast<std::size_t>(r);
  }
  ::close(fd);
  size_ = size;
  return true;
}

} // namespace hoct
