// hoct's benchmark (not a test; run it with bench/run): the exact contour tree on the thesis'
// datasets against the thesis' times and against hoct's PL tree of the 16x refinement, its
// scaling on random fields up to 4 million cells for degrees 2, 3 and 5 with one and two
// threads, phase by phase, the CLI's peak memory, the PL tree on large meshes, and whole CLI runs
// on large noisy trees. Prints Markdown for docs/PERFORMANCE.md; medians of --runs runs.
#include "bench_pieces.hpp"
#include "bench_pipeline.hpp"
#include "bench_support.hpp"

#include "datasets/datasets.hpp"
#include "datasets/shuffled_points.hpp"
#include "exact/exact_contour_tree.hpp"
#include "io/vtu_writer.hpp"
#include "mesh/mesh.hpp"
#include "mesh/mesh_partition.hpp"
#include "pl/pl_contour_tree.hpp"
#include "pl/pl_mesh.hpp"
#include "pl/refinement.hpp"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

using namespace hoct;
using namespace hoct::bench;

namespace {

struct Settings {
  int runs = 5;
  bool quick = false;
  std::vector<std::string> sections = {"datasets", "scaling", "density", "plateau", "quads", "reeb",
                                       "memory",   "pl",      "large",   "mpi",     "pieces"};
  std::vector<int> degrees = {2, 3, 5};
  std::vector<double> sizes = {1e4, 1e5, 1e6, 4e6};
  std::vector<int> threads = {1, 2};
  std::string ttk_ftm; // an external TTK FTM driver to time side by side (see pl_section)
  std::string ttk_ftr; // an external TTK FTR driver, the Reeb graph (see reeb_section)
};

bool wants(const Settings &s, const std::string &section) {
  for (const auto &x : s.sections)
    if (x == section)
      return true;
  return false;
}

// `runs` runs of the pipeline for each thread count, interleaved (run i with every count before
// run i + 1) so that the machine's slow spells hit every count alike: the per-count medians, and
// the median over runs of the cell phase's speed-up from the first count to the last.
struct ThreadRuns {
  std::vector<PipelineResult> median; // per thread count, in the order given
  double cell_speedup = 0;
};
ThreadRuns interleaved_runs(const std::string &vtu, const std::vector<int> &threads, bool vtp,
                            int runs, const ScratchDir &scratch) {
  std::vector<std::vector<PipelineResult>> all(threads.size());
  std::vector<double> speedups;
  for (int i = 0; i < runs; ++i) {
    for (std::size_t k = 0; k < threads.size(); ++k)
      all[k].push_back(run_pipeline(vtu, threads[k], vtp, scratch));
    const double last = all.back().back().cell_phase();
    if (threads.size() > 1 && last > 0)
      speedups.push_back(all.front().back().cell_phase() / last);
  }
  ThreadRuns out;
  for (auto &r : all)
    out.median.push_back(median_of(r));
  out.cell_speedup = speedups.empty() ? 0.0 : median(std::move(speedups));
  return out;
}

// Exact tree and PL tree of the k = 4 refinement, interleaved so that the machine's noise hits
// both alike; medians of the computation alone (mesh and refinement built before).
std::pair<double, double> exact_vs_pl(const Mesh &mesh, const PlMesh &pl, int threads, int runs) {
  std::vector<double> te, tp;
  ExactTreeOptions eo;
  eo.threads = threads;
  for (int i = 0; i < runs; ++i) {
    auto t = clock_type::now();
    const TreeResult a = exact_contour_tree(mesh, eo);
    te.push_back(seconds_since(t));
    t = clock_type::now();
    const TreeResult b = pl_contour_tree(pl, false, "", false, threads);
    tp.push_back(seconds_since(t));
  }
  return {median(te), median(tp)};
}

void datasets_section(const Settings &s) {
  const std::vector<std::pair<std::string, double>> thesis = {{"conductor", 962.2},
                                                              {"gauss", 56.7},
                                                              {"heater", 10678.1},
                                                              {"sphere", 206.9},
                                                              {"two-triangle", 0.193}};
  const int runs = s.quick ? 3 : std::max(s.runs, 11); // small inputs: more runs are cheap
  std::printf("## Thesis datasets: `hoct tree FILE.vtu --json J --vtp V`, phase by phase "
              "(1 thread, median of %d runs, seconds)\n\n",
              runs);
  std::printf("| dataset | cells | degree | nodes | read | mesh, checks | Bernstein conversion "
              "| critical points: edges | critical points: interior | connections | graph assembly "
              "| sweeps | merge | write | total | exact tree | thesis | speed-up (tree) | speed-up "
              "(total) |\n|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"
              "---|---|\n");
  struct Row {
    std::string name;
    double e1 = 0, p1 = 0, e2 = 0, p2 = 0, refine = 0, speedup = 0;
  };
  std::vector<Row> rows;
  for (const auto &[name, t_thesis] : thesis) {
    ScratchDir scratch;
    const MeshInput input = generate_dataset(name, DatasetOptions{});
    const std::string vtu = scratch.file(name + ".vtu");
    write_vtu(vtu, input);
    const Mesh mesh = build_mesh(input);
    const auto t = clock_type::now();
    const PlMesh pl = refine(mesh, 4);
    Row row{name};
    row.refine = seconds_since(t);
    const ThreadRuns tr = interleaved_runs(vtu, s.threads, true, runs, scratch);
    const PipelineResult m1 = tr.median.front();
    row.speedup = tr.cell_speedup;
    for (int threads : s.threads) {
      const auto [e, p] = exact_vs_pl(mesh, pl, threads, runs);
      if (threads == 1)
        row.e1 = e, row.p1 = p;
      else
        row.e2 = e, row.p2 = p;
    }
    std::printf("| %s | %lld | %d | %zu | %.4f | %.4f | %.4f | %.4f | %.4f | %.4f | %.4f | %.4f "
                "| %.4f | %.4f | %.4f | %.5f | %.1f | %.0fx | %.0fx |\n",
                name.c_str(), static_cast<long long>(m1.cells), mesh.field.max_degree(), m1.nodes,
                m1.read, m1.mesh_checks(), m1.bernstein, m1.edges, m1.interior, m1.connections,
                m1.assembly, m1.sweeps, m1.merge, m1.write, m1.total, m1.tree, t_thesis,
                t_thesis / m1.tree, t_thesis / m1.total);
    std::fflush(stdout);
    rows.push_back(row);
  }
  std::printf("\n### Exact tree versus hoct's PL tree of the k = 4 refinement (16x the "
              "triangles), interleaved runs (median of %d)\n\n",
              runs);
  std::printf("| dataset | exact, 1 thread | PL k=4 | exact / PL (1 thread) | exact, 2 threads | "
              "exact / PL (2 threads) | PL refinement built in | cell phase 1 -> 2 threads |\n"
              "|---|---|---|---|---|---|---|---|\n");
  for (const Row &r : rows)
    std::printf("| %s | %.5f | %.5f | %.2f | %.5f | %.2f | %.4f | %.2fx |\n", r.name.c_str(), r.e1,
                r.p1, r.e1 / r.p1, r.e2, r.e2 / r.p2, r.refine, r.speedup);
  std::printf("\n(Both trees run their join and split sweeps on a thread each where there are "
              "two threads and enough nodes; the PL tree has no other parallel phase. The cell "
              "phase's speed-up is from the pipeline runs of the first table, 1- and 2-thread runs "
              "interleaved, median of the per-run ratios.)\n\n");
}

// The `random` dataset of about `size` cells of `degree` (wave numbers times `frequency`) written
// to `vtu`; returns its cells.
long long write_random(const std::string &vtu, double size, int degree, double frequency = 1,
                       double plateau = 0) {
  DatasetOptions o;
  o.cells = static_cast<long long>(size);
  o.degree = degree;
  o.frequency = frequency;
  o.plateau = plateau;
  const MeshInput in = generate_dataset("random", o);
  write_vtu(vtu, in);
  return static_cast<long long>(in.num_cells());
}

// The scaling tables: one field on ever finer meshes (`scaling`: the smaller meshes hold more of
// the field per cell), or the field's features refined with the mesh (`density`: wave numbers
// times sqrt(cells / 1e4), the same features per cell at every size, so that time per cell
// shows the algorithm's own scaling).
// Runs per scaling row: the small meshes' phases last milliseconds, where this shared machine's
// noise moves single runs (and the 1 -> 2 thread ratios) most, and more runs are cheap.
int scaling_runs(const Settings &s, double cells) {
  if (s.quick)
    return s.runs;
  if (cells <= 1.5e5)
    return std::max(s.runs, 11);
  return cells <= 1.5e6 ? s.runs : std::min(s.runs, 3);
}

void scaling_section(const Settings &s, bool constant_density) {
  if (constant_density)
    std::printf("## Scaling at constant feature density: `random --frequency F` with F = "
                "sqrt(cells / 1e4) (the 1e4 row's features per cell at every size)");
  else
    std::printf("## Scaling on `random` fields (one field, finer meshes)");
  std::printf(": `hoct tree FILE.vtu --json J` phase by phase (seconds; medians of %d runs up to "
              "1e5 cells, %d up to 1e6, %d above; 1- and 2-thread runs interleaved, each building "
              "the mesh and the tree on its threads; the cell phase is the critical points, the "
              "connections and the graph assembly, its speed-up the median of the per-run ratios; "
              "mesh, 2 threads: the whole build, checks and conversion)\n\n",
              scaling_runs(s, 1e5), scaling_runs(s, 1e6), scaling_runs(s, 4e6));
  std::printf(
      "| degree | cells | graph nodes | tree nodes | read | mesh, checks | Bernstein conversion "
      "| critical points: edges | critical points: interior | connections | graph assembly | "
      "sweeps | merge | write | total | us/cell (tree) | cells/s (total) | tree, 2 threads | "
      "cell phase 1 -> 2 threads | mesh, 2 threads | total, 2 threads "
      "|\n|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"
      "\n");
  for (int degree : s.degrees)
    for (double size : s.sizes) {
      ScratchDir scratch;
      const std::string vtu = scratch.file("random.vtu");
      write_random(vtu, size, degree, constant_density ? std::sqrt(size / 1e4) : 1.0);
      const ThreadRuns tr = interleaved_runs(vtu, s.threads, false, scaling_runs(s, size), scratch);
      const PipelineResult &m1 = tr.median.front(), &m2 = tr.median.back();
      const double cells = static_cast<double>(m1.cells);
      std::printf(
          "| %d | %lld | %lld | %zu | %.3f | %.3f | %.3f | %.4f | %.4f | %.4f | %.4f | %.3f | "
          "%.4f | %.3f | %.3f | %.2f | %.0f | %.3f | %.2fx | %.3f | %.3f |\n",
          degree, static_cast<long long>(m1.cells), static_cast<long long>(m1.graph_nodes),
          m1.nodes, m1.read, m1.mesh_checks(), m1.bernstein, m1.edges, m1.interior, m1.connections,
          m1.assembly, m1.sweeps, m1.merge, m1.write, m1.total, 1e6 * m1.tree / cells,
          cells / m1.total, m2.tree, tr.cell_speedup, m2.mesh, m2.total);
      std::fflush(stdout);
    }
  std::printf("\n");
}

// Degenerate data at scale: the cubic `random` field with a plateau over 30% of its values
// (`--plateau 30`: about a third of the cells constant, the cells around them falling back to
// the K x K refinement), against the same field without it.
void plateau_section(const Settings &s) {
  const int runs = s.quick ? s.runs : std::min(std::max(s.runs, 3), 5);
  std::printf("## Plateaus: `random --degree 3 --plateau 30` (values below their 30th percentile "
              "raised to it) against the same field without the plateau: `hoct tree FILE.vtu "
              "--json J` (seconds, medians of %d runs, 1- and 2-thread runs interleaved)\n\n",
              runs);
  std::printf("| cells | constant cells | fallback cells | graph nodes | tree nodes | read | mesh "
              "| exact tree | write | total | exact tree without the plateau | with / without | "
              "exact tree, 2 threads | total, 2 threads |\n"
              "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (double size : s.sizes) {
    ScratchDir scratch;
    const std::string flat = scratch.file("plateau.vtu"), plain = scratch.file("plain.vtu");
    write_random(flat, size, 3, 1.0, 30);
    write_random(plain, size, 3);
    const ThreadRuns tr = interleaved_runs(flat, s.threads, false, runs, scratch);
    const ThreadRuns tp = interleaved_runs(plain, {1}, false, runs, scratch);
    const PipelineResult &m1 = tr.median.front(), &m2 = tr.median.back(), &p1 = tp.median.front();
    std::printf("| %lld | %.0f | %.0f | %lld | %zu | %.3f | %.3f | %.3f | %.3f | %.3f | %.3f | "
                "%.2fx | %.3f | %.3f |\n",
                static_cast<long long>(m1.cells), m1.constant_cells, m1.fallback_cells,
                static_cast<long long>(m1.graph_nodes), m1.nodes, m1.read, m1.mesh, m1.tree,
                m1.write, m1.total, p1.tree, m1.tree / p1.tree, m2.tree, m2.total);
    std::fflush(stdout);
  }
  std::printf("\n");
}

// Quadrilaterals against triangles of the same order on the same grid (`random --quads`: each
// rectangle one quadrilateral of order p, or two triangles of degree p: the same nodes, so the
// time ratio is the ratio of times per degree of freedom), runs interleaved; and the peak memory
// of each in a process of its own.
void quads_section(const Settings &s) {
  const int runs = s.quick ? s.runs : std::min(std::max(s.runs, 3), 5);
  const std::vector<double> sizes =
      s.quick ? std::vector<double>{1e4} : std::vector<double>{1e5, 1e6};
  std::printf("## Quadrilaterals: `random --quads --degree P` against `random --degree P` on the "
              "same grid (twice the cells: the same nodes), `hoct tree FILE.vtu --json J`, 1 "
              "thread (seconds, medians of %d interleaved runs; peak memory: GNU time's maximum "
              "resident set of `--threads 1`, per input cell)\n\n",
              runs);
  std::printf("| order | quadrilaterals | triangles | nodes | quads: mesh | quads: tree | quads: "
              "total | triangles: mesh | triangles: tree | triangles: total | time per node, "
              "quads / triangles | quads: peak MiB (bytes per cell) | triangles: peak MiB (bytes "
              "per cell) |\n|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (int p : {2, 3})
    for (double size : sizes) {
      ScratchDir scratch;
      const std::string qv = scratch.file("quads.vtu"), tv = scratch.file("triangles.vtu");
      DatasetOptions o;
      o.cells = static_cast<long long>(size);
      o.degree = p;
      o.quadrilaterals = true;
      long long quads = 0, nodes = 0;
      {
        const MeshInput in = generate_dataset("random", o);
        quads = static_cast<long long>(in.num_cells());
        nodes = static_cast<long long>(in.num_points());
        write_vtu(qv, in);
      }
      const long long tris = write_random(tv, 2 * size, p);
      std::vector<PipelineResult> rq, rt;
      for (int i = 0; i < runs; ++i) {
        rq.push_back(run_pipeline(qv, 1, false, scratch));
        rt.push_back(run_pipeline(tv, 1, false, scratch));
      }
      std::vector<double> ratios;
      for (int i = 0; i < runs; ++i)
        ratios.push_back(rq[static_cast<std::size_t>(i)].total /
                         rt[static_cast<std::size_t>(i)].total);
      const PipelineResult q = median_of(rq), t = median_of(rt);
      auto peak = [&](const std::string &vtu) {
        return run_process({executable_dir() + "/hoct", "tree", vtu, "--json",
                            scratch.file("cli.json"), "--threads", "1", "-q"});
      };
      const ProcessPeak pq = peak(qv), pt = peak(tv);
      std::printf("| %d | %lld | %lld | %lld | %.3f | %.3f | %.3f | %.3f | %.3f | %.3f | %.2fx | "
                  "%.0f (%.0f) | %.0f (%.0f) |\n",
                  p, quads, tris, nodes, q.mesh, q.tree, q.total, t.mesh, t.tree, t.total,
                  median(std::move(ratios)), pq.max_rss_kib / 1024.0,
                  1024.0 * pq.max_rss_kib / static_cast<double>(quads), pt.max_rss_kib / 1024.0,
                  1024.0 * pt.max_rss_kib / static_cast<double>(tris));
      std::fflush(stdout);
    }
  std::printf("\n");
}

// Reeb graphs: the plate with 10 x 10 holes (`hoct generate plate`), cubic. The Reeb graph's own
// work is the cut into disks and the gluing (both inside the tree's time); the rest is the
// contour tree of the disks, which is what the tree costs on a disk of those cells. Against a
// genus-0 mesh there is nothing to compare: the contour tree path runs untouched there.
// The PL mesh in the binary layout the external FTM driver reads: "HOCTPL1\n", u64 vertices,
// u64 triangles, xyz doubles, scalar doubles, int64 vertex ids per triangle.
void write_pl_binary(const std::string &path, const PlMesh &pl) {
  std::FILE *f = std::fopen(path.c_str(), "wb");
  if (!f)
    throw std::runtime_error("cannot write " + path);
  const uint64_t nv = pl.points.size(), nt = pl.triangles.size();
  std::fwrite("HOCTPL1\n", 1, 8, f);
  std::fwrite(&nv, sizeof nv, 1, f);
  std::fwrite(&nt, sizeof nt, 1, f);
  std::fwrite(pl.points.data(), sizeof(Vec3), nv, f);
  std::fwrite(pl.values.data(), sizeof(double), nv, f);
  std::fwrite(pl.triangles.data(), sizeof(std::array<int64_t, 3>), nt, f);
  std::fclose(f);
}

// "key=value" from a line of the driver's output, -1 if absent.
double field(const std::string &text, const std::string &line_start, const std::string &key) {
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line))
    if (line.rfind(line_start, 0) == 0) {
      const auto at = line.find(" " + key + "=");
      if (at != std::string::npos)
        return std::stod(line.substr(at + key.size() + 2));
    }
  return -1;
}

