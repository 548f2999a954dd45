// `hoct render INPUT -o FIELD.png|.svg`: the field, exact isolines and critical points.
#include "commands.hpp"
#include "exact/exact_contour_tree.hpp"
#include "field_options.hpp"
#include "io/tree_json.hpp"
#include "load_mesh.hpp"
#include "output_paths.hpp"
#include "render/field_renderer.hpp"
#include "tree_input.hpp"
#include "util/error.hpp"

#include <cstdio>
#include <filesystem>
#include <memory>
#include <sstream>

namespace hoct::cli {
namespace {

struct RenderCmdOptions {
  std::string file, output, tree, view = "1,1,1", size = "1000x800", simplify;
  FieldOptions field;
  int isolines = 12;
  bool no_points = false;
};

void run_render(const RenderCmdOptions &o) {
  if (o.output.empty())
    throw Error("render: give an output picture with -o FIELD.png (or .svg)");
  require_distinct_outputs({{"the input", o.file}, {"the --tree input", o.tree}},
                           {{"-o", o.output}});
  const LoadedMesh lm = load_mesh(o.file, o.field.selection(), /*strict=*/true);
  RenderOptions ro;
  if (std::sscanf(o.size.c_str(), "%dx%d", &ro.width, &ro.height) != 2)
    throw Error("render: --size must look like 1000x800, got '" + o.size + "'");
  Vec3 v;
  char c1, c2;
  std::istringstream vs(o.view);
  if (!(vs >> v[0] >> c1 >> v[1] >> c2 >> v[2]) || c1 != ',' || c2 != ',' ||
      v[0] * v[0] + v[1] * v[1] + v[2] * v[2] == 0)
    throw Error("render: --view must be a direction x,y,z, got '" + o.view + "'");
  ro.view = v;
  if (o.isolines < 0 || o.isolines > 1000)
    throw Error("render: --isolines must be between 0 and 1000");
  ro.isolines = o.isolines;
  ro.title = std::filesystem::path(o.file).filename().string() + " (" + lm.mesh.field_name + ")";
  std::vector<TreeNode> nodes;
  if (!o.no_points) {
    if (!o.tree.empty()) {
      TreeResult tree = read_tree_json(o.tree);
      require_tree_of_mesh(o.tree, tree, o.file, lm.mesh, "--scalar");
      nodes = std::move(tree.nodes);
    } else {
      ExactTreeOptions eo;
      eo.threads = 0;
      nodes = exact_contour_tree(lm.mesh, eo).nodes;
    }
  }
  render_field(o.output, lm.mesh, nodes, ro);
  std::printf("%s: %lld cells, %d isolines, %zu critical points -> %s\n", o.file.c_str(),
              static_cast<long long>(lm.mesh.topology.num_cells()), ro.isolines, nodes.size(),
              o.output.c_str());
}

} // namespace

void register_render(CLI::App &app) {
  auto o = std::make_shared<RenderCmdOptions>();
  auto *sub = app.add_subcommand(
      "render", "Draw the field with exact isolines and its critical points (PNG or SVG)");
  sub->add_option("file", o->file, "Input file (.vtu, .pvtu, .pvd, .msh, .pos)")->required();
  sub->add_option("-o,--output", o->output, "Picture to write (.png or .svg)");
  add_field_options(sub, o->field);
  sub->add_option("--tree", o->tree,
                  "Critical points from this tree (JSON from hoct tree; default: compute the "
                  "exact tree)");
  sub->add_flag("--no-critical-points", o->no_points, "Draw no critical points");
  sub->add_option("--isolines", o->isolines, "Number of isolines (default 12)");
  sub->add_option("--view", o->view,
                  "View direction x,y,z towards the viewer for surfaces (default 1,1,1; planar "
                  "meshes are seen from above)");
  sub->add_option("--size", o->size, "Picture size WxH in pixels (default 1000x800)");
  sub->callback([o] { run_render(*o); });
}

} // namespace hoct::cli
