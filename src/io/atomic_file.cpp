#include "io/atomic_file.hpp"

#include "error.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <unistd.h>

namespace hoct {

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
