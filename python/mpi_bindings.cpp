#include "mpi_bindings.hpp"

#include "argument_checks.hpp"
#include "array_input.hpp"
#include "py_types.hpp"
#include "util/error.hpp"
#include "util/parallel_for.hpp"
#ifdef HOCT_WITH_MPI
#include "distributed/distributed_read.hpp"
#include "distributed/distributed_tree.hpp"
#include "distributed/pieces_gather.hpp"
#include "distributed/rank_join.hpp"
#include "distributed/vtu_by_ranks.hpp"
#include "io/read_mesh.hpp"
#include "mesh/gll_nodes.hpp"

#include <mpi.h>
#endif

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cctype>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace py = pybind11;

namespace hoct::python {
namespace {

// One rank's piece: its share joined with the other ranks' (or, where the ranks could not join
// the pieces alone, the whole mesh on every rank, and why).
struct PyPiece {
#ifdef HOCT_WITH_MPI
  std::optional<RankInput> share;
  std::optional<MeshInput> whole;
  MPI_Comm comm = MPI_COMM_NULL;
#endif
  std::string whole_why;
  int64_t cells = 0, whole_cells = 0, whole_points = 0;
  std::string source, field_name;
};

#ifndef HOCT_WITH_MPI
[[noreturn]] void no_mpi(const std::string &what) {
  throw Error(what + ": this hoct was built without MPI (Debian: libopenmpi-dev), so it cannot "
                     "use comm");
}
#else
MPI_Comm running_comm(long long fortran_comm, const std::string &what) {
  int initialized = 0, finalized = 0;
  MPI_Initialized(&initialized);
  MPI_Finalized(&finalized);
  if (!initialized || finalized)
    throw Error(what + ": comm given but MPI is not running in this process (import "
                       "mpi4py.MPI first)");
  return MPI_Comm_f2c(static_cast<MPI_Fint>(fortran_comm));
}

// Runs a collective step: an AgreedError every rank raises; any other exception is this rank's
// alone, and the others would wait for it at their next collective step: the job is aborted.
template <class F> auto collective(MPI_Comm comm, F &&f) {
  try {
    return f();
  } catch (const AgreedError &) {
    throw;
  } catch (const std::exception &e) {
    int ranks = 1, rank = 0;
    MPI_Comm_size(comm, &ranks);
    MPI_Comm_rank(comm, &rank);
    if (ranks > 1) {
      std::fprintf(stderr, "hoct: error (MPI rank %d): %s\n", rank, e.what());
      MPI_Abort(comm, 1);
    }
    throw;
  }
}

// The tree over `comm` for contour_tree's request, by `compute` (a distributed_tree
// call, the GIL released): the Tree on rank 0, None on the others. With `arc_paths`, the ranks'
// pieces draw the reported tree's arcs on the surface (no rank holds the whole graph).
template <class F> py::object tree_over(MPI_Comm comm, TreeRequest rq, bool arc_paths, F compute) {
  rq.arcs = arc_paths ? ArcGeometry::Paths : ArcGeometry::None;
  std::optional<DistributedOutcome> d;
  {
    py::gil_scoped_release release;
    d = collective(comm, [&] { return compute(rq); });
  }
  if (d->rank != 0)
    return py::none();
  TreeOutcome &out = d->outcome;
  return py::cast(PyTree{out.simplified ? std::move(*out.simplified) : std::move(out.tree)});
}

// A piece of this rank's share.
PyPiece share_piece(RankInput share, const std::string &source, MPI_Comm comm) {
  PyPiece p;
  p.cells = static_cast<int64_t>(share.piece.input.num_cells());
  p.whole_cells = share.whole_cells;
  p.whole_points = share.whole_points;
  p.field_name = share.field_name;
  p.share = std::move(share);
  p.source = source;
  p.comm = comm;
  return p;
}

// A piece that is the whole mesh (on every rank), and why.
PyPiece whole_piece(MeshInput whole, const std::string &why, const std::string &source,
                    MPI_Comm comm) {
  PyPiece p;
  p.whole_why = why;
  p.cells = p.whole_cells = static_cast<int64_t>(whole.num_cells());
  p.whole_points = static_cast<int64_t>(whole.num_points());
  p.field_name = whole.field_name;
  p.whole = std::move(whole);
  p.source = source;
  p.comm = comm;
  return p;
}

// The piece from this rank's pieces (`failure`: why it has none), joined with the other ranks'.
PyPiece joined_piece(std::vector<FilePiece> pieces, const std::string &failure,
                     const std::string &source, int threads, MPI_Comm comm,
                     const std::function<MeshInput()> &whole_everywhere,
                     const std::function<MeshInput()> &whole_on_root) {
  ReadLimits limits;
  limits.threads = threads;
  RankRead read = join_rank_pieces(std::move(pieces), failure, source, limits, comm);
  if (!read.input)
    return whole_piece(whole_everywhere(), read.fallback, source, comm);
  read.input->read_whole = whole_on_root;
  return share_piece(std::move(*read.input), source, comm);
}
#endif

// read_pieces(path, comm): a .pvtu, each rank reading its own pieces; a .vtu, each its own part.
PyPiece read_pieces(const std::string &path, const std::string &scalar,
                    const std::string &max_memory, int threads, long long fortran_comm) {
#ifdef HOCT_WITH_MPI
  const MPI_Comm comm = running_comm(fortran_comm, "read_pieces");
  ReadLimits limits = read_limits_for(py_checks::no_nul(max_memory, "read_pieces: max_memory"));
  limits.threads = thread_count(threads);
  const FieldSelection field(py_checks::no_nul(scalar, "read_pieces: scalar"));
  py_checks::no_nul(path, "read_pieces: path");
  return collective(comm, [&] {
    std::string extension = std::filesystem::path(path).extension().string();
    for (char &c : extension)
      c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    const bool vtu = extension == ".vtu";
    RankRead read = vtu ? read_vtu_by_ranks(path, field, limits, comm)
                        : read_pvtu_by_ranks(path, field, limits, comm);
    if (read.input) {
      // DOLFINx's degree >= 3 nodes at GLL points, resampled piece by piece as hoct.read
      // resamples the whole.
      resample_gll_share(*read.input, comm);
      return share_piece(std::move(*read.input), path, comm);
    }
    // Every rank reads the whole file, which reports what is wrong.
    std::string failure;
    MeshInput whole;
    try {
      whole = read_mesh(path, field, limits);
      resample_gll_cells(whole);
    } catch (const std::exception &e) {
      failure = e.what();
    }
    agree_on_failure(failure, comm);
    return whole_piece(std::move(whole), read.fallback, path, comm);
  });
#else
  (void)path, (void)scalar, (void)max_memory, (void)threads, (void)fortran_comm;
  no_mpi("read_pieces");
#endif
}

#ifdef HOCT_WITH_MPI
// A rank's arrays as piece_from_arrays got them, held (not copied) for the joins that need the
// rank's piece again (the whole on rank 0 or on every rank): its FilePiece is made from them
// when asked, so that the rank holds its joined share alone meanwhile.
struct RankArrays {
  // The caller's arrays (Python objects: DoubleArray and IndexArray, not copied).
  py::object points, values, global_ids, ghost_cells;
  std::vector<py::object> blocks, types;
  std::string field_name;
  bool float32_points = false, float32_values = false;
  int rank = 0;

