#include "tree_mpi.hpp"

#include "io/read_limits.hpp"
#include "io/read_mesh.hpp"
#include "io/tree_json.hpp"
#include "io/tree_svg_writer.hpp"
#include "io/tree_vtp_writer.hpp"
#include "load_mesh.hpp"
#include "memory_guard.hpp"
#include "mesh/duplicate_points.hpp"
#include "mesh/gll_nodes.hpp"
#include "mesh/mesh_partition.hpp"
#include "tree_summary.hpp"
#include "util/error.hpp"
#include "util/parallel_for.hpp"
#include "util/stopwatch.hpp"

#ifdef HOCT_WITH_MPI
#include "distributed/distributed_read.hpp"
#include "distributed/distributed_tree.hpp"
#include "distributed/mpi_session.hpp"
#include "distributed/rank_join.hpp"
#include "distributed/scatter_whole.hpp"
#include "distributed/vtu_by_ranks.hpp"

#include <mpi.h>
#endif

#include <cstdio>
#include <cstdlib>
#include <filesystem>

namespace hoct::cli {

#ifdef HOCT_WITH_MPI

bool under_mpi() { return launched_by_mpi(); }

namespace {
// `collectives_done` is set once this rank takes part in no more collective step.
void run_ranks(const DistributedTreeRun &run, TreeRequest rq, bool root, bool &collectives_done);
void report(const DistributedTreeRun &run, const DistributedOutcome &d,
            const std::string &field_name, int64_t cells, const Stopwatch &total, int threads);
} // namespace

void run_tree_mpi(const DistributedTreeRun &run, TreeRequest rq) {
  static MpiSession session; // finalized at exit
  const bool root = session.rank() == 0;
  bool collectives_done = false;
  try {
    run_ranks(run, rq, root, collectives_done);
  } catch (const AgreedError &) {
    if (root)
      throw; // every rank has it: reported once, by rank 0
    std::exit(1);
  } catch (const std::exception &e) {
    if (!collectives_done && session.size() > 1) {
      // This rank's alone, and the others would wait for it at the next collective step.
      std::fprintf(stderr, "hoct: error (MPI rank %d): %s\n", session.rank(), e.what());
      MPI_Abort(MPI_COMM_WORLD, 1);
    }
    throw;
  }
}

namespace {

// --refine K: a rank's share of `cells` (the cells of `input` over `shares` ranks), refined,
// within the memory budget; refused on every rank if not (every rank's own check, agreed).
void check_refinement_share(const std::string &file, const TreeRequest &rq, const MeshInput &input,
                            int shares) {
  if (rq.method != TreeMethod::Refine)
    return;
  std::string failure;
  try {
    const int64_t triangles = triangles_before(input, static_cast<int64_t>(input.num_cells()));
    check_refinement_memory(file, (triangles + shares - 1) / shares, rq.refine,
                            " (a rank's share)");
  } catch (const std::exception &e) {
    failure = e.what();
  }
  agree_on_failure(failure);
}

// A file that is not partitioned, read whole (by rank 0): duplicates merged if asked, GLL nodes
// resampled (their notes printed with `notes`), as one process reads it.
MeshInput read_whole_file(const DistributedTreeRun &run, const ReadLimits &limits, bool notes) {
  MeshInput input = read_mesh(run.file, run.field, limits);
  if (run.merge_tolerance >= 0)
    merge_duplicate_points(input, run.merge_tolerance, limits.threads);
  const GllResampling g = resample_gll_cells(input);
  if (notes)
    print_gll_notes(run.file, g);
  return input;
}

void run_ranks(const DistributedTreeRun &run, TreeRequest rq, bool root, bool &collectives_done) {
  Stopwatch total;
  // One thread per rank unless asked: the ranks share the machine's cores.
  if (rq.threads == 0)
    rq.threads = 1;
  ReadLimits limits = read_limits();
  limits.threads = thread_count(rq.threads);
  // A partitioned file: each rank reads its own pieces, where the ranks can join them alone; a
  // .vtu: each rank reads its own part, where the file allows it.
  const std::string extension = std::filesystem::path(run.file).extension().string();
  const bool by_parts = (extension == ".pvtu" || extension == ".vtu") && run.merge_tolerance < 0;
  if (by_parts) {
    RankRead read;
    try {
      read = extension == ".pvtu" ? read_pvtu_by_ranks(run.file, run.field, limits, MPI_COMM_WORLD)
                                  : read_vtu_by_ranks(run.file, run.field, limits, MPI_COMM_WORLD);
    } catch (const std::exception &e) { // MPI's own limits (2 GiB a step): this rank's alone
      throw Error(run.file + ": " + e.what());
    }
    if (read.input) {
      if (root && !run.quiet && !read.note.empty())
        std::fprintf(stderr, "hoct: note: %s: %s\n", run.file.c_str(), read.note.c_str());
      // DOLFINx's degree >= 3 nodes at GLL points: each rank resamples its piece, as one
      // process resamples the whole.
      const GllResampling gll = resample_gll_share(*read.input, MPI_COMM_WORLD);
      if (root)
        print_gll_notes(run.file, gll);
      const std::string field_name = read.input->field_name;
      const int64_t cells = read.input->whole_cells;
      check_refinement_share(run.file, rq, read.input->piece.input, 1);
      rq.read_seconds = total.seconds();
      const DistributedOutcome d = distributed_tree(std::move(*read.input), rq, MPI_COMM_WORLD);
      collectives_done = true;
      if (root)
        report(run, d, field_name, cells, total, thread_count(rq.threads));
      return;
    }
    if (root && !run.quiet && extension == ".pvtu")
      std::fprintf(stderr,
                   "hoct: note: rank 0 reads the whole of %s and sends each rank its share (%s: "
                   "the ranks could not join its pieces alone)\n",
                   run.file.c_str(), read.fallback.c_str());
    else if (root && !run.quiet)
      std::fprintf(stderr,
                   "hoct: note: rank 0 reads the whole of %s and sends each rank its share (the "
                   "ranks could not read it by parts: %s)\n",
                   run.file.c_str(), read.fallback.c_str());
  }
  // Any other file: rank 0 reads it and sends each rank its share (no other rank reads it or
  // holds the whole); where the whole is needed again, rank 0 reads it again.
  MeshInput whole;
  std::string failure; // rank 0's errors are everyone's
  if (root)
    try {
      whole = read_whole_file(run, limits, /*notes=*/true);
      for (const std::string &w : whole.warnings)
        std::fprintf(stderr, "hoct: warning: %s\n", w.c_str());
    } catch (const std::exception &e) {
      failure = e.what();
    }
  agree_on_failure(failure);
  RankInput share = scatter_whole(root ? &whole : nullptr, MPI_COMM_WORLD);
  whole = MeshInput{};
  share.read_whole = [run, limits, root] {
    return root ? read_whole_file(run, limits, /*notes=*/false) : MeshInput{};
  };
  check_refinement_share(run.file, rq, share.piece.input, 1);
  rq.read_seconds = total.seconds();
  const std::string field_name = share.field_name;
  const int64_t cells = share.whole_cells;
  const DistributedOutcome d = distributed_tree(std::move(share), rq, MPI_COMM_WORLD);
  collectives_done = true; // from here on, errors are rank 0's, reported as without MPI
  if (root)
    report(run, d, field_name, cells, total, thread_count(rq.threads));
}

// Rank 0: the outputs and the summary.
void report(const DistributedTreeRun &run, const DistributedOutcome &d,
            const std::string &field_name, int64_t cells, const Stopwatch &total, int threads) {
  const TreeResult &tree = d.outcome.reported();
  for (const auto &why : d.outcome.warnings)
    std::fprintf(stderr, "hoct: warning: --force: %s\n", why.c_str());
  if (!run.svg.empty() && tree.branches.empty())
    throw Error("--svg draws the reduced tree (drop --augmented)");
  if (!run.json.empty())
    write_tree_json(run.json, tree, /*timings=*/!run.no_timings, threads);
  if (!run.vtp.empty())
    write_tree_vtp(run.vtp, tree);
  if (!run.svg.empty())
    write_tree_svg(run.svg, tree,
                   std::filesystem::path(run.file).filename().string() + ": " + tree.method +
                       (tree.reeb_graph ? " Reeb graph, " : " contour tree, ") +
                       std::to_string(tree.nodes.size()) + " nodes");
  if (!run.quiet) {
    std::printf("%s: field '%s', %lld cells, %s %s over %d MPI ranks\n", run.file.c_str(),
                field_name.c_str(), static_cast<long long>(cells), tree.method.c_str(),
                tree.reeb_graph ? graph_kind(tree).c_str() : "contour tree", d.ranks);
    print_tree_body(tree, total.seconds());
    if (!d.whole_tree.empty())
      std::printf("  tree: the whole mesh on rank 0 (%s)\n", d.whole_tree.c_str());
    if (const ArcPathCounts &a = d.arc_paths; a.arcs > 0)
      std::printf("  arcs' paths: by the ranks, %lld by a rank holding both ends, %lld across "
                  "ranks within their values, %lld below, %lld above, %lld anywhere, %lld "
                  "straight; rank 0 "
                  "received %.1f KiB (components %.1f), sent %.1f KiB; a rank sent the others "
                  "at most %.1f KiB; %.3f s\n",
                  static_cast<long long>(a.local), static_cast<long long>(a.routed[0]),
                  static_cast<long long>(a.routed[1]), static_cast<long long>(a.routed[2]),
                  static_cast<long long>(a.routed[3]), static_cast<long long>(a.straight),
                  a.bytes_received / 1024.0, a.component_bytes / 1024.0, a.bytes_sent / 1024.0,
                  a.neighbour_bytes / 1024.0, a.seconds);
    if (d.whole_check.empty())
      std::printf("  checks: by the pieces together (seams, shape, duplicate vertices)\n");
    else
      std::printf("  checks: the whole mesh on rank 0 (the pieces found: %s)\n",
                  d.whole_check.c_str());
    if (!d.reports.empty())
      std::printf("  ranks (cells, kept nodes, bytes sent / received, peak memory, piece time):\n");
    for (std::size_t k = 0; k < d.reports.size(); ++k) {
      const RankReport &q = d.reports[k];
      std::printf("    %zu: %lld cells, %lld kept, %.1f / %.1f KiB, %.0f MiB, %.3f s\n", k,
                  static_cast<long long>(q.cells), static_cast<long long>(q.kept_nodes),
                  q.bytes_sent / 1024.0, q.bytes_received / 1024.0, q.peak_bytes / 1048576.0,
                  q.piece_seconds);
    }
  }
  if (run.branches)
    print_branches(tree);
}

} // namespace

#else

bool under_mpi() { return false; }

void run_tree_mpi(const DistributedTreeRun &, TreeRequest) {
  throw Error("this hoct was built without MPI (Debian: libopenmpi-dev)");
}

#endif

} // namespace hoct::cli
