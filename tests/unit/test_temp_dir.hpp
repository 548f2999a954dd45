// A directory of its own for a test's files, removed with everything in it at the end.
#pragma once

#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

namespace hoct::testing {

class TempDir {
public:
  // /tmp/<prefix>-<pid>, with the subdirectories `subdirs` (e.g. "sub").
  explicit TempDir(const std::string &prefix, const std::string &subdir = {})
      : path_(std::filesystem::temp_directory_path() /
              (prefix + "-" + std::to_string(::getpid()))) {
    std::filesystem::create_directories(subdir.empty() ? path_ : path_ / subdir);
  }
  ~TempDir() { std::filesystem::remove_all(path_); }
  TempDir(const TempDir &) = delete;
  TempDir &operator=(const TempDir &) = delete;
  std::string file(const std::string &name) const { return (path_ / name).string(); }
  std::string write(const std::string &name, const std::string &content) const {
    std::ofstream(file(name), std::ios::binary) << content;
    return file(name);
  }

private:
  std::filesystem::path path_;
};

} // namespace hoct::testing