  // Released with the GIL, whichever thread drops the last reference (null handles are left
  // for the members' own destructors).
  ~RankArrays() {
    py::gil_scoped_acquire gil;
    points = values = global_ids = ghost_cells = py::object();
    blocks.clear();
    types.clear();
  }

  // This rank's piece (none if it has no cells); throws what is wrong with the arrays. Takes
  // the GIL: callers may have released it.
  std::vector<FilePiece> pieces() const {
    py::gil_scoped_acquire gil;
    std::vector<IndexArray> block_arrays, type_arrays;
    for (const py::object &b : blocks)
      block_arrays.push_back(py::cast<IndexArray>(b));
    for (const py::object &t : types)
      type_arrays.push_back(py::cast<IndexArray>(t));
    const auto global_ids = py::cast<IndexArray>(this->global_ids);
    const auto ghost_cells = py::cast<IndexArray>(this->ghost_cells);
    FilePiece p;
    p.input = input_from_arrays(py::cast<DoubleArray>(points), block_arrays, type_arrays,
                                py::cast<DoubleArray>(values), field_name, float32_points,
                                float32_values);
    p.input.source = "the arrays of rank " + std::to_string(rank);
    p.file = p.input.source;
    const auto n = static_cast<py::ssize_t>(p.input.num_points());
    if (global_ids.size() > 0) {
      if (global_ids.ndim() != 1 || global_ids.shape(0) != n)
        throw Error("piece_from_arrays: global_ids must have one entry per point (" +
                    std::to_string(n) + "), not " + std::to_string(global_ids.size()));
      p.arrays.global_ids.assign(global_ids.data(), global_ids.data() + n);
      p.arrays.global_ids_name = "global_ids";
    }
    const auto cells = static_cast<py::ssize_t>(p.input.num_cells());
    if (ghost_cells.size() > 0) {
      if (ghost_cells.ndim() != 1 || ghost_cells.shape(0) != cells)
        throw Error("piece_from_arrays: ghost_cells must have one entry per cell (" +
                    std::to_string(cells) + "), not " + std::to_string(ghost_cells.size()));
      p.arrays.cell_ghost.resize(static_cast<std::size_t>(cells));
      for (py::ssize_t c = 0; c < cells; ++c) {
        // vtkGhostType's DUPLICATECELL: a copy of a cell another rank owns.
        p.arrays.cell_ghost[c] = ghost_cells.data()[c] != 0 ? 1 : 0;
        p.arrays.ghost_cells += p.arrays.cell_ghost[c];
      }
    }
    std::vector<FilePiece> out;
    if (p.input.num_cells() > 0)
      out.push_back(std::move(p));
    return out;
  }
};
#endif

// piece_from_arrays(...): this rank's arrays (`failure`: why it has none, found by the
// package's checks), with global point ids (empty: none) and ghost cells (empty: none).
PyPiece piece_from_arrays(const DoubleArray &points, const std::vector<IndexArray> &blocks,
                          const std::vector<IndexArray> &types, const DoubleArray &values,
                          const std::string &field_name, bool float32_points, bool float32_values,
                          const IndexArray &global_ids, const IndexArray &ghost_cells,
                          const std::string &failure, int threads, long long fortran_comm) {
#ifdef HOCT_WITH_MPI
  const MPI_Comm comm = running_comm(fortran_comm, "piece_from_arrays");
  std::string problem = failure;
  auto arrays = std::make_shared<RankArrays>();
  MPI_Comm_rank(comm, &arrays->rank);
  arrays->points = points;
  arrays->values = values;
  arrays->blocks.assign(blocks.begin(), blocks.end());
  arrays->types.assign(types.begin(), types.end());
  arrays->global_ids = global_ids;
  arrays->ghost_cells = ghost_cells;
  arrays->field_name = field_name;
  arrays->float32_points = float32_points;
  arrays->float32_values = float32_values;
  std::vector<FilePiece> own;
  if (problem.empty()) {
    try {
      own = arrays->pieces();
    } catch (const std::exception &e) {
      problem = e.what();
    }
  }
  // A rank's own problem is every rank's (with its number), before any join.
  const std::string rank = std::to_string(arrays->rank);
  agree_on_failure(problem.empty() ? problem : "rank " + rank + ": " + problem, comm);
  const int t = thread_count(threads);
  const std::string where = "the ranks' arrays";
  py::gil_scoped_release release;
  return collective(comm, [&] {
    return joined_piece(
        std::move(own), "", where, t, comm,
        [&] {
          std::string why;
          MeshInput whole;
          try {
            whole = join_pieces_everywhere(arrays->pieces(), where, t, comm);
          } catch (const std::exception &e) {
            why = e.what();
          }
          agree_on_failure(why, comm);
          return whole;
        },
        [arrays, where, t, comm] { return join_pieces_on_root(arrays->pieces(), where, t, comm); });
  });
#else
  (void)points, (void)blocks, (void)types, (void)values, (void)field_name, (void)float32_points,
      (void)float32_values, (void)global_ids, (void)ghost_cells, (void)failure, (void)threads,
      (void)fortran_comm;
  no_mpi("piece_from_arrays");
#endif
}

// The tree (by any method) over the ranks of an MPI communicator (mpi4py's, by its Fortran
// rank holds the whole mesh and calls this; rank 0 gets the tree, the others None.
py::object contour_tree_mpi(const PyMesh &m, long long fortran_comm, const std::string &method,
                            int refine, int threads, bool keep_flat, bool force, bool augmented,
                            const std::string &simplify, bool arc_paths) {
#ifdef HOCT_WITH_MPI
  const MPI_Comm comm = running_comm(fortran_comm, "contour_tree");
  return tree_over(
      comm, tree_request(method, refine, threads, keep_flat, force, augmented, simplify), arc_paths,
      [&](const TreeRequest &rq) { return distributed_tree(m.input, rq, comm); });
#else
  (void)m, (void)fortran_comm, (void)method, (void)refine, (void)threads, (void)keep_flat,
      (void)force, (void)augmented, (void)simplify, (void)arc_paths;
  no_mpi("contour_tree");
#endif
}

// The same from each rank's piece (over the communicator the piece was joined on, or one
// congruent with it).
py::object contour_tree_piece(const PyPiece &p, long long fortran_comm, const std::string &method,
                              int refine, int threads, bool keep_flat, bool force, bool augmented,
                              const std::string &simplify, bool arc_paths) {
#ifdef HOCT_WITH_MPI
  const MPI_Comm comm = running_comm(fortran_comm, "contour_tree");
  int same = MPI_UNEQUAL;
  MPI_Comm_compare(comm, p.comm, &same);
  if (same != MPI_IDENT && same != MPI_CONGRUENT)
    throw Error("contour_tree: comm is not the communicator the piece was made on");
  return tree_over(comm,
                   tree_request(method, refine, threads, keep_flat, force, augmented, simplify),
                   arc_paths, [&](const TreeRequest &rq) {
                     return p.share ? distributed_tree(RankInput(*p.share), rq, comm)
                                    : distributed_tree(*p.whole, rq, comm);
                   });
#else
  (void)p, (void)fortran_comm, (void)method, (void)refine, (void)threads, (void)keep_flat,
      (void)force, (void)augmented, (void)simplify, (void)arc_paths;
  no_mpi("contour_tree");
#endif
}

} // namespace

void bind_mpi(py::module_ &m) {
  py::class_<PyPiece>(m, "Piece",
                      "One rank's piece of a mesh spread over the ranks of an MPI communicator "
                      "(read_pieces, piece_from_arrays), for contour_tree(piece, comm=...): "
                      "num_cells (this rank's share of the input cells), whole_cells, "
                      "whole_points, field_name, source, and whole_on_every_rank (None, or why "
                      "every rank holds the whole mesh instead)")
      .def_property_readonly("num_cells", [](const PyPiece &p) { return p.cells; })
      .def_property_readonly("whole_cells", [](const PyPiece &p) { return p.whole_cells; })
      .def_property_readonly("whole_points", [](const PyPiece &p) { return p.whole_points; })
      .def_property_readonly("field_name", [](const PyPiece &p) { return p.field_name; })
      .def_property_readonly("source", [](const PyPiece &p) { return p.source; })
      .def_property_readonly("whole_on_every_rank", [](const PyPiece &p) -> py::object {
        if (p.whole_why.empty())
          return py::none();
        return py::str(p.whole_why);
      });
  m.def("read_pieces", &read_pieces, py::call_guard<py::gil_scoped_release>());
  m.def("piece_from_arrays", &piece_from_arrays);
  m.def("contour_tree_mpi", &contour_tree_mpi);
  m.def("contour_tree_piece", &contour_tree_piece);
}

} // namespace hoct::python
