#include "tree_input.hpp"

#include "util/error.hpp"

#include <cstdio>

namespace hoct::cli {
namespace {

// 1234567 -> "1,234,567".
std::string grouped(int64_t n) {
  std::string digits = std::to_string(n < 0 ? -n : n), out;
  for (std::size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0)
      out += ',';
    out += digits[i];
  }
  return n < 0 ? "-" + out : out;
}

std::string describe(const InputFingerprint &f) {
  return grouped(f.points) + " points and " + grouped(f.cells) + " cells, field '" + f.field +
         "' (fingerprint " + f.hex() + ")";
}

} // namespace

void require_tree_of_mesh(const std::string &tree_path, const TreeResult &tree,
                          const std::string &mesh_path, const Mesh &mesh,
                          const std::string &options) {
  if (!tree.input) {
    std::fprintf(stderr,
                 "hoct: warning: %s records no input fingerprint (written by an earlier hoct): "
                 "cannot check that it is the tree of %s\n",
                 tree_path.c_str(), mesh_path.c_str());
    return;
  }
  if (!mesh.fingerprint || tree.input->same_data(*mesh.fingerprint))
    return;
  const InputFingerprint &m = *mesh.fingerprint;
  const bool same_sizes = tree.input->points == m.points && tree.input->cells == m.cells;
  throw Error(
      tree_path + " is the tree of a mesh with " + describe(*tree.input) + ", but " + mesh_path +
      " has " + describe(m) +
      (same_sizes ? " (the same sizes, but other coordinates, connectivity or values)" : "") +
      ": compute its tree with hoct tree " + mesh_path + " --json ... (or give the input " +
      "and the " + options + " the tree was computed with)");
}

} // namespace hoct::cli
