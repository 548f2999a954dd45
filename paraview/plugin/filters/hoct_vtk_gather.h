// A grid distributed over the processes of a parallel ParaView (pvbatch, pvserver under MPI), for
// the distributed tree: each process's own piece, joined with the others' where the processes
// can join them alone (no process holds the whole), else gathered into one mesh on every
// process.
#pragma once

#include "io/piece_join.hpp"
#include "mesh/mesh_input.hpp"

#include <string>
#include <vector>

class vtkDataArray;
class vtkMultiProcessController;
class vtkUnstructuredGrid;

namespace hoct::paraview {

// Collective over `controller`: every process passes its own piece and the point scalar it
// selected (`scalar` null, or `failure` not empty, where it could not select one). The pieces'
// triangles, that scalar, their ghost levels and global point ids go to every process (VTK's
// AllGather of data objects) and are joined in process order by the rule that joins a .pvtu's
// pieces (io/piece_join: ghost cells dropped, shared points merged by global id or position).
// Returns the whole mesh, the same on every process, and the scalar's name. Every process
// throws the same hoct::InputError where any process failed (the lowest one's message), the
// pieces name different scalars, or none has cells.
MeshInput gather_whole(vtkMultiProcessController *controller, vtkUnstructuredGrid *grid,
                       vtkDataArray *scalar, const std::string &failure, int threads,
                       std::string *scalar_name);

// This process's piece as a .pvtu's piece is read (its cells, the scalar, its ghost levels and
// global point ids); none without cells. Throws hoct::InputError for a piece it cannot take.
std::vector<FilePiece> own_piece(vtkUnstructuredGrid *grid, vtkDataArray *scalar, int process);

} // namespace hoct::paraview
