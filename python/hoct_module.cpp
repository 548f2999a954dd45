// Python bindings (pybind11): a thin layer over the library, exposing meshes and trees as
// numpy arrays. The Python package `hoct` (python/hoct/__init__.py) adds the conveniences.
#include "argument_checks.hpp"
#include "array_input.hpp"
#include "datasets/datasets.hpp"
#include "io/read_mesh.hpp"
#include "io/tree_json.hpp"
#include "io/tree_svg_writer.hpp"
#include "io/tree_vtp_writer.hpp"
#include "io/vtk_cells.hpp"
#include "mesh/duplicate_points.hpp"
#include "mesh/gll_nodes.hpp"
#include "mesh/mesh.hpp"
#include "mpi_bindings.hpp"
#include "pipeline/compute_tree.hpp"
#include "py_types.hpp"
#ifdef HOCT_WITH_VTK
#include "vtkio/vtk_file_reader.hpp"
#endif
#ifdef HOCT_WITH_MPI
#include "distributed/distributed_tree.hpp"

#include <mpi.h>
#endif
#include "pipeline/domain_check.hpp"
#include "poly/lagrange_node_order.hpp"
#include "tree/merge_tree.hpp"
#include "tree/tree_result.hpp"
#include "util/error.hpp"
#include "util/parallel_for.hpp"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cstdio>
#include <memory>
#include <optional>

namespace py = pybind11;
using namespace hoct;
using py_checks::no_nul;

using python::PyMesh;
using python::PyTree;
using python::tree_request;

namespace {

template <class T> py::array_t<T> array_1d(const std::vector<T> &v) {
  py::array_t<T> a(static_cast<py::ssize_t>(v.size()));
  std::copy(v.begin(), v.end(), a.mutable_data());
  return a;
}

// The mesh built on `threads` threads (0 = every hardware thread, as the command line's default;
// the same mesh for any number). Problems a forced tree can go past (inverted cells, duplicate
// vertices) are left to contour_tree, as `hoct tree` does; any other makes it throw here.
PyMesh make_mesh(MeshInput in, int threads = 0) {
  PyMesh m;
  m.input = std::move(in);
  m.mesh = std::make_shared<Mesh>(
      build_mesh(m.input, {.throw_on_error = false, .threads = thread_count(threads)}));
  require_valid_mesh(*m.mesh, /*allow_forceable=*/true);
  return m;
}

// hoct.from_arrays: the arrays as an input (python/array_input), built.
PyMesh from_arrays(py::array_t<double, py::array::c_style | py::array::forcecast> points,
                   const std::vector<py::array_t<int64_t, py::array::c_style>> &blocks,
                   const std::vector<py::array_t<int64_t, py::array::c_style>> &types,
                   py::array_t<double, py::array::c_style | py::array::forcecast> values,
                   double merge_tolerance, const std::string &field_name, bool float32_points,
                   bool float32_values) {
  MeshInput in = python::input_from_arrays(points, blocks, types, values, field_name,
                                           float32_points, float32_values);
  if (merge_tolerance >= 0)
    merge_duplicate_points(in, merge_tolerance, thread_count(0));
  return make_mesh(std::move(in));
}

PyTree py_contour_tree(const PyMesh &m, const std::string &method, int refine, int threads,
                       bool keep_flat, bool force, bool augmented, const std::string &simplify) {
  TreeRequest rq = tree_request(method, refine, threads, keep_flat, force, augmented, simplify);
  rq.arcs = ArcGeometry::Graph;
  TreeOutcome out = compute_tree(*m.mesh, rq, &m.input);
  return {out.simplified ? std::move(*out.simplified) : std::move(out.tree)};
}

py::dict merge_tree_dict(const PyTree &t, bool join) {
  // The join (split) tree of the contour tree's nodes: parent of each node (-1 at the root).
  std::vector<GraphEdge> edges;
  std::vector<double> values;
  for (const auto &n : t.tree.nodes)
    values.push_back(n.value);
  for (const auto &a : t.tree.arcs)
    edges.push_back({a[0], a[1]});
  const ScalarGraph g(values, edges);
  const MergeTree mt = join ? join_tree(g) : split_tree(g);
  py::dict d;
  d["parent"] = array_1d(mt.parent);
  return d;
}

} // namespace

