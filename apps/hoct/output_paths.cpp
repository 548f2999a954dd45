#include "output_paths.hpp"

#include "util/error.hpp"

#include <filesystem>
#include <system_error>

namespace hoct::cli {
namespace {

namespace fs = std::filesystem;

bool same_file(const std::string &a, const std::string &b) {
  std::error_code ea, eb;
  // Two outputs to /dev/null (or any character device) do not overwrite each other.
  if (fs::is_character_file(a, ea) && fs::is_character_file(b, eb))
    return false;
  const bool a_exists = fs::exists(a, ea), b_exists = fs::exists(b, eb);
  if (a_exists && b_exists) {
    std::error_code e;
    return fs::equivalent(a, b, e);
  }
  if (a_exists != b_exists)
    return false;
  std::error_code e1, e2;
  const fs::path pa = fs::weakly_canonical(fs::absolute(a, e1), e1),
                 pb = fs::weakly_canonical(fs::absolute(b, e2), e2);
  return !e1 && !e2 ? pa == pb : fs::path(a).lexically_normal() == fs::path(b).lexically_normal();
}

} // namespace

void require_distinct_outputs(const std::vector<std::pair<std::string, std::string>> &inputs,
                              const std::vector<std::pair<std::string, std::string>> &outputs) {
  for (std::size_t i = 0; i < outputs.size(); ++i) {
    const auto &[option, path] = outputs[i];
    if (path.empty())
      continue;
    for (const auto &[in_option, in_path] : inputs)
      if (!in_path.empty() && same_file(path, in_path))
        throw Error(option + " " + path + " is " + in_option + " " + in_path +
                    ": writing it would destroy the input (choose another output)");
    for (std::size_t j = 0; j < i; ++j)
      if (!outputs[j].second.empty() && same_file(path, outputs[j].second))
        throw Error(outputs[j].first + " " + outputs[j].second + " and " + option + " " + path +
                    " are the same file: one output would overwrite the other");
  }
}

void require_extension(const std::string &option, const std::string &path,
                       const std::string &extension, const std::string &format) {
  const std::string got = fs::path(path).extension().string();
  if (got != extension)
    throw Error(option + " " + path + ": only " + format + " (" + extension +
                ") is written here, but the name says " +
                (got.empty() ? std::string("no format") : "'" + got + "'") + "; name it *" +
                extension);
}

} // namespace hoct::cli