std::string capture(const std::string &command) {
  std::FILE *p = popen(command.c_str(), "r");
  if (!p)
    throw std::runtime_error("cannot run " + command);
  std::string out;
  char buf[4096];
  for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, p)) > 0;)
    out.append(buf, n);
  if (pclose(p) != 0)
    throw std::runtime_error(command + " failed");
  return out;
}

// "time_tree_s" of a tree's JSON, -1 if absent.
double json_tree_seconds(const std::string &path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  const std::string s = text.str();
  const auto at = s.find("\"time_tree_s\":");
  return at == std::string::npos ? -1 : std::stod(s.substr(at + 14));
}

void reeb_section(const Settings &s) {
  const int runs = s.quick ? s.runs : std::min(std::max(s.runs, 3), 5);
  const std::vector<double> sizes =
      s.quick ? std::vector<double>{1e4} : std::vector<double>{1e5, 1e6};
  const bool ttk = !s.ttk_ftr.empty();
  std::printf(
      "## Reeb graphs: `plate --degree 3` (100 holes), `hoct tree FILE.vtu --json J`, 1 "
      "thread (seconds, medians of %d runs; peak memory: GNU time's maximum resident set)\n\n",
      runs);
  std::printf("| cells | loops | edges cut | mesh | cut | disks' tree | gluing | tree (all) | "
              "total | tree / disks' tree | peak MiB (bytes per cell) |\n"
              "|---|---|---|---|---|---|---|---|---|---|---|\n");
  std::vector<std::string> ttk_rows;
  for (double size : sizes) {
    ScratchDir scratch;
    const std::string vtu = scratch.file("plate.vtu");
    DatasetOptions o;
    o.cells = static_cast<long long>(size);
    o.degree = 3;
    long long cells = 0;
    std::string bin;
    std::size_t pl_triangles = 0;
    {
      MeshInput in = generate_dataset("plate", o);
      cells = static_cast<long long>(in.num_cells());
      write_vtu(vtu, in);
      if (ttk) { // the PL 16x refinement (k = 4) of the same field, for TTK
        const PlMesh pl = refine(build_mesh(std::move(in)), 4);
        bin = scratch.file("pl.bin");
        write_pl_binary(bin, pl);
        pl_triangles = pl.triangles.size();
      }
    }
    std::vector<PipelineResult> r;
    std::vector<double> ratios;
    for (int i = 0; i < runs; ++i) {
      r.push_back(run_pipeline(vtu, 1, false, scratch));
      const PipelineResult &x = r.back();
      ratios.push_back(x.tree / (x.tree - x.cut - x.gluing));
    }
    const PipelineResult m = median_of(r);
    const ProcessPeak peak = run_process({executable_dir() + "/hoct", "tree", vtu, "--json",
                                          scratch.file("cli.json"), "--threads", "1", "-q"});
    std::printf("| %lld | %lld | %lld | %.3f | %.3f | %.3f | %.3f | %.3f | %.3f | %.2fx | %.0f "
                "(%.0f) |\n",
                cells, static_cast<long long>(m.loops), static_cast<long long>(m.seam_edges),
                m.mesh, m.cut, m.tree - m.cut - m.gluing, m.gluing, m.tree, m.total,
                median(std::move(ratios)), peak.max_rss_kib / 1024.0,
                1024.0 * peak.max_rss_kib / static_cast<double>(cells));
    std::fflush(stdout);
    if (!ttk)
      continue;
    // Cold against cold: each run a fresh `hoct tree` process (its tree time from the JSON)
    // and a fresh driver process (its graph time, reading excluded), alternated.
    std::vector<double> hoct_cold, ftr, ratio;
    bool same = true;
    for (int i = 0; i < runs; ++i) {
      const std::string json = scratch.file("cold.json");
      run_process(
          {executable_dir() + "/hoct", "tree", vtu, "--json", json, "--threads", "1", "-q"});
      hoct_cold.push_back(json_tree_seconds(json));
      const std::string out = capture(s.ttk_ftr + " " + bin + " --runs 1 --threads 1 2>/dev/null");
      ftr.push_back(field(out, "median", "total"));
      ratio.push_back(hoct_cold.back() / ftr.back());
      same = same && field(out, "graph:", "loops") == static_cast<double>(m.loops);
    }
    char row[512];
    std::snprintf(row, sizeof row, "| %lld | %zu | %.3f | %.3f | %.3f | %s |\n", cells,
                  pl_triangles, median(hoct_cold), median(ftr), median(std::move(ratio)),
                  same ? "yes" : "NO");
    ttk_rows.push_back(row);
  }
  std::printf("\n");
  if (!ttk)
    return;
  std::printf("Side by side with TTK's Reeb graph (FTR; `%s`, an external driver built outside "
              "this repository from topology-tool-kit/ttk) on the PL 16x refinement (k = 4) of "
              "the same field; both cold (a fresh process per run, runs alternated, reading "
              "excluded: hoct's `time_tree_s`, TTK's triangulation preconditioning + order array "
              "+ FTRGraph::build), 1 thread, medians of %d runs:\n\n"
              "| cells | PL 16x triangles | hoct exact tree (s) | TTK FTR on PL 16x (s) | "
              "exact / FTR | same loops |\n|---|---|---|---|---|---|\n",
              s.ttk_ftr.c_str(), runs);
  for (const std::string &row : ttk_rows)
    std::printf("%s", row.c_str());
  std::printf("\n");
}

