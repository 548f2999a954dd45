#include "hoct_vtk_gather.h"

#include "io/piece_join.hpp"
#include "util/error.hpp"
#include "vtkio/grid_input.hpp"

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDataSetAttributes.h>
#include <vtkFieldData.h>
#include <vtkMultiProcessController.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkSmartPointer.h>
#include <vtkStringArray.h>
#include <vtkUnstructuredGrid.h>

#include <utility>
#include <vector>

namespace hoct::paraview {
namespace {

constexpr const char *kFailure = "HoctFailure"; // a process's own failure, as field data

// The piece as it travels: its cells and points, the scalar (as the active scalars), the ghost
// levels and the global point ids; nothing else.
void light_copy(vtkUnstructuredGrid *grid, vtkDataArray *scalar, vtkUnstructuredGrid *out) {
  out->SetPoints(grid->GetPoints());
  out->SetCells(grid->GetCellTypesArray(), grid->GetCells());
  vtkPointData *pd = grid->GetPointData();
  out->GetPointData()->SetScalars(scalar);
  const char *ghost = vtkDataSetAttributes::GhostArrayName();
  if (vtkDataArray *a = pd->GetArray(ghost))
    out->GetPointData()->AddArray(a);
  if (vtkDataArray *a = grid->GetCellData()->GetArray(ghost))
    out->GetCellData()->AddArray(a);
  if (vtkDataArray *a = pd->GetGlobalIds())
    out->GetPointData()->SetGlobalIds(a);
  for (const char *name : {"GlobalNodeId", "GlobalIds", "GlobalPointIds", "GlobalNodeIds"})
    if (vtkDataArray *a = pd->GetArray(name); a && a != scalar)
      out->GetPointData()->AddArray(a);
}

} // namespace

MeshInput gather_whole(vtkMultiProcessController *controller, vtkUnstructuredGrid *grid,
                       vtkDataArray *scalar, const std::string &failure, int threads,
                       std::string *scalar_name) {
  vtkNew<vtkUnstructuredGrid> light;
  if (!failure.empty()) {
    vtkNew<vtkStringArray> why;
    why->SetName(kFailure);
    why->InsertNextValue(failure);
    light->GetFieldData()->AddArray(why);
  } else if (grid && scalar && grid->GetNumberOfCells() > 0) {
    light_copy(grid, scalar, light);
  }
  std::vector<vtkSmartPointer<vtkDataObject>> all;
  controller->AllGather(light, all);
  // Every process reads the same gathered pieces: it fails, or goes on, as the others do.
  for (std::size_t r = 0; r < all.size(); ++r)
    if (all[r])
      if (auto *why =
              vtkStringArray::SafeDownCast(all[r]->GetFieldData()->GetAbstractArray(kFailure)))
        throw InputError("process " + std::to_string(r) + ": " + why->GetValue(0));
  std::vector<FilePiece> pieces;
  std::string name;
  for (std::size_t r = 0; r < all.size(); ++r) {
    auto *g = vtkUnstructuredGrid::SafeDownCast(all[r]);
    if (!g || g->GetNumberOfCells() == 0)
      continue;
    vtkDataArray *s = g->GetPointData()->GetScalars();
    const std::string where = "the piece of process " + std::to_string(r);
    if (!s)
      throw InputError(where + " arrived without its point scalar (an internal error)");
    const std::string n = s->GetName() ? s->GetName() : "";
    if (pieces.empty())
      name = n;
    else if (n != name)
      throw InputError(where + " has the scalar '" + n + "', the others '" + name +
                       "': select one point array for every piece");
    FilePiece p = vtkio::grid_piece(g, s, FieldSelection::kScalar, where);
    p.file = where;
    if (p.input.num_cells() > 0)
      pieces.push_back(std::move(p));
  }
  if (pieces.empty())
    throw InputError("no process has triangle cells of the input");
  *scalar_name = name;
  return join_pieces(std::move(pieces), "the input's pieces", /*by_ids=*/true, threads);
}

std::vector<FilePiece> own_piece(vtkUnstructuredGrid *grid, vtkDataArray *scalar, int process) {
  std::vector<FilePiece> pieces;
  if (!grid || !scalar || grid->GetNumberOfCells() == 0)
    return pieces;
  vtkNew<vtkUnstructuredGrid> light;
  light_copy(grid, scalar, light);
  const std::string where = "the piece of process " + std::to_string(process);
  FilePiece p = vtkio::grid_piece(light, scalar, FieldSelection::kScalar, where);
  p.file = where;
  if (p.input.num_cells() > 0)
    pieces.push_back(std::move(p));
  return pieces;
}

} // namespace hoct::paraview
