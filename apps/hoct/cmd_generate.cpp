// `hoct generate NAME -o FILE.vtu`: the synthetic datasets modelled on the thesis' chapter 5.
#include "commands.hpp"
#include "datasets/datasets.hpp"
#include "error.hpp"
#include "io/vtu_writer.hpp"

#include <chrono>
#include <cstdio>
#include <map>
#include <memory>

namespace hoct::cli {
namespace {

struct GenerateOptions {
  std::string name, output, encoding = "appended";
  int degree = 0;
  double cells = 0;
  uint64_t seed = 1;
  bool list = false;
};

void run_generate(const GenerateOptions &o) {
  if (o.list || o.name == "list") {
    for (const auto &n : dataset_names())
      std::printf("%-13s %s\n", n.c_str(), dataset_description(n).c_str());
    return;
  }
  if (o.name.empty())
    throw Error("generate: name a dataset (hoct generate --list shows them)");
  if (o.output.empty())
    throw Error("generate: give an output file with -o FILE.vtu");
  static const std::map<std::string, VtkEncoding> encodings = {
      {"ascii", VtkEncoding::Ascii},
      {"base64", VtkEncoding::Base64},
      {"zlib", VtkEncoding::Base64Zlib},
      {"appended", VtkEncoding::AppendedRaw},
      {"appended-base64", VtkEncoding::AppendedBase64}};
  const auto enc = encodings.find(o.encoding);
  if (enc == encodings.end())
    throw Error("generate: unknown encoding '" + o.encoding +
                "' (ascii, base64, zlib, appended, appended-base64)");
  const auto t0 = std::chrono::steady_clock::now();
  DatasetOptions opt;
  opt.degree = o.degree;
  opt.cells = static_cast<long long>(o.cells);
  opt.seed = o.seed;
  const MeshInput mesh = generate_dataset(o.name, opt);
  write_vtu(o.output, mesh, enc->second);
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("%s: %zu cells of degree %d, %zu points -> %s (%.2f s)\n", o.name.c_str(),
              mesh.num_cells(), mesh.num_cells() ? mesh.cell_degree[0] : 0, mesh.num_points(),
              o.output.c_str(), s);
}

} // namespace

void register_generate(CLI::App &app) {
  auto o = std::make_shared<GenerateOptions>();
  auto *sub =
      app.add_subcommand("generate", "Write a synthetic dataset (thesis chapter 5) as .vtu");
  sub->add_option("name", o->name,
                  "Dataset: conductor, gauss, heater, random, sphere, two-triangle");
  sub->add_option("-o,--output", o->output, "Output file (.vtu)");
  sub->add_option("--degree", o->degree, "Polynomial degree (default: the dataset's own)");
  sub->add_option("--cells", o->cells, "Target number of cells (default: the dataset's own)");
  sub->add_option("--seed", o->seed, "Random seed (deterministic output for a seed)");
  sub->add_option("--encoding", o->encoding,
                  "VTU encoding: ascii, base64, zlib, appended (default), appended-base64");
  sub->add_flag("--list", o->list, "List the datasets");
  sub->callback([o] { run_generate(*o); });
}

} // namespace hoct::cli
