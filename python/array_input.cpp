#include "array_input.hpp"

#include "io/vtk_cells.hpp"
#include "poly/lagrange_node_order.hpp"
#include "util/error.hpp"

namespace hoct::python {

namespace py = pybind11;

MeshInput input_from_arrays(const DoubleArray &points, const std::vector<IndexArray> &blocks,
                            const std::vector<IndexArray> &types, const DoubleArray &values,
                            const std::string &field_name, bool float32_points,
                            bool float32_values) {
  if (points.ndim() != 2 || (points.shape(1) != 2 && points.shape(1) != 3))
    throw Error("from_arrays: points must have shape (n, 2) or (n, 3)");
  if (values.ndim() != 1 || values.shape(0) != points.shape(0))
    throw Error("from_arrays: values must have one entry per point");
  if (types.size() != blocks.size())
    throw Error("from_arrays: one cell type per block of cells");
  MeshInput in;
  const auto p = points.unchecked<2>();
  for (py::ssize_t i = 0; i < points.shape(0); ++i)
    in.points.push_back({p(i, 0), p(i, 1), points.shape(1) == 3 ? p(i, 2) : 0.0});
  in.values.assign(values.data(), values.data() + values.shape(0));
  if (float32_points)
    in.coordinate_precision = 0x1p-24;
  if (float32_values)
    in.value_precision = 0x1p-24;
  int64_t first = 0; // the cell index of the block's first cell, for messages
  for (std::size_t b = 0; b < blocks.size(); ++b) {
    const auto &cells = blocks[b];
    if (cells.ndim() != 2)
      throw Error("from_arrays: cells must have shape (cells, nodes per cell), nodes in VTK order");
    const int64_t n = cells.shape(1);
    if (types[b].ndim() != 1 || types[b].shape(0) != cells.shape(0))
      throw Error("from_arrays: one cell type per cell");
    const auto t = types[b].unchecked<1>();
    const auto c = cells.unchecked<2>();
    std::vector<int64_t> ids(static_cast<std::size_t>(n));
    std::string problem;
    for (py::ssize_t k = 0; k < cells.shape(0); ++k) {
      int64_t type = t(k);
      if (type == 0) {
        if (degree_from_node_count(n) < 1)
          throw Error("from_arrays: " + std::to_string(n) +
                      " nodes per cell is not a complete triangle (3, 6, 10, 15, ...)");
        type = n == 3 ? 5 : 69;
      }
      for (int64_t i = 0; i < n; ++i)
        ids[static_cast<std::size_t>(i)] = c(k, static_cast<py::ssize_t>(i));
      if (add_vtk_cell(in, type, ids.data(), n, points.shape(0), 0, &problem) !=
          VtkCellResult::Added)
        throw Error("from_arrays: cell " + std::to_string(first + k) + problem);
    }
    first += cells.shape(0);
  }
  in.source = "arrays";
  in.field_name = field_name;
  return in;
}

} // namespace hoct::python