// A number of a tree JSON's "stats" (written last: only the file's tail is read), -1 if absent.
double json_stat(const std::string &path, const std::string &key) {
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  const std::streamoff size = in.tellg(), tail = std::min<std::streamoff>(size, 1 << 16);
  std::string text(static_cast<std::size_t>(tail), '\0');
  in.seekg(size - tail);
  in.read(text.data(), tail);
  const std::string quoted = "\"" + key + "\":";
  const auto at = text.rfind(quoted);
  return at == std::string::npos ? -1 : std::stod(text.substr(at + quoted.size()));
}

// Large trees: the whole `hoct tree FILE --linear --json J` run on noisy degree-1 fields (a
// tree node for every few vertices), each run a fresh process (cold), 1 and 2 threads
// alternated; the phases from the JSON's stats, the rest of the run (start, output) as the
// difference; then one run with `--vtp V` too (arcs drawn on the surface).
void large_section(const Settings &s) {
  const int runs = s.quick ? 1 : std::min(std::max(s.runs, 3), 5);
  struct Case {
    double cells, frequency;
  };
  const std::vector<Case> cases =
      s.quick ? std::vector<Case>{{2e5, 120}} : std::vector<Case>{{2e6, 400}, {8e6, 800}};
  std::printf("## Large trees: `hoct tree FILE.vtu --linear --json J --threads T` on noisy "
              "fields (`random --degree 1 --frequency F`), a fresh process per run, 1 and 2 "
              "threads alternated (seconds, medians of %d runs; whole: the process's wall time; "
              "branches: flat regions contracted, branches decomposed; rest: whole - read - "
              "check - tree - branches, the output above all)\n\n",
              runs);
  std::printf(
      "| points | tree nodes | threads | read | check | tree | sweeps | pairs | branches "
      "| rest | whole | whole / (read + tree) | pairs / sweeps | JSON MB (MB/s of the "
      "rest) | peak MiB |\n|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  std::vector<std::string> vtp_rows;
  for (const Case &c : cases) {
    ScratchDir scratch;
    const std::string vtu = scratch.file("noisy.vtu"), json = scratch.file("t.json");
    write_random(vtu, c.cells, 1, c.frequency);
    std::map<int, std::vector<double>> read, check, tree, sweeps, pairs, branches, whole, peak;
    double nodes = 0, points = 0, bytes = 0;
    for (int i = 0; i < runs; ++i)
      for (int threads : {1, 2}) {
        const ProcessPeak p =
            run_process({executable_dir() + "/hoct", "tree", vtu, "--linear", "--json", json,
                         "--threads", std::to_string(threads), "-q"});
        read[threads].push_back(json_stat(json, "time_read_s"));
        check[threads].push_back(json_stat(json, "time_check_s"));
        tree[threads].push_back(json_stat(json, "time_tree_s"));
        sweeps[threads].push_back(json_stat(json, "time_sweeps_s"));
        pairs[threads].push_back(json_stat(json, "time_pairs_s"));
        branches[threads].push_back(json_stat(json, "time_branches_s"));
        whole[threads].push_back(p.seconds);
        peak[threads].push_back(p.max_rss_kib / 1024.0);
        nodes = json_stat(json, "nodes");
        points = json_stat(json, "pl_vertices");
        bytes = static_cast<double>(std::filesystem::file_size(json));
      }
    for (int threads : {1, 2}) {
      const double r = median(read[threads]), k = median(check[threads]), t = median(tree[threads]),
                   b = median(branches[threads]), w = median(whole[threads]),
                   rest = w - r - k - t - b;
      std::printf("| %.0f | %.0f | %d | %.3f | %.3f | %.3f | %.3f | %.3f | %.3f | %.3f | %.3f | "
                  "%.2fx | %.2f | %.0f (%.0f) | %.0f |\n",
                  points, nodes, threads, r, k, t, median(sweeps[threads]), median(pairs[threads]),
                  b, rest, w, w / (r + t), median(pairs[threads]) / median(sweeps[threads]),
                  bytes / 1e6, rest > 0 ? bytes / 1e6 / rest : 0.0, median(peak[threads]));
      std::fflush(stdout);
    }
    const std::string vtp = scratch.file("t.vtp");
    const ProcessPeak p = run_process({executable_dir() + "/hoct", "tree", vtu, "--linear",
                                       "--json", json, "--vtp", vtp, "--threads", "2", "-q"});
    char row[256];
    std::snprintf(row, sizeof row, "| %.0f | %.0f | %.3f | %.0f | %.0f |\n", points, nodes,
                  p.seconds, static_cast<double>(std::filesystem::file_size(vtp)) / 1e6,
                  p.max_rss_kib / 1024.0);
    vtp_rows.push_back(row);
  }
  std::printf("\nWith `--vtp V` too (every arc drawn on the surface), 2 threads, one run:\n\n"
              "| points | tree nodes | whole (s) | .vtp MB | peak MiB |\n|---|---|---|---|---|\n");
  for (const std::string &row : vtp_rows)
    std::printf("%s", row.c_str());
  std::printf("\n");
}

// The mesh as a partitioned file: `pieces` .vtu files of contiguous cells (no ghosts; the shared
// points written by both neighbours, joined by position) listed by `pvtu`.
void write_pieces(const std::string &pvtu, const MeshInput &in, int pieces) {
  const std::filesystem::path listing(pvtu);
  std::string xml = "<?xml version=\"1.0\"?>\n<VTKFile type=\"PUnstructuredGrid\" "
                    "version=\"0.1\">\n <PUnstructuredGrid GhostLevel=\"0\">\n  <PPointData "
                    "Scalars=\"f\">\n   <PDataArray type=\"Float64\" Name=\"f\"/>\n  "
                    "</PPointData>\n  <PPoints><PDataArray type=\"Float64\" "
                    "NumberOfComponents=\"3\"/></PPoints>\n";
  for (int k = 0; k < pieces; ++k) {
    const auto [begin, end] = piece_cell_range(static_cast<int64_t>(in.num_cells()), pieces, k);
    const std::string name = listing.stem().string() + "_" + std::to_string(k) + ".vtu";
    write_vtu((listing.parent_path() / name).string(), extract_piece(in, begin, end).input);
    xml += "  <Piece Source=\"" + name + "\"/>\n";
  }
  xml += " </PUnstructuredGrid>\n</VTKFile>\n";
  std::ofstream(pvtu) << xml;
}

// `mpirun -np N hoct tree` against one plain process, on the mesh as one .vtu (each rank reads
// its own part) and as a .pvtu of 8 pieces (each rank reads its own): whole runs (a fresh mpirun
// per run, rank counts alternated), each rank's report (its piece's time, kept nodes, bytes, peak
// memory) read from the summary, and the JSON compared with the plain run's.
void mpi_section(const Settings &s) {
  const int runs = s.quick ? 1 : std::min(std::max(s.runs, 3), 5);
  const double size = s.quick ? 1e5 : 4e6;
  const std::vector<int> counts = s.quick ? std::vector<int>{1, 2} : std::vector<int>{1, 2, 4, 8};
  ScratchDir scratch;
  const std::string vtu = scratch.file("random.vtu"), pvtu = scratch.file("random.pvtu"),
                    plate = scratch.file("plate.vtu"), shuffled = scratch.file("shuffled.vtu"),
                    vtp = scratch.file("arcs.vtp");
  long long cells = 0, plate_cells = 0;
  {
    DatasetOptions o;
    o.cells = static_cast<long long>(size);
    o.degree = 3;
    MeshInput in = generate_dataset("random", o);
    write_vtu(vtu, in);
    write_pieces(pvtu, in, 8);
    cells = static_cast<long long>(in.num_cells());
    // The same mesh with its points numbered at random (each rank's cells then use points all
    // over the file).
    const MeshInput mixed = with_points_shuffled(in, 3);
    in = MeshInput{};
    write_vtu(shuffled, mixed);
    o.cells = static_cast<long long>(size / 4); // a Reeb graph: the surface cut open, glued back
    const MeshInput holes = generate_dataset("plate", o);
    write_vtu(plate, holes);
    plate_cells = static_cast<long long>(holes.num_cells());
  }
  setenv("OMPI_ALLOW_RUN_AS_ROOT", "1", 1); // a container's root
  setenv("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1", 1);
  setenv("HOCT_MPI", "1", 1); // -np 1 too runs the distributed code
  const std::string hoct = executable_dir() + "/hoct";
  auto slurp = [](const std::string &path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  struct Input {
    std::string file, label, mesh;
    long long cells;
    std::vector<std::string> flags;
  };
  const std::vector<Input> inputs = {
      {vtu, "FILE.vtu (each rank reads its own part)", "random cubic cells", cells, {}},
      {pvtu, "FILE.pvtu, 8 pieces (each rank reads its own)", "random cubic cells", cells, {}},
      {shuffled,
       "FILE.vtu with its points numbered at random (each rank reads its own cells and share of "
       "the points)",
       "random cubic cells",
       cells,
       {}},
      {plate,
       "the plate's Reeb graph, FILE.vtu (each rank reads its own part)",
       "cubic cells of the plate with 100 holes",
       plate_cells,
       {}},
      {plate,
       "the plate's PL Reeb graph, `--linear`, FILE.vtu (each rank reads its own part)",
       "cubic cells of the plate with 100 holes",
       plate_cells,
       {"--linear"}},
      {vtu,
       "the arcs drawn on the surface, `--vtp V`, FILE.vtu (the pieces draw them)",
       "random cubic cells",
       cells,
       {"--vtp", vtp}},
      {plate,
       "the plate's Reeb graph with its arcs drawn, `--vtp V`, FILE.vtu (the pieces draw them)",
       "cubic cells of the plate with 100 holes",
       plate_cells,
       {"--vtp", vtp}}};
  for (const Input &input : inputs) {
    const std::string plain_json = scratch.file("plain.json");
    std::vector<double> plain;
    std::map<int, std::vector<double>> whole, piece, kept, sent, received, peak, arcs_received,
        arcs_reports, arcs_neighbour, arcs_seconds;
    std::map<int, std::string> arcs_rounds;
    std::map<int, bool> same, by_pieces;
    for (int i = 0; i < runs; ++i) {
      std::vector<std::string> one{hoct,           "tree",      input.file, "--json", plain_json,
                                   "--no-timings", "--threads", "1",        "-q"};
      one.insert(one.end(), input.flags.begin(), input.flags.end());
      plain.push_back(run_process(one).seconds);
      for (int n : counts) {
        const std::string json = scratch.file("mpi.json"), out = scratch.file("mpi.txt"),
                          err = scratch.file("mpi.err");
        std::vector<std::string> command{
            "/usr/bin/mpirun", "--oversubscribe", "-np", std::to_string(n), hoct,        "tree",
            input.file,        "--json",          json,  "--no-timings",    "--threads", "1"};
        command.insert(command.end(), input.flags.begin(), input.flags.end());
        const ProcessPeak p = run_process(command, out, err);
        whole[n].push_back(p.seconds);
        same[n] = (i == 0 || same[n]) && slurp(json) == slurp(plain_json);
        const std::string text = slurp(out);
        by_pieces[n] = (i == 0 || by_pieces[n]) &&
                       text.find("checks: by the pieces together") != std::string::npos &&
                       slurp(err).find("reads the whole") == std::string::npos;
        // "    k: C cells, K kept, S / R KiB, M MiB, T s" per rank.
        std::istringstream lines(text);
        double max_piece = 0, max_kept = 0, max_sent = 0, max_peak = 0, root_received = 0;
        for (std::string line; std::getline(lines, line);) {
          int rank = 0;
          double c = 0, k = 0, sk = 0, rk = 0, m = 0, t = 0;
          if (std::sscanf(line.c_str(), " %d: %lf cells, %lf kept, %lf / %lf KiB, %lf MiB, %lf s",
                          &rank, &c, &k, &sk, &rk, &m, &t) == 7) {
            max_piece = std::max(max_piece, t);
            max_kept = std::max(max_kept, k);
            max_sent = std::max(max_sent, sk);
            max_peak = std::max(max_peak, m);
            if (rank == 0)
              root_received = rk;
          }
        }
        // "  arcs' paths: by the ranks, L by a rank ..., S straight; rank 0 received R KiB
        // (components C), sent ... KiB; a rank sent the others at most N KiB; T s".
        if (const std::size_t at = text.find("arcs' paths: by the ranks, ");
            at != std::string::npos) {
          const std::string line = text.substr(at, text.find('\n', at) - at);
          double r = 0, c = 0, nb = 0, t = 0;
          const std::size_t rec = line.find("rank 0 received"), most = line.find("at most");
          if (rec != std::string::npos && most != std::string::npos &&
              std::sscanf(line.c_str() + rec, "rank 0 received %lf KiB (components %lf)", &r, &c) ==
                  2 &&
              std::sscanf(line.c_str() + most, "at most %lf KiB; %lf s", &nb, &t) == 2) {
            arcs_received[n].push_back(r);
            arcs_reports[n].push_back(c);
            arcs_neighbour[n].push_back(nb);
            arcs_seconds[n].push_back(t);
          }
          const std::size_t from = std::string("arcs' paths: by the ranks, ").size();
          arcs_rounds[n] = line.substr(from, line.find(';') - from);
        }
        piece[n].push_back(max_piece);
        kept[n].push_back(max_kept);
        sent[n].push_back(max_sent);
        received[n].push_back(root_received);
        peak[n].push_back(max_peak);
      }
    }
    std::string flags;
    for (const std::string &f : input.flags)
      flags += " " + (f == vtp ? std::string("V") : f);
    std::printf("## MPI, %s: `mpirun --oversubscribe -np N hoct tree FILE --json J --no-timings "
                "--threads 1%s` (HOCT_MPI=1) on %lld %s, a fresh mpirun per run, rank counts "
                "alternated with one plain process (`hoct tree FILE --threads 1%s`): medians of "
                "%d runs; per rank, the largest over the ranks\n\n",
                input.label.c_str(), flags.c_str(), input.cells, input.mesh.c_str(), flags.c_str(),
                runs);
    std::printf("plain process: %.3f s\n\n", median(plain));
    std::printf("| ranks | whole (s) | 1 rank / N ranks | plain / N ranks | piece (s) | kept nodes "
                "| KiB sent | KiB rank 0 received | peak MiB | JSON as plain | checked and read by "
                "parts |\n|---|---|---|---|---|---|---|---|---|---|---|\n");
    const double one = median(whole[counts.front()]);
    for (int n : counts) {
      const double w = median(whole[n]);
      std::printf("| %d | %.3f | %.2fx | %.2fx | %.3f | %.0f | %.1f | %.1f | %.0f | %s | %s |\n", n,
                  w, one / w, median(plain) / w, median(piece[n]), median(kept[n]), median(sent[n]),
                  median(received[n]), median(peak[n]), same[n] ? "yes" : "NO",
                  by_pieces[n] ? "yes" : "NO");
      std::fflush(stdout);
    }
    std::printf("\n");
    if (arcs_received.empty())
      continue;
    std::printf("The arcs' drawing (from the summary's \"arcs' paths\" line): medians; the rounds "
                "of the last run\n\n| ranks | drawing (s) | KiB rank 0 received | of which "
                "reports | most KiB a rank sent the others | arcs drawn |\n"
                "|---|---|---|---|---|---|\n");
    for (int n : counts)
      if (!arcs_received[n].empty())
        std::printf("| %d | %.3f | %.1f | %.1f | %.1f | %s |\n", n, median(arcs_seconds[n]),
                    median(arcs_received[n]), median(arcs_reports[n]), median(arcs_neighbour[n]),
                    arcs_rounds[n].c_str());
    std::printf("\n");
  }
}

// Peak memory of `hoct tree FILE.vtu --json J --threads 1` in a process of its own (GNU time).
void memory_section(const Settings &s) {
  std::printf("## Peak memory of `hoct tree FILE.vtu --json J` (random fields; GNU time's maximum "
              "resident set)\n\n| degree | cells | peak MiB | bytes per cell | wall time (s) "
              "|\n|---|---|---|---|---|\n");
  for (int degree : s.degrees)
    for (double size : s.sizes) {
      ScratchDir scratch;
      const std::string vtu = scratch.file("random.vtu");
      const long long cells = write_random(vtu, size, degree);
      const ProcessPeak peak = run_process({executable_dir() + "/hoct", "tree", vtu, "--json",
                                            scratch.file("cli.json"), "--threads", "1", "-q"});
      std::printf("| %d | %lld | %.0f | %.0f | %.2f |\n", degree, cells, peak.max_rss_kib / 1024.0,
                  1024.0 * peak.max_rss_kib / static_cast<double>(cells), peak.seconds);
      std::fflush(stdout);
    }
  std::printf("\n");
}

void pl_section(const Settings &s) {
  const bool ttk = !s.ttk_ftm.empty();
  std::printf("## PL contour tree on large meshes (degree-1 `random` fields; median of %d "
              "runs, 1 thread)\n\n",
              s.runs);
  std::printf(
      "Warm: hoct's tree computed again in the benchmark's process (`pl_contour_tree`, the "
      "graph, sweeps, merge and pairs); cold: a fresh `hoct tree FILE.vtu --linear --threads 1` "
      "process per run, the same scope from its JSON (`time_tree_s`: the split into linear "
      "triangles is `time_pl_mesh_s`, left out, as the warm runs start from it).");
  if (ttk)
    std::printf(" Side by side with TTK's FTM (`%s`, an external driver built outside this "
                "repository from topology-tool-kit/ttk; TTK = triangulation preconditioning + "
                "order array + FTMTree::build, reading excluded): cold, a fresh driver process "
                "per run (`--runs 1`), alternated with hoct's cold runs; warm, the driver's "
                "median of %d runs in one process. Each ratio compares like with like. Peak: "
                "the maximum resident set of a cold process (hoct: reading the .vtu, the mesh "
                "checks, the split into triangles, the tree and its JSON; TTK: reading the "
                "binary mesh, the triangulation and the tree).",
                s.ttk_ftm.c_str(), s.runs);
  std::printf("\n\n| vertices | triangles | graph (s) | sweeps (s) | merge (s) | hoct warm (s) | "
              "hoct cold (s) | hoct peak (MiB) |%s\n|---|---|---|---|---|---|---|---|%s\n",
              ttk ? " TTK cold (s) | TTK warm (s) | hoct / TTK, cold | hoct / TTK, warm | TTK "
                    "peak (MiB) | hoct / TTK, peak | same critical points |"
                  : "",
              ttk ? "---|---|---|---|---|---|---|" : "");
  for (long long cells : s.quick ? std::vector<long long>{500000}
                                 : std::vector<long long>{500000, 2000000, 8000000}) {
    DatasetOptions o;
    o.cells = cells;
    o.degree = 1;
    ScratchDir scratch;
    const std::string vtu = scratch.file("pl.vtu"), json = scratch.file("cold.json");
    PlMesh pl;
    {
      const MeshInput in = generate_dataset("random", o);
      write_vtu(vtu, in);
      pl = split_lagrange_cells(in);
    }
    const std::string bin = scratch.file("pl.bin");
    if (ttk)
      write_pl_binary(bin, pl);
    std::vector<double> g, sw, m, total, cold, ttk_cold, cold_ratio, peak, ttk_peak;
    bool same = true;
    TreeResult r;
    for (int i = 0; i < s.runs; ++i) {
      const auto t = clock_type::now();
      r = pl_contour_tree(pl, false, "");
      total.push_back(seconds_since(t));
      g.push_back(r.stats.time.graph.value_or(0));
      sw.push_back(r.stats.time.sweeps.value_or(0));
      m.push_back(r.stats.time.merge.value_or(0) + r.stats.time.pairs.value_or(0));
      peak.push_back(run_process({executable_dir() + "/hoct", "tree", vtu, "--linear", "--json",
                                  json, "--threads", "1", "-q"})
                         .max_rss_kib /
                     1024.0);
      cold.push_back(json_stat(json, "time_tree_s"));
      if (ttk) {
        const std::string out = capture(s.ttk_ftm + " " + bin + " --runs 1 --threads 1");
        ttk_cold.push_back(field(out, "median", "total"));
        ttk_peak.push_back(field(out, "memory:", "peak_rss_mib"));
        cold_ratio.push_back(cold.back() / ttk_cold.back());
      }
    }
    std::printf("| %lld | %zu | %.3f | %.3f | %.3f | %.3f | %.3f | %.0f |",
                static_cast<long long>(pl.num_vertices()), pl.triangles.size(), median(g),
                median(sw), median(m), median(total), median(cold), median(peak));
    if (ttk) {
      const std::string out =
          capture(s.ttk_ftm + " " + bin + " --runs " + std::to_string(s.runs) + " --threads 1");
      const double warm = field(out, "median", "total");
      int64_t counts[3] = {0, 0, 0};
      for (const auto &n : r.nodes)
        ++counts[n.type == NodeType::Minimum ? 0 : n.type == NodeType::Maximum ? 1 : 2];
      same = field(out, "tree:", "minima") == counts[0] &&
             field(out, "tree:", "maxima") == counts[1] &&
             field(out, "tree:", "saddles") == counts[2];
      std::printf(" %.3f | %.3f | %.2f | %.2f | %.0f | %.2f | %s |", median(ttk_cold), warm,
                  median(std::move(cold_ratio)), median(total) / warm, median(ttk_peak),
                  median(peak) / median(ttk_peak), same ? "yes" : "NO");
    }
    std::printf("\n");
    std::fflush(stdout);
  }
  std::printf("\n");
}

} // namespace

int main(int argc, char **argv) {
  CLI::App app{"hoct benchmark: prints Markdown tables for docs/PERFORMANCE.md"};
  Settings s;
  app.add_option("--runs", s.runs, "Repetitions per measurement (medians are reported)")
      ->check(CLI::Range(1, 1000));
  app.add_flag("--quick", s.quick, "A smoke run: small sizes, few runs");
  app.add_option("--sections", s.sections,
                 "Sections to run: datasets, scaling, density, plateau, quads, reeb, memory, pl, "
                 "large, mpi, pieces")
      ->delimiter(',');
  app.add_option("--degrees", s.degrees, "Degrees of the scaling, density and memory sections")
      ->delimiter(',');
  app.add_option("--sizes", s.sizes, "Cell counts of the scaling section, e.g. 1e4,1e5")
      ->delimiter(',');
  app.add_option("--ttk-ftr", s.ttk_ftr,
                 "An external TTK FTR driver (reads the binary PL mesh, prints 'median ... "
                 "total=S' and 'graph: ... loops=N') to time side by side in the reeb section");
  app.add_option("--ttk-ftm", s.ttk_ftm,
                 "An external TTK FTM driver (reads the binary PL mesh, prints 'median ... "
                 "ftm=S total=S', 'tree: minima=N maxima=N saddles=N' and 'memory: "
                 "peak_rss_mib=M') to time side by side");
  CLI11_PARSE(app, argc, argv);
  if (s.quick) {
    s.runs = std::min(s.runs, 3);
    if (app.count("--sizes") == 0)
      s.sizes = {1e4, 1e5};
  }
  if (wants(s, "datasets"))
    datasets_section(s);
  if (wants(s, "scaling"))
    scaling_section(s, false);
  if (wants(s, "density"))
    scaling_section(s, true);
  if (wants(s, "plateau"))
    plateau_section(s);
  if (wants(s, "quads"))
    quads_section(s);
  if (wants(s, "reeb"))
    reeb_section(s);
  if (wants(s, "memory"))
    memory_section(s);
  if (wants(s, "pl"))
    pl_section(s);
  if (wants(s, "large"))
    large_section(s);
  if (wants(s, "mpi"))
    mpi_section(s);
  if (wants(s, "pieces")) // the sizes given, else 2e6 cells (1e5 with --quick)
    hoct::bench::pieces_section(app.count("--sizes") ? s.sizes
                                : s.quick            ? std::vector<double>{1e5}
                                                     : std::vector<double>{2e6},
                                s.runs);
  std::printf("peak resident memory of the benchmark: %.1f MiB\n", peak_rss_kib() / 1024.0);
  return 0;
}
