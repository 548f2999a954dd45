// The bytes of a whole input file in one writable buffer, read without a detour: one read() loop
// into an anonymous mapping that the kernel populates in one go (first-touch page faults of a
// fresh buffer cost more here than copying the file), or adopted from a string (input held in
// memory). Not a file mapping: a file truncated by another process while hoct reads it yields
// short or malformed data and a clear error, never a SIGBUS.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace hoct {

// What `path` is if it exists and is neither a regular file nor a directory ("is a FIFO (a named
// pipe) ...", "is a character device, not a mesh file", ...), else empty. Never opens it.
std::string special_file(const std::string &path);

class FileBytes {
public:
  FileBytes() = default;
  explicit FileBytes(std::string bytes);
  FileBytes(FileBytes &&other) noexcept;
  FileBytes &operator=(FileBytes &&other) noexcept;
  FileBytes(const FileBytes &) = delete;
  FileBytes &operator=(const FileBytes &) = delete;
  ~FileBytes();

  // Reads the file at `path`. On failure returns false and sets `error` to what went wrong
  // ("is a directory", "is a FIFO ...", "is a character device ...", "cannot open (reason)",
  // "cannot read (reason)"), for the caller's message. Only regular files are read.
  bool read(const std::string &path, std::string &error);

  char *data() { return data_; }
  const char *data() const { return data_; }
  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  std::string_view view() const { return {data_, size_}; }

private:
  void release();

  std::string owned_;   // adopted bytes
  char *map_ = nullptr; // or an anonymous mapping of map_length_ bytes
  std::size_t map_length_ = 0;
  char *data_ = nullptr;
  std::size_t size_ = 0;
};

} // namespace hoct
