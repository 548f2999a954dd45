// Checks on the files a command will write, made before anything is computed: outputs must not
// overwrite an input nor each other (by file identity where the files exist: device and inode,
// so a hard link, a symbolic link or another spelling of the same path counts; by the
// normalised path where they do not yet), and a file is written in the format its name says.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace hoct::cli {

// `inputs` as (description, path) pairs, e.g. {"the input", "f.vtu"}, `outputs` as (option,
// path) pairs, e.g. {"--json", "t.json"}; empty paths are ignored. Throws hoct::Error naming both
// options if an output is an input or another output.
void require_distinct_outputs(const std::vector<std::pair<std::string, std::string>> &inputs,
                              const std::vector<std::pair<std::string, std::string>> &outputs);

// Throws hoct::Error unless `path` ends with `extension` (".vtu"): the writer writes that format
// only, and a file named otherwise would hold something its name does not say.
void require_extension(const std::string &option, const std::string &path,
                       const std::string &extension, const std::string &format);

} // namespace hoct::cli
