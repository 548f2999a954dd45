// `hoct convert INPUT -o OUTPUT.vtu`: any input hoct reads (.vtu, .msh) as VTK XML with Lagrange
// triangles and the chosen scalar, for ParaView (paraview/render_tree.py uses it for .msh files).
#include "commands.hpp"
#include "field_options.hpp"
#include "io/read_mesh.hpp"
#include "io/vtu_writer.hpp"
#include "output_paths.hpp"
#include "util/error.hpp"

#include <cstdio>
#include <memory>
#include <string>

namespace hoct::cli {

void register_convert(CLI::App &app) {
  struct Options {
    std::string input, output;
    FieldOptions field;
  };
  auto o = std::make_shared<Options>();
  auto *sub = app.add_subcommand(
      "convert",
      "Write any input (.vtu, .pvtu, .pvd, .msh, .pos) as VTK XML (.vtu) with Lagrange triangles");
  sub->add_option("input", o->input, "Input file (.vtu, .pvtu, .pvd, .msh, .pos)")->required();
  sub->add_option("-o,--output", o->output, "Output file (.vtu)")->required();
  add_field_options(sub, o->field);
  sub->callback([o] {
    require_extension("-o", o->output, ".vtu", "VTK XML unstructured grid");
    require_distinct_outputs({{"the input", o->input}}, {{"-o", o->output}});
    const MeshInput mesh = read_mesh(o->input, o->field.selection());
    for (const std::string &w : mesh.warnings)
      std::fprintf(stderr, "hoct: warning: %s\n", w.c_str());
    write_vtu(o->output, mesh);
    const std::string step = mesh.field_detail.empty() ? "" : " " + mesh.field_detail;
    std::printf("%s: %zu cells, %zu points, field '%s'%s -> %s\n", o->input.c_str(),
                mesh.num_cells(), mesh.num_points(), mesh.field_name.c_str(), step.c_str(),
                o->output.c_str());
  });
}

} // namespace hoct::cli
