#include "distributed/distributed_tree.hpp"

#include "distributed/distributed_arc_paths.hpp"
#include "distributed/distributed_checks.hpp"
#include "distributed/mpi_exchange.hpp"

#include "exact/piece_arcs.hpp"
#include "exact/piece_codec.hpp"
#include "exact/piece_trees.hpp"
#include "exact/pl_piece_trees.hpp"
#include "exact/pl_reeb_pieces.hpp"
#include "exact/reeb_group.hpp"
#include "exact/reeb_pieces.hpp"
#include "mesh/duplicate_points.hpp"
#include "mesh/mesh.hpp"
#include "mesh/mesh_checks.hpp"
#include "mesh/mesh_partition.hpp"
#include "mesh/piece_surface.hpp"
#include "pipeline/compute_tree.hpp"
#include "pipeline/domain_check.hpp"
#include "pl/pl_mesh.hpp"
#include "util/error.hpp"
#include "util/parallel_for.hpp"
#include "util/stopwatch.hpp"
#include "util/uninitialized_vector.hpp"

#include <mpi.h>
#include <sys/resource.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <regex>
#include <string>
#include <type_traits>

namespace hoct {
namespace {

// Blocks of at most 1 GiB per MPI call (counts are ints).
constexpr int64_t kChunk = int64_t{1} << 30;

void send_bytes(MPI_Comm comm, const std::vector<std::byte> &bytes, int to, int tag) {
  const uint64_t n = bytes.size();
  MPI_Send(&n, 1, MPI_UINT64_T, to, tag, comm);
  for (uint64_t at = 0; at < n; at += kChunk)
    MPI_Send(bytes.data() + at, static_cast<int>(std::min<uint64_t>(kChunk, n - at)), MPI_BYTE, to,
             tag, comm);
}

std::vector<std::byte> receive_bytes(MPI_Comm comm, int from, int tag) {
  uint64_t n = 0;
  MPI_Recv(&n, 1, MPI_UINT64_T, from, tag, comm, MPI_STATUS_IGNORE);
  std::vector<std::byte> bytes(n);
  for (uint64_t at = 0; at < n; at += kChunk)
    MPI_Recv(bytes.data() + at, static_cast<int>(std::min<uint64_t>(kChunk, n - at)), MPI_BYTE,
             from, tag, comm, MPI_STATUS_IGNORE);
  return bytes;
}

void broadcast_string(MPI_Comm comm, std::string &s, int root) {
  uint64_t n = s.size();
  MPI_Bcast(&n, 1, MPI_UINT64_T, root, comm);
  s.resize(n);
  MPI_Bcast(s.data(), static_cast<int>(n), MPI_CHAR, root, comm);
}

// A collective step's end: if any rank failed (a non-empty message), every rank throws the
// lowest failing rank's message.
void agree(MPI_Comm comm, const std::string &failure, int rank, int ranks) {
  int first = failure.empty() ? ranks : rank;
  MPI_Allreduce(MPI_IN_PLACE, &first, 1, MPI_INT, MPI_MIN, comm);
  if (first == ranks)
    return;
  std::string message = failure;
  broadcast_string(comm, message, first);
  throw AgreedError(message);
}

// The whole mesh's scales from every piece's.
MeshScales reduce_scales(MPI_Comm comm, const MeshScales &own) {
  double v[9] = {own.min_value,  -own.max_value, -static_cast<double>(own.max_degree),
                 own.box[0][0],  own.box[0][1],  own.box[0][2],
                 -own.box[1][0], -own.box[1][1], -own.box[1][2]};
  MPI_Allreduce(MPI_IN_PLACE, v, 9, MPI_DOUBLE, MPI_MIN, comm);
  MeshScales s;
  s.min_value = v[0];
  s.max_value = -v[1];
  s.max_degree = static_cast<int>(-v[2]);
  s.box = {Vec3{v[3], v[4], v[5]}, Vec3{-v[6], -v[7], -v[8]}};
  return s;
}

// What only the whole mesh can tell (topology, duplicate vertices across pieces): the pieces
// do not report it.
bool whole_mesh_problem(Problem p) {
  return p == Problem::NonManifoldEdge || p == Problem::NonManifoldVertex ||
         p == Problem::NonOrientable || p == Problem::DuplicateVertices || p == Problem::EmptyMesh;
}

// A piece's problems named by the whole's cells, as text for rank 0.
std::string encode_problems(ProblemLog log, int64_t first_cell) {
  const std::regex one(R"(\b(cell|quadrilateral|triangle) (\d+))"),
      two(R"(\bcells (\d+) and (\d+))");
  auto shift = [&](const std::string &m) {
    std::string out;
    std::sregex_iterator it(m.begin(), m.end(), two), end;
    std::size_t last = 0;
    std::string tmp;
    for (; it != end; ++it) {
      tmp.append(m, last, static_cast<std::size_t>(it->position(0)) - last);
      tmp += "cells " + std::to_string(std::stoll((*it)[1]) + first_cell) + " and " +
             std::to_string(std::stoll((*it)[2]) + first_cell);
      last = static_cast<std::size_t>(it->position(0) + it->length(0));
    }
    tmp.append(m, last, std::string::npos);
    last = 0;
    for (std::sregex_iterator i(tmp.begin(), tmp.end(), one); i != end; ++i) {
      out.append(tmp, last, static_cast<std::size_t>(i->position(0)) - last);
      out += (*i)[1].str() + " " + std::to_string(std::stoll((*i)[2]) + first_cell);
      last = static_cast<std::size_t>(i->position(0) + i->length(0));
    }
    out.append(tmp, last, std::string::npos);
    return out;
  };
  if (first_cell > 0)
    log.rewrite_examples(shift);
  std::string s;
  auto put = [&](const std::string &x) { s += std::to_string(x.size()) + ":" + x; };
  for (const auto &[kind, r] : log.kinds()) {
    if (whole_mesh_problem(kind))
      continue;
    put(std::to_string(static_cast<int>(kind)));
    put(std::to_string(static_cast<int>(r.severity)));
    put(std::to_string(r.count));
    put(std::to_string(r.examples.size()));
    for (const std::string &e : r.examples)
      put(e);
  }
  return s;
}

void decode_problems(const std::string &s, ProblemLog &log) {
  std::size_t at = 0;
  auto get = [&] {
    const std::size_t colon = s.find(':', at);
    const std::size_t n = std::stoull(s.substr(at, colon - at));
    std::string x = s.substr(colon + 1, n);
    at = colon + 1 + n;
    return x;
  };
  while (at < s.size()) {
    const auto kind = static_cast<Problem>(std::stoi(get()));
    ProblemRecord r;
    r.severity = static_cast<Severity>(std::stoi(get()));
    r.count = std::stoll(get());
    const int n = std::stoi(get());
    for (int i = 0; i < n; ++i)
      r.examples.push_back(get());
    log.append(kind, r);
  }
}

// Every rank's string on rank 0, in rank order.
std::vector<std::string> gather_strings(MPI_Comm comm, const std::string &own) {
  std::vector<std::string> out;
  for (const std::vector<std::byte> &b :
       gather_bytes(comm, std::as_bytes(std::span<const char>(own.data(), own.size()))))
    out.emplace_back(reinterpret_cast<const char *>(b.data()), b.size());
  return out;
}

} // namespace

void agree_on_failure(const std::string &failure) { agree_on_failure(failure, MPI_COMM_WORLD); }

void agree_on_failure(const std::string &failure, MPI_Comm comm) {
  int rank = 0, ranks = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &ranks);
  agree(comm, failure, rank, ranks);
}

