// `hoct generate NAME -o FILE.vtu`: the synthetic datasets modelled on the thesis' chapter 5
// (src/datasets), written as VTK XML with Lagrange triangles.
#include "commands.hpp"
#include "datasets/datasets.hpp"
#include "io/vtu_writer.hpp"
#include "output_paths.hpp"
#include "util/error.hpp"
#include "util/stopwatch.hpp"

#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <string>

namespace hoct::cli {
namespace {

struct GenerateOptions {
  std::string name, output, encoding = "appended";
  int degree = 0;
  double cells = 0; // a double, so that 1e6 is accepted
  uint64_t seed = 1;
  double frequency = 1;
  double plateau = 0;
  double scale = 1, offset = 0;
  bool list = false;
  bool quads = false;
};

const std::map<std::string, VtkEncoding> &encodings() {
  static const std::map<std::string, VtkEncoding> e = {
      {"ascii", VtkEncoding::Ascii},
      {"base64", VtkEncoding::Base64},
      {"zlib", VtkEncoding::Base64Zlib},
      {"appended", VtkEncoding::AppendedRaw},
      {"appended-base64", VtkEncoding::AppendedBase64}};
  return e;
}

void list_datasets() {
  for (const auto &n : dataset_names())
    std::printf("%-13s %s\n", n.c_str(), dataset_description(n).c_str());
}

void run_generate(const GenerateOptions &o) {
  if (o.list || o.name == "list") {
    list_datasets();
    return;
  }
  if (o.name.empty())
    throw Error("generate: name a dataset (hoct generate --list shows them)");
  if (dataset_description(o.name).empty()) {
    std::string known;
    for (const auto &n : dataset_names())
      known += (known.empty() ? "" : ", ") + n;
    throw Error("generate: unknown dataset '" + o.name + "' (known: " + known + ")");
  }
  if (o.output.empty())
    throw Error("generate: give an output file with -o FILE.vtu");
  require_extension("-o", o.output, ".vtu", "VTK XML unstructured grid");
  if (!(o.cells >= 0) || o.cells > 1e12 || o.cells != std::floor(o.cells))
    throw Error("generate: --cells must be a positive whole number");
  if (o.degree < 0)
    throw Error("generate: --degree must be positive");
  const VtkEncoding encoding = encodings().at(o.encoding);

  Stopwatch clock;
  DatasetOptions options;
  options.degree = o.degree;
  options.cells = static_cast<long long>(o.cells);
  options.seed = o.seed;
  options.frequency = o.frequency;
  options.plateau = o.plateau;
  options.scale = o.scale;
  options.offset = o.offset;
  options.quadrilaterals = o.quads;
  const MeshInput mesh = generate_dataset(o.name, options);
  const double generated = clock.lap();
  write_vtu(o.output, mesh, encoding);
  const double written = clock.lap();
  std::printf(
      "%s: %zu cells, %zu points, degree %d -> %s (%.2f s: generate %.2f s, write %.2f s)\n",
      o.name.c_str(), mesh.num_cells(), mesh.num_points(),
      mesh.num_cells() ? static_cast<int>(mesh.cell_degree[0]) : 0, o.output.c_str(),
      generated + written, generated, written);
}

} // namespace

void register_generate(CLI::App &app) {
  auto o = std::make_shared<GenerateOptions>();
  std::string names;
  for (const auto &n : dataset_names())
    names += (names.empty() ? "" : ", ") + n;
  auto *sub = app.add_subcommand(
      "generate", "Write a synthetic dataset (modelled on the thesis' chapter 5) as .vtu; "
                  "deterministic for a seed");
  sub->add_option("name", o->name, "Dataset: " + names + " (or 'list')");
  sub->add_option("-o,--output", o->output, "Output file (.vtu)");
  sub->add_option("--degree", o->degree, "Polynomial degree 1..10 (default: the dataset's own)");
  sub->add_option("--cells", o->cells,
                  "Target number of cells, e.g. 1e6 (default: the dataset's own; the result is "
                  "the nearest size the dataset's mesh family allows)");
  sub->add_option("--seed", o->seed, "Random seed (default 1)");
  sub->add_option("--frequency", o->frequency,
                  "random only: multiply the wave numbers (default 1; F^2 times the features; "
                  "scale it with sqrt(cells) to keep the features per cell)");
  sub->add_option("--plateau", o->plateau,
                  "random only: raise the node values below their P-th percentile to it, a "
                  "plateau of constant cells over about P% of the square (default 0)");
  sub->add_option("--scale", o->scale,
                  "Multiply every value by S (default 1; applied before --offset)");
  sub->add_option("--offset", o->offset,
                  "Add C to every value (default 0): the same field around C, as kelvin or "
                  "pascal data are");
  sub->add_option("--encoding", o->encoding,
                  "VTU encoding: ascii, base64, zlib, appended (default), appended-base64")
      ->check(CLI::IsMember({"ascii", "base64", "zlib", "appended", "appended-base64"}));
  sub->add_flag("--quads", o->quads,
                "random only: Lagrange quadrilaterals of order --degree (VTK type 70) instead of "
                "triangles, on the same grid");
  sub->add_flag("--list", o->list, "List the datasets with a one-line description each");
  sub->callback([o] { run_generate(*o); });
}

} // namespace hoct::cli
