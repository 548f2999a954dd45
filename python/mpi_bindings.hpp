// The module's MPI entry points (mpi4py communicators, passed by their Fortran handles): the
// exact tree of a whole mesh every rank holds (contour_tree_mpi), and hoct.Piece, one rank's
// piece of a mesh no rank holds whole (read_pieces of a .pvtu, piece_from_arrays in situ), with
// its tree (contour_tree_piece). Built without MPI, they raise HoctError.
#pragma once

#include <pybind11/pybind11.h>

namespace hoct::python {

void bind_mpi(pybind11::module_ &m);

} // namespace hoct::python