DistributedOutcome distributed_tree(const MeshInput &whole, const TreeRequest &rq) {
  return distributed_tree(whole, rq, MPI_COMM_WORLD);
}

namespace {

// The library's own communicator for one call (MPI_Comm_dup: collective, freed at the end).
class OwnComm {
public:
  explicit OwnComm(MPI_Comm of) { MPI_Comm_dup(of, &comm_); }
  ~OwnComm() { MPI_Comm_free(&comm_); }
  OwnComm(const OwnComm &) = delete;
  OwnComm &operator=(const OwnComm &) = delete;
  MPI_Comm get() const { return comm_; }

private:
  MPI_Comm comm_ = MPI_COMM_NULL;
};

DistributedOutcome distributed_tree_on(RankInput in, const MeshInput *whole, const TreeRequest &rq,
                                       MPI_Comm comm);

} // namespace

DistributedOutcome distributed_tree(const MeshInput &whole, const TreeRequest &rq, MPI_Comm comm) {
  const OwnComm own(comm);
  int rank = 0, ranks = 1;
  MPI_Comm_rank(own.get(), &rank);
  MPI_Comm_size(own.get(), &ranks);
  RankInput in;
  in.piece = partition_piece(whole, ranks, rank);
  in.first_triangle = triangles_before(whole, in.piece.first_cell);
  in.whole_cells = static_cast<int64_t>(whole.num_cells());
  in.whole_points = static_cast<int64_t>(whole.num_points());
  in.cells_split = !whole.lagrange_triangles_only();
  in.source = whole.source;
  in.field_name = whole.field_name;
  return distributed_tree_on(std::move(in), &whole, rq, own.get());
}

