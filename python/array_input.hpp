// Numpy arrays as a mesh input (hoct.from_arrays, hoct.piece_from_arrays): points (n, 2|3),
// cells in blocks of one node count, nodes in VTK order, each cell's VTK type (0: a complete
// Lagrange triangle of the node count), values per point. Cells convert only safely (no
// forcecast): a float or uint64 array is refused, not truncated or wrapped (the package
// converts the arrays a .vtu file could hold, with messages). Throws hoct::Error naming the
// cell for anything else.
#pragma once

#include "mesh/mesh_input.hpp"

#include <pybind11/numpy.h>

#include <string>
#include <vector>

namespace hoct::python {

using DoubleArray =
    pybind11::array_t<double, pybind11::array::c_style | pybind11::array::forcecast>;
using IndexArray = pybind11::array_t<int64_t, pybind11::array::c_style>;

MeshInput input_from_arrays(const DoubleArray &points, const std::vector<IndexArray> &blocks,
                            const std::vector<IndexArray> &types, const DoubleArray &values,
                            const std::string &field_name, bool float32_points,
                            bool float32_values);

} // namespace hoct::python
