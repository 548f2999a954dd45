// hoct's benchmark (not a test): times the exact contour tree on the thesis' datasets and the
// PL contour tree on large refined meshes, as medians of repeated runs, and prints Markdown
// tables for docs/PERFORMANCE.md. Run it with bench/run.
#include "datasets/datasets.hpp"
#include "mesh/mesh.hpp"
#include "pl/pl_contour_tree.hpp"
#include "pl/pl_mesh.hpp"
#include "pl/refinement.hpp"
#include "tree/exact_contour_tree.hpp"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <functional>
#include <map>
#include <string>
#include <vector>

using namespace hoct;
using clock_type = std::chrono::steady_clock;

namespace {

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

// Median wall time of `runs` calls of f (seconds).
double time_median(int runs, const std::function<void()> &f) {
  std::vector<double> t;
  for (int i = 0; i < runs; ++i) {
    const auto a = clock_type::now();
    f();
    t.push_back(std::chrono::duration<double>(clock_type::now() - a).count());
  }
  return median(t);
}

double stat(const TreeResult &t, const std::string &name) {
  for (const auto &[k, v] : t.stats)
    if (k == name)
      return v;
  return 0;
}

long peak_rss_kib() {
  std::ifstream f("/proc/self/status");
  std::string line;
  while (std::getline(f, line))
    if (line.rfind("VmHWM:", 0) == 0)
      return std::stol(line.substr(6));
  return -1;
}

} // namespace

int main(int argc, char **argv) {
  CLI::App app{"hoct benchmark"};
  int runs = 5;
  bool quick = false;
  app.add_option("--runs", runs, "Repetitions per measurement (median reported)");
  app.add_flag("--quick", quick, "Smaller sizes (a smoke run)");
  CLI11_PARSE(app, argc, argv);

  // The thesis' Table 5.1 (seconds).
  const std::map<std::string, double> thesis = {{"conductor", 962.2},
                                                {"gauss", 56.7},
                                                {"heater", 10678.1},
                                                {"sphere", 206.9},
                                                {"two-triangle", 0.193}};
  std::printf("## Exact contour tree on the thesis' datasets (median of %d runs, 1 thread)\n\n",
              runs);
  std::printf("| dataset | cells | degree | nodes | fallback cells | exact tree (s) | thesis (s) | "
              "speed-up | PL tree of k=4 refinement (s) | exact / PL |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|\n");
  for (const auto &[name, t_thesis] : thesis) {
    DatasetOptions o;
    const MeshInput in = generate_dataset(name, o);
    const Mesh mesh = build_mesh(in);
    TreeResult tree;
    const double t_exact = time_median(runs, [&] { tree = exact_contour_tree(mesh); });
    const PlMesh pl = refine(mesh, 4);
    const double t_pl = time_median(runs, [&] { pl_contour_tree(pl, false, ""); });
    std::printf("| %s | %lld | %d | %zu | %.0f | %.4f | %.1f | %.0fx | %.4f | %.2f |\n",
                name.c_str(), static_cast<long long>(mesh.topology.num_cells()),
                mesh.field.max_degree(), tree.nodes.size(), stat(tree, "fallback_cells"), t_exact,
                t_thesis, t_thesis / t_exact, t_pl, t_exact / t_pl);
    std::fflush(stdout);
  }

  std::printf("\n## Exact tree phases on `random` (degree 3; median of %d runs)\n\n", runs);
  std::printf("| cells | critical points (s) | connections (s) | sweeps + merge (s) | total (s) | "
              "us per cell |\n|---|---|---|---|---|---|\n");
  for (long long cells : quick ? std::vector<long long>{10000, 100000}
                               : std::vector<long long>{10000, 100000, 1000000}) {
    DatasetOptions o;
    o.cells = cells;
    const Mesh mesh = build_mesh(generate_dataset("random", o));
    std::vector<double> crit, conn, sweep;
    TreeResult tree;
    const double total = time_median(runs, [&] {
      tree = exact_contour_tree(mesh);
      crit.push_back(stat(tree, "time_edge_nodes_s") +
                     stat(tree, "time_interior_critical_points_s"));
      conn.push_back(stat(tree, "time_connections_s") + stat(tree, "time_fallback_and_chains_s"));
      sweep.push_back(stat(tree, "time_sweeps_s") + stat(tree, "time_merge_s"));
    });
    std::printf("| %lld | %.3f | %.3f | %.3f | %.3f | %.2f |\n",
                static_cast<long long>(mesh.topology.num_cells()), median(crit), median(conn),
                median(sweep), total, 1e6 * total / static_cast<double>(mesh.topology.num_cells()));
    std::fflush(stdout);
  }

  std::printf(
      "\n## PL contour tree on large meshes (degree-1 `random` fields; median of %d runs)\n\n",
      runs);
  std::printf("| vertices | triangles | graph (s) | sweeps (s) | merge (s) | total (s) |\n"
              "|---|---|---|---|---|---|\n");
  for (long long cells :
       quick ? std::vector<long long>{500000} : std::vector<long long>{500000, 2000000, 8000000}) {
    DatasetOptions o;
    o.cells = cells;
    o.degree = 1;
    const PlMesh pl = split_lagrange_cells(generate_dataset("random", o));
    std::vector<double> g, s, m;
    const double total = time_median(runs, [&] {
      const TreeResult r = pl_contour_tree(pl, false, "");
      g.push_back(stat(r, "time_graph_s"));
      s.push_back(stat(r, "time_sweeps_s"));
      m.push_back(stat(r, "time_merge_s") + stat(r, "time_pairs_s"));
    });
    std::printf("| %lld | %zu | %.3f | %.3f | %.3f | %.3f |\n",
                static_cast<long long>(pl.num_vertices()), pl.triangles.size(), median(g),
                median(s), median(m), total);
    std::fflush(stdout);
  }
  std::printf("\npeak resident memory: %.1f MiB\n", peak_rss_kib() / 1024.0);
  return 0;
}