DistributedOutcome distributed_tree(RankInput in, const TreeRequest &rq, MPI_Comm comm) {
  const OwnComm own(comm);
  return distributed_tree_on(std::move(in), nullptr, rq, own.get());
}

namespace {

// Rank 0's part of distributed_arc_paths: the arcs of the trees compute_tree draws for `rq` (the
// reported one; with AllPaths the whole tree's too), named by the group of all pieces' nodes
// (`all`: PieceTrees::nodes or ReebGroup::nodes); parallel arcs in groups, by level in the
// order one process draws them (compute_arc_paths).
void draw_arcs(MPI_Comm comm, PieceArcGraph &piece, std::span<const PieceNode> all,
               const TreeRequest &rq, int threads, DistributedOutcome &d) {
  std::vector<TreeResult *> drawn;
  TreeOutcome &o = d.outcome;
  if (rq.arcs == ArcGeometry::AllPaths || !o.simplified)
    drawn.push_back(&o.tree);
  if (o.simplified)
    drawn.push_back(&*o.simplified);
  std::vector<ArcEnds> arcs;
  int32_t groups = 0;
  for (const TreeResult *t : drawn) {
    const std::vector<ArcEnds> more = tree_arc_ends(*t, all, groups);
    arcs.insert(arcs.end(), more.begin(), more.end());
  }
  std::vector<std::vector<Vec3>> paths =
      distributed_arc_paths(comm, piece, std::move(arcs), threads, &d.arc_paths);
  std::size_t at = 0;
  for (TreeResult *t : drawn) {
    t->arc_paths.resize(t->arcs.size());
    for (std::size_t i = 0; i < t->arcs.size(); ++i, ++at) {
      const auto &[lo, hi] = t->arcs[i];
      t->arc_paths[i] = paths[at].empty()
                            ? std::vector<Vec3>{t->nodes[lo].position, t->nodes[hi].position}
                            : std::move(paths[at]);
    }
    t->stats.time.arc_paths = d.arc_paths.seconds;
  }
}

DistributedOutcome distributed_tree_on(RankInput in, const MeshInput *whole, const TreeRequest &rq,
                                       MPI_Comm comm) {
  DistributedOutcome d;
  MPI_Comm_rank(comm, &d.rank);
  MPI_Comm_size(comm, &d.ranks);
  const int rank = d.rank, ranks = d.ranks;
  // The request is every rank's: its errors are thrown on every rank together.
  const bool linear = rq.method == TreeMethod::Linear, refined = rq.method == TreeMethod::Refine;
  if (refined && (rq.refine < 1 || rq.refine > 1024))
    throw AgreedError("refine: K must be between 1 and 1024, not " + std::to_string(rq.refine));
  if (rq.simplify && rq.augmented)
    throw AgreedError("simplification works on the reduced tree (drop --augmented)");
  const int threads = thread_count(rq.threads);
  Stopwatch clock;

  // 1. This rank's piece, built with the whole mesh's scales.
  const int64_t cells = in.whole_cells;
  MeshPiece &piece = in.piece;
  const int64_t begin = piece.first_cell;
  RankReport me;
  me.cells = static_cast<int64_t>(piece.input.num_cells());
  // The piece's points other pieces use too: its fans there are checked with theirs.
  const std::vector<std::array<int32_t, 2>> spans = std::move(piece.point_span);
  std::vector<uint8_t> open(spans.size());
  for (std::size_t i = 0; i < open.size(); ++i)
    open[i] = spans[i][0] != spans[i][1];
  MeshScales scales;
  MeshBuildOptions bo;
  bo.throw_on_error = false;
  bo.threads = threads;
  bo.whole_scales = [comm, &scales](const MeshScales &own) {
    return scales = reduce_scales(comm, own);
  };
  bo.open_points = open;
  // More ranks than cells: a rank without cells takes part in the collective steps only.
  const bool empty_piece = me.cells == 0;
  Mesh mesh;
  if (empty_piece) {
    scales = reduce_scales(comm, MeshScales{});
    mesh.complete = true;
  } else {
    mesh = build_mesh(piece.input, bo);
  }
  const double build_seconds = clock.lap();

  // 2. The checks: each piece's own, then (once every piece found its cells well formed) the
  // whole's seams, shape and duplicate vertices by all pieces together. Where they find
  // anything (or a piece found a problem of the whole's kinds), rank 0 checks the whole mesh
  // alone, for the report a run without MPI gives.
  int flags[2] = {mesh.complete ? 1 : 0, 0};
  for (const auto &[kind, r] : mesh.problems.kinds())
    if (whole_mesh_problem(kind))
      flags[1] = -1;
  MPI_Allreduce(MPI_IN_PLACE, flags, 2, MPI_INT, MPI_MIN, comm);
  const int complete = flags[0];
  if (flags[1] != 0)
    d.whole_check = "a piece found a problem of the whole mesh's kinds";
  const std::vector<std::string> logs = gather_strings(comm, encode_problems(mesh.problems, begin));
  SurfaceShape surface;
  if (complete) {
    const Topology &topo = mesh.topology;
    PieceSurface own;
    UninitializedVector<Vec3> positions;
    UninitializedVector<int64_t> ids;
    own = empty_piece ? empty_piece_surface(rank)
                      : summarize_piece(topo, piece.global_point, spans, rank, threads);
    if (!empty_piece && ranks > 1) { // one rank: its own duplicate check was the whole's
      positions.resize(static_cast<std::size_t>(topo.num_vertices()));
      ids.resize(positions.size());
      for (int64_t v = 0; v < topo.num_vertices(); ++v) {
        const int64_t p = topo.vertex_point(v); // a corner: one of the piece's input points
        positions[v] = piece.input.points[p];
        ids[v] = piece.global_point[p];
      }
    }
    surface = merge_surfaces(comm, std::move(own));
    const auto &[lo, hi] = scales.box;
    const double tolerance = 1e-10 * std::hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
    if (duplicate_vertices_across(comm, positions, ids, tolerance, scales.box, threads) &&
        d.whole_check.empty())
      d.whole_check = "vertices of different ids at the same position";
    if (!surface.seam_problem.empty() && d.whole_check.empty())
      d.whole_check = surface.seam_problem;
  }
  std::string failure;
  std::vector<std::string> warnings;
  // Rank 0 checks the whole mesh alone where the pieces found anything: the whole is joined on
  // rank 0 then (read_whole is collective: a caller's pieces come from every rank).
  int check_whole = rank == 0 && complete && cells > 0 && !d.whole_check.empty() ? 1 : 0;
  MeshInput loaded;
  if (!whole) {
    MPI_Bcast(&check_whole, 1, MPI_INT, 0, comm);
    if (check_whole) {
      try {
        loaded = in.read_whole();
      } catch (const std::exception &e) {
        failure = e.what();
      }
    }
  }
  int reeb = 0; // not a disk or a sphere: the Reeb graph (exact/reeb_pieces)
  if (rank == 0 && failure.empty()) {
    try {
      Mesh checked;
      checked.source = in.source;
      checked.complete = complete != 0;
      if (cells == 0) {
        checked.problems.add(Problem::EmptyMesh, "the mesh has no cells");
        checked.complete = false;
      }
      for (const std::string &log : logs)
        decode_problems(log, checked.problems);
      std::string shape;
      if (checked.complete && d.whole_check.empty()) {
        shape = domain_shape(surface);
      } else if (checked.complete) {
        const MeshInput &all = whole ? *whole : loaded;
        ProblemLog topology_problems;
        SplitCells split;
        const MeshInput *triangles = &all;
        if (!all.lagrange_triangles_only()) {
          ProblemLog ignored; // the pieces report the split's own problems
          split = split_cells(all, ignored, threads);
          triangles = &split.mesh;
        }
        const Topology topo = Topology::build(*triangles, topology_problems, threads);
        const std::array<Vec3, 2> box = bounding_box(triangles->points, threads);
        check_duplicate_vertices(*triangles, topo, topology_problems, threads, &box);
        checked.problems.append(topology_problems);
        shape = domain_shape(topo);
      }
      warnings = check_domain(checked, rq.force);
      reeb = !shape.empty();
    } catch (const std::exception &e) {
      failure = e.what();
    }
  }
  agree(comm, failure, rank, ranks);
  MPI_Bcast(&reeb, 1, MPI_INT, 0, comm);
  // The field's reference and precision (the whole's, as every piece computes them) from the
  // first rank with cells.
  int source = empty_piece ? ranks : rank;
  MPI_Allreduce(MPI_IN_PLACE, &source, 1, MPI_INT, MPI_MIN, comm);
  double field_scale[2] = {mesh.field.reference(), mesh.field.precision()};
  MPI_Bcast(field_scale, 2, MPI_DOUBLE, source, comm);
  // What the pieces do not compute, rank 0 computes from the whole mesh: the linear method's
  // Bezier or serendipity cells (whose PL mesh has points of its own) and the refine method's
  // mesh the pieces did not check (its PL vertices are counted with the whole's Euler
  // characteristic from their check).
  // Rank 0's tree of the whole mesh, as one process computes it (the mesh checked already, or
  // forced past).
  auto tree_of_whole = [&](const MeshInput &all) {
    MeshBuildOptions bo;
    bo.throw_on_error = false;
    bo.threads = threads;
    return compute_tree(build_mesh(all, bo), rq, &all);
  };
  std::string whole_reason;
  // The arcs are drawn by the pieces (distributed_arc_paths); an augmented tree's are straight,
  // as one process draws them.
  const bool pieces_draw = rq.arcs != ArcGeometry::None && !rq.augmented;
  if (linear || refined) {
    int other_cells = linear && !empty_piece && !nodal_lagrange_cells(piece.input) ? 1 : 0;
    MPI_Allreduce(MPI_IN_PLACE, &other_cells, 1, MPI_INT, MPI_MAX, comm);
    const std::string method = linear ? "the linear method's" : "the refine method's";
    if (rank == 0 && other_cells)
      whole_reason = method + " PL mesh of Bezier or serendipity cells has points of its own";
    else if (rank == 0 && refined && !d.whole_check.empty())
      whole_reason = method + " pieces need the mesh checked by them";
    broadcast_string(comm, whole_reason, 0);
  }
  if (!whole_reason.empty()) {
    d.whole_tree = whole_reason;
    const bool read = !whole && !check_whole; // rank 0 may hold the whole for the checks
    if (rank != 0) {
      if (read)
        in.read_whole();
      return d;
    }
    if (read)
      loaded = in.read_whole();
    d.outcome = tree_of_whole(whole ? *whole : loaded);
    return d;
  }

  // 3. The piece's kept trees, 4. merged in a binary tree of ranks (a Reeb graph's pieces as
  // groups, glued at every merge).
  PieceTrees trees;
  PieceArcGraph arc_graph; // the piece's graph, to draw the arcs (pieces_draw)
  ReebGroup group;         // a Reeb graph's pieces, glued at every merge (exact/reeb_group)
  TreeTimings time;
  PlPieceTrees pl; // the PL methods' counts: this piece's, then the whole's on rank 0
  try {
    const PiecePlace place{rank, piece.global_point, begin, in.first_triangle, spans};
    ExactTreeOptions eo;
    eo.augmented = rq.augmented;
    eo.threads = threads;
    eo.fallback_refinement = rq.fallback_refinement;
    if (empty_piece) {
      trees.first_piece = trees.last_piece = rank;
    } else if ((linear || refined) && reeb) { // the PL mesh cut into disks (pl_reeb_pieces)
      const PlPieceMesh m = linear ? linear_piece_mesh(piece.input, place)
                                   : refined_piece_mesh(mesh, place, rq.refine);
      pl.triangles = static_cast<int64_t>(m.pl.triangles.size());
      pl.own_points = m.own_points;
      pl.cell_points = m.cell_points;
      group = pl_reeb_group(m, place, rq.augmented, threads, pieces_draw ? &arc_graph : nullptr);
    } else if (linear || refined) {
      PieceArcGraph *arcs = pieces_draw ? &arc_graph : nullptr;
      pl = linear ? pl_piece_trees(piece.input, place, rq.augmented, threads, arcs)
                  : refined_piece_trees(mesh, place, rq.refine, rq.augmented, threads, arcs);
      trees = std::move(pl.trees);
    } else if (reeb) {
      trees = reeb_piece(mesh, place, eo, time, pieces_draw ? &arc_graph : nullptr);
    } else {
      trees = piece_trees(mesh, place, eo, time, pieces_draw ? &arc_graph : nullptr);
    }
    if (reeb && (empty_piece || !(linear || refined)))
      group = reeb_group(trees, rq.augmented);
  } catch (const std::exception &e) {
    failure = std::string(e.what());
  }
  agree(comm, failure, rank, ranks);
  me.piece_seconds = build_seconds + clock.seconds();
  me.kept_nodes =
      static_cast<int64_t>(reeb && (linear || refined) ? group.nodes.size() : trees.nodes.size());
  const double tree_start = clock.seconds();
  for (int step = 1; step < ranks; step *= 2) {
    if (rank % (2 * step) == step) {
      const std::vector<std::byte> bytes =
          reeb ? encode_reeb_group(group) : encode_piece_trees(trees);
      send_bytes(comm, bytes, rank - step, step);
      me.bytes_sent += static_cast<int64_t>(bytes.size());
      ++me.messages;
      break;
    }
    if (rank % (2 * step) == 0 && rank + step < ranks) {
      const std::vector<std::byte> bytes = receive_bytes(comm, rank + step, step);
      me.bytes_received += static_cast<int64_t>(bytes.size());
      ++me.messages;
      if (reeb)
        group = merge_reeb_groups(group, decode_reeb_group(bytes), rq.augmented);
      else
        trees = merge_piece_trees(trees, decode_piece_trees(bytes), rq.augmented, threads);
    }
  }
  PlCounts pl_counts;
  if (linear || refined) {
    int64_t counts[3] = {pl.triangles, pl.own_points, pl.cell_points};
    MPI_Reduce(rank == 0 ? MPI_IN_PLACE : counts, counts, 3, MPI_INT64_T, MPI_SUM, 0, comm);
    pl_counts = whole_pl_counts(counts[0], counts[1], counts[2], refined ? rq.refine : 0,
                                surface.euler_characteristic);
  }
  // Every rank's report on rank 0.
  struct rusage usage {};
  getrusage(RUSAGE_SELF, &usage);
  me.peak_bytes = static_cast<int64_t>(usage.ru_maxrss) * 1024;
  static_assert(std::is_trivially_copyable_v<RankReport>);
  if (rank == 0)
    d.reports.resize(static_cast<std::size_t>(ranks));
  MPI_Gather(&me, sizeof(RankReport), MPI_BYTE, d.reports.data(), sizeof(RankReport), MPI_BYTE, 0,
             comm);
  // The input's fingerprint (a pass over the whole input) by the last rank, idle by now, while
  // rank 0 finishes the tree.
  constexpr int kFingerprintTag = 1 << 20;
  // A Reeb graph's pieces may not follow one process (below): rank 0 then needs the whole,
  // which the ranks join together when they hold no whole input.
  const bool joined_whole = reeb && !whole;
  if (rank != 0) {
    if (rank == ranks - 1 && whole) {
      const uint64_t hash = mesh_fingerprint(*whole).hash;
      MPI_Send(&hash, 1, MPI_UINT64_T, 0, kFingerprintTag, comm);
    }
    int need = 0;
    if (joined_whole)
      MPI_Bcast(&need, 1, MPI_INT, 0, comm);
    if (need)
      in.read_whole();
    if (pieces_draw)
      distributed_arc_paths(comm, arc_graph, {}, threads);
    return d;
  }

  // 5. Rank 0: the whole tree, finished as compute_tree finishes it.
  const double reference = linear ? 0.0 : field_scale[0];
  TreeResult tree =
      reeb && (linear || refined)
          ? pl_reeb_graph_of_group(group, rq.augmented, method_name(rq), pl_counts, reference)
      : reeb ? reeb_graph_of_group(group, rq.augmented, reference)
      : linear || refined
          ? pl_tree_of_pieces(trees, rq.augmented, method_name(rq), pl_counts, reference)
          : tree_of_pieces(trees, rq.augmented, reference);
  const int64_t ties = tree.stats.seam_paths_nonmonotone.value_or(0);
  if (joined_whole) {
    int need = ties > 0 ? 1 : 0;
    MPI_Bcast(&need, 1, MPI_INT, 0, comm);
  }
  if (ties > 0) {
    // A seam piece whose path in the disks' tree does not rise (a tie with a fallback lattice
    // node on a plateau, typically between pieces, where one process has no seam): glued at its
    // ends only, it would make a loop one process does not. Rank 0 computes the graph from the
    // whole mesh.
    d.whole_tree = std::to_string(ties) + " seam piece(s) of the pieces' cuts do not rise: ties "
                                          "on a plateau";
    if (ranks > 1 && whole) {
      uint64_t ignored = 0;
      MPI_Recv(&ignored, 1, MPI_UINT64_T, ranks - 1, kFingerprintTag, comm, MPI_STATUS_IGNORE);
    }
    if (!whole)
      loaded = in.read_whole();
    d.outcome = tree_of_whole(whole ? *whole : loaded);
    return d;
  }
  time.tree = clock.seconds() - tree_start + (me.piece_seconds - build_seconds);
  time.gluing = tree.stats.time.gluing;
  tree.stats.time = time;
  TreeContext context;
  context.warnings = warnings;
  if (!whole)
    context.fingerprint = in.fingerprint;
  else if (ranks == 1)
    context.fingerprint = mesh_fingerprint(*whole);
  context.input_cells = cells;
  context.build_times = mesh.build_times;
  context.cells_split = in.cells_split;
  context.precision = field_scale[1];
  TreeRequest finish = rq;
  if (!finish.build_seconds)
    finish.build_seconds = build_seconds;
  if (pieces_draw)
    finish.arcs = ArcGeometry::None; // drawn below, by the pieces
  d.outcome = finish_tree(std::move(tree), finish, context);
  if (ranks > 1 && whole) {
    InputFingerprint f;
    f.points = in.whole_points;
    f.cells = cells;
    f.field = in.field_name;
    MPI_Recv(&f.hash, 1, MPI_UINT64_T, ranks - 1, kFingerprintTag, comm, MPI_STATUS_IGNORE);
    d.outcome.tree.input = f;
    if (d.outcome.simplified)
      d.outcome.simplified->input = f;
  }
  if (pieces_draw)
    draw_arcs(comm, arc_graph, reeb ? group.nodes : trees.nodes, rq, threads, d);
  return d;
}

} // namespace

} // namespace hoct