PYBIND11_MODULE(_hoct, m) {
  m.doc() = "hoct: exact contour trees of piecewise-polynomial fields (native part)";
#ifdef HOCT_WITH_VTK
  hoct::vtkio::register_vtk_reader(); // legacy .vtk, XDMF, Exodus II, LZ4/LZMA .vtu
#endif
  // Messages quote file names and file contents: made a str with any NUL and invalid UTF-8
  // kept visible (PyErr_SetString would end it at a NUL, or fail on the bytes).
  static py::exception<Error> hoct_error(m, "HoctError", PyExc_ValueError);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p)
        std::rethrow_exception(p);
    } catch (const Error &e) {
      const std::string what = e.what();
      py::object text = py::reinterpret_steal<py::object>(PyUnicode_DecodeUTF8(
          what.data(), static_cast<py::ssize_t>(what.size()), "backslashreplace"));
      PyErr_SetObject(hoct_error.ptr(), text.ptr());
    }
  });

  py::class_<PyMesh>(m, "Mesh")
      .def_property_readonly("num_cells",
                             [](const PyMesh &x) { return x.mesh->topology.num_cells(); })
      .def_property_readonly("num_points", [](const PyMesh &x) { return x.mesh->num_points; })
      .def_property_readonly(
          "euler_characteristic",
          [](const PyMesh &x) { return x.mesh->topology.euler_characteristic(); })
      .def_property_readonly("boundary_loops",
                             [](const PyMesh &x) { return x.mesh->topology.boundary_loops(); })
      .def_property_readonly("value_range",
                             [](const PyMesh &x) {
                               return std::make_pair(x.mesh->field.min_value(),
                                                     x.mesh->field.max_value());
                             })
      .def_property_readonly("degrees",
                             [](const PyMesh &x) {
                               std::vector<int> d(x.input.cell_degree.begin(),
                                                  x.input.cell_degree.end());
                               return array_1d(d);
                             })
      .def_property_readonly("source", [](const PyMesh &x) { return x.mesh->source; })
      .def_property_readonly("field_name", [](const PyMesh &x) { return x.mesh->field_name; })
      .def_property_readonly(
          "fingerprint",
          [](const PyMesh &x) -> py::object {
            if (!x.mesh->fingerprint)
              return py::none();
            return py::str(x.mesh->fingerprint->hex());
          },
          "The 16 hexadecimal digits of the hash of the points, cells, degrees and node values "
          "(the same for the same data in any file format); a tree's input['fingerprint']")
      .def("value", [](const PyMesh &x, int64_t cell, double u, double v) {
        py_checks::eval_point(cell, u, v, x.mesh->topology.num_cells());
        return x.mesh->field.value(cell, u, v);
      });

  py::class_<PyTree>(m, "Tree")
      .def_property_readonly("method", [](const PyTree &t) { return t.tree.method; })
      // "contour tree", or "Reeb graph" on a domain that is not a disk or a sphere (its level
      // sets may form loops: `loops` of them, parallel arcs in `arcs`).
      .def_property_readonly(
          "kind", [](const PyTree &t) { return t.tree.reeb_graph ? "Reeb graph" : "contour tree"; })
      .def_property_readonly("loops", [](const PyTree &t) { return t.tree.loops; })
      .def_property_readonly(
          "input",
          [](const PyTree &t) -> py::object {
            if (!t.tree.input)
              return py::none();
            py::dict d;
            d["points"] = t.tree.input->points;
            d["cells"] = t.tree.input->cells;
            d["field"] = t.tree.input->field;
            d["fingerprint"] = t.tree.input->hex();
            return d;
          },
          "The mesh the tree was computed from, as its JSON's \"input\" records it: points, "
          "cells, field and fingerprint (Mesh.fingerprint)")
      .def_property_readonly(
          "positions",
          [](const PyTree &t) {
            py::array_t<double> a({static_cast<py::ssize_t>(t.tree.nodes.size()), py::ssize_t{3}});
            auto w = a.mutable_unchecked<2>();
            for (std::size_t i = 0; i < t.tree.nodes.size(); ++i)
              for (int k = 0; k < 3; ++k)
                w(static_cast<py::ssize_t>(i), k) = t.tree.nodes[i].position[k];
            return a;
          })
      .def_property_readonly("values",
                             [](const PyTree &t) {
                               std::vector<double> v;
                               for (const auto &n : t.tree.nodes)
                                 v.push_back(n.value);
                               return array_1d(v);
                             })
      .def_property_readonly("types",
                             [](const PyTree &t) {
                               std::vector<std::string> v;
                               for (const auto &n : t.tree.nodes)
                                 v.push_back(to_string(n.type));
                               return v;
                             })
      .def_property_readonly("locations",
                             [](const PyTree &t) {
                               std::vector<std::string> v;
                               for (const auto &n : t.tree.nodes)
                                 v.push_back(to_string(n.location));
                               return v;
                             })
      .def_property_readonly("cells",
                             [](const PyTree &t) {
                               std::vector<int64_t> v;
                               for (const auto &n : t.tree.nodes)
                                 v.push_back(n.cell);
                               return array_1d(v);
                             })
      .def_property_readonly(
          "arcs",
          [](const PyTree &t) {
            py::array_t<int64_t> a({static_cast<py::ssize_t>(t.tree.arcs.size()), py::ssize_t{2}});
            auto w = a.mutable_unchecked<2>();
            for (std::size_t i = 0; i < t.tree.arcs.size(); ++i) {
              w(static_cast<py::ssize_t>(i), 0) = t.tree.arcs[i][0];
              w(static_cast<py::ssize_t>(i), 1) = t.tree.arcs[i][1];
            }
            return a;
          })
      .def_property_readonly("pairs",
                             [](const PyTree &t) {
                               py::dict d;
                               std::vector<int64_t> b, e;
                               std::vector<double> p;
                               std::vector<std::string> k;
                               std::vector<uint8_t> u;
                               for (const auto &x : t.tree.pairs) {
                                 b.push_back(x.birth);
                                 e.push_back(x.death);
                                 p.push_back(x.persistence());
                                 k.push_back(to_string(x.kind));
                                 u.push_back(t.tree.uncertain(x));
                               }
                               d["birth"] = array_1d(b);
                               d["death"] = array_1d(e);
                               d["persistence"] = array_1d(p);
                               d["kind"] = k;
                               // At or below the input's precision (Tree.precision), or
                               // within twice a fallback stand-in's slack.
                               d["uncertain"] = array_1d(u).attr("astype")("bool");
                               return d;
                             })
      .def_property_readonly("branches",
                             [](const PyTree &t) {
                               py::dict d;
                               std::vector<int64_t> ex, sa, pa;
                               std::vector<double> pe;
                               std::vector<int> de;
                               for (const auto &b : t.tree.branches) {
                                 ex.push_back(b.extremum);
                                 sa.push_back(b.saddle);
                                 pa.push_back(b.parent);
                                 pe.push_back(b.persistence);
                                 de.push_back(b.depth);
                               }
                               d["extremum"] = array_1d(ex);
                               d["saddle"] = array_1d(sa);
                               d["persistence"] = array_1d(pe);
                               d["parent"] = array_1d(pa);
                               d["depth"] = array_1d(de);
                               return d;
                             })
      .def_property_readonly(
          "precision",
          [](const PyTree &t) -> py::object {
            if (!t.tree.stats.precision)
              return py::none();
            return py::float_(*t.tree.stats.precision);
          },
          "The smallest persistence the input's values resolve; pairs at or below it are "
          "flagged in pairs['uncertain'] (so are pairs within twice a fallback cell's slack, "
          "stats['fallback_error'])")
      .def_property_readonly("stats",
                             [](const PyTree &t) {
                               py::dict d;
                               for (const auto &[k, v] : t.tree.stats.entries())
                                 d[py::str(k)] = v;
                               return d;
                             })
      .def(
          "simplify",
          [](const PyTree &t, double threshold, bool loops) {
            PyTree r;
            r.tree = simplify_tree(t.tree, py_checks::threshold(threshold, "simplify"), loops);
            return r;
          },
          py::arg("threshold"), py::arg("loops") = false)
      .def("arc_paths",
           [](PyTree &t) {
             if (t.tree.graph || t.tree.arc_paths.empty()) // (drawn already by MPI ranks)
               compute_arc_paths(t.tree, 0);               // every hardware thread: the same paths
             std::vector<std::vector<std::array<double, 3>>> out;
             for (const auto &p : t.tree.arc_paths)
               out.emplace_back(p.begin(), p.end());
             return out;
           })
      .def(
          "simplify_by",
          [](const PyTree &t, const std::string &spec, bool loops) {
            const TreeResult &x = t.tree;
            const double range = x.nodes.empty() ? 0 : x.nodes.back().value - x.nodes.front().value;
            PyTree r;
            r.tree = simplify_tree(x, parse_threshold(spec, "simplify_by").absolute(range), loops);
            return r;
          },
          py::arg("spec"), py::arg("loops") = false)
      .def(
          "to_json",
          [](const PyTree &t, bool timings) {
            return tree_to_json(t.tree, timings, thread_count(0));
          },
          py::arg("timings") = true)
      // The files `hoct tree` writes (--json, --vtp, --svg), atomically.
      .def(
          "write_json",
          [](const PyTree &t, const std::string &path, bool timings) {
            write_tree_json(no_nul(path, "write_json: path"), t.tree, timings, thread_count(0));
          },
          py::arg("path"), py::arg("timings") = true, py::call_guard<py::gil_scoped_release>())
      .def(
          "write_vtp",
          [](PyTree &t, const std::string &path) {
            if (t.tree.arc_paths.empty())
              compute_arc_paths(t.tree, 0);
            write_tree_vtp(no_nul(path, "write_vtp: path"), t.tree);
          },
          py::arg("path"), py::call_guard<py::gil_scoped_release>())
      .def(
          "write_svg",
          [](const PyTree &t, const std::string &path, const std::string &title) {
            if (t.tree.branches.empty())
              throw Error("write_svg draws the reduced tree (not an augmented one)");
            write_tree_svg(no_nul(path, "write_svg: path"), t.tree,
                           no_nul(title, "write_svg: title"));
          },
          py::arg("path"), py::arg("title") = "", py::call_guard<py::gil_scoped_release>())
      .def("join_tree", [](const PyTree &t) { return merge_tree_dict(t, true); })
      .def("split_tree", [](const PyTree &t) { return merge_tree_dict(t, false); });

  // The computations release the GIL: other Python threads run meanwhile.
  m.def(
      "read",
      [](const std::string &path, const std::string &scalar, const std::string &max_memory,
         int threads, double merge_tolerance, const std::string &component, int64_t step,
         std::optional<double> time) {
        ReadLimits limits = read_limits_for(no_nul(max_memory, "read: max_memory"));
        limits.threads = thread_count(threads);
        FieldSelection field(no_nul(scalar, "read: scalar"));
        if (!component.empty())
          field.component = parse_component(component);
        field.step = step;
        field.time = time;
        MeshInput input = read_mesh(no_nul(path, "read: path"), field, limits);
        // The reader's warnings and notes, for the package to raise as Python warnings.
        std::vector<std::string> notes = input.warnings;
        if (merge_tolerance >= 0) // as `hoct tree --merge-duplicates=TOL`
          merge_duplicate_points(input, merge_tolerance, thread_count(threads));
        for (std::string &note : gll_notes(resample_gll_cells(input))) // as `hoct tree` reads
          notes.push_back(std::move(note));
        return std::make_pair(make_mesh(std::move(input), threads), notes);
      },
      py::arg("path"), py::arg("scalar"), py::arg("max_memory"), py::arg("threads"),
      py::arg("merge_tolerance"), py::arg("component") = "", py::arg("step") = -1,
      py::arg("time") = py::none(), py::call_guard<py::gil_scoped_release>());
  m.def("from_arrays", &from_arrays);
  m.def("is_bookkeeping_array", &is_bookkeeping_array);
  m.def("contour_tree", &py_contour_tree, py::call_guard<py::gil_scoped_release>());
  python::bind_mpi(m);
  m.def(
      "generate",
      [](const std::string &name, int degree, long long cells, uint64_t seed, double frequency,
         double plateau, double scale, double offset, bool quads) {
        DatasetOptions o;
        o.quadrilaterals = quads;
        o.scale = scale;
        o.offset = offset;
        o.degree = degree;
        o.cells = cells;
        o.seed = seed;
        o.frequency = frequency;
        o.plateau = plateau;
        return make_mesh(generate_dataset(no_nul(name, "generate: name"), o));
      },
      py::call_guard<py::gil_scoped_release>());
  m.def("dataset_names", &dataset_names);
}

namespace hoct::python {

TreeRequest tree_request(const std::string &method, int refine, int threads, bool keep_flat,
                         bool force, bool augmented, const std::string &simplify) {
  TreeRequest rq;
  if (method == "exact")
    rq.method = TreeMethod::Exact;
  else if (method == "linear")
    rq.method = TreeMethod::Linear;
  else if (method == "refine")
    rq.method = TreeMethod::Refine;
  else
    throw Error("contour_tree: method must be 'exact', 'linear' or 'refine'");
  rq.refine = refine;
  rq.threads = threads;
  rq.keep_flat = keep_flat;
  rq.force = force;
  rq.augmented = augmented;
  if (!simplify.empty())
    rq.simplify = parse_threshold(simplify, "contour_tree: simplify");
  return rq;
}

} // namespace hoct::python
