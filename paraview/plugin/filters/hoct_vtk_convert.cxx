#include "hoct_vtk_convert.h"

#include "io/vtk_cells.hpp"
#include "util/error.hpp"
#include "vtkio/grid_input.hpp"

#include <vtkAbstractArray.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkIdTypeArray.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>
#include <vtkUnstructuredGrid.h>

#include <cmath>
#include <string>
#include <vector>

namespace hoct::paraview {
namespace {

[[noreturn]] void fail(const std::string &what) { throw InputError("the input grid: " + what); }

// A one-component VTK array named `name` with `count` values value(i).
template <class Array, class F>
vtkNew<Array> make_array(const char *name, std::size_t count, F value) {
  vtkNew<Array> a;
  a->SetName(name);
  a->SetNumberOfTuples(static_cast<vtkIdType>(count));
  for (std::size_t i = 0; i < count; ++i)
    a->SetValue(static_cast<vtkIdType>(i), value(i));
  return a;
}

vtkNew<vtkPoints> make_points(const TreePolyData &d, std::size_t count) {
  vtkNew<vtkPoints> p;
  p->SetDataTypeToDouble();
  p->SetNumberOfPoints(static_cast<vtkIdType>(count));
  for (std::size_t i = 0; i < count; ++i)
    p->SetPoint(static_cast<vtkIdType>(i), &d.points[3 * i]);
  return p;
}

vtkNew<vtkCellArray> make_verts(std::size_t count) {
  vtkNew<vtkCellArray> v;
  for (std::size_t i = 0; i < count; ++i) {
    const vtkIdType id = static_cast<vtkIdType>(i);
    v->InsertNextCell(1, &id);
  }
  return v;
}

} // namespace

vtkDataArray *point_scalar(vtkUnstructuredGrid *grid, vtkDataArray *selected,
                           const std::string &requested, bool *by_default) {
  *by_default = false;
  if (selected)
    return selected;
  vtkPointData *pd = grid->GetPointData();
  if (!requested.empty())
    fail("no point array named '" + requested + "' (point arrays: " + vtkio::list_point_arrays(pd) +
         ")");
  *by_default = true;
  std::string problem;
  vtkDataArray *a = vtkio::find_point_array(pd, FieldSelection{}, &problem);
  if (!a)
    fail("no point scalar array selected and " + problem);
  return a;
}

MeshInput mesh_input_from_grid(vtkUnstructuredGrid *grid, vtkDataArray *scalar) {
  if (!scalar)
    fail("no point scalar array selected");
  FilePiece piece = vtkio::grid_piece(grid, scalar, FieldSelection::kScalar, "the input grid");
  if (piece.input.num_cells() == 0)
    fail(kVtkSurfaceCells);
  return std::move(piece.input);
}

int ttk_critical_type(NodeType type) {
  switch (type) {
  case NodeType::Minimum:
    return 0;
  case NodeType::Saddle:
    return 1;
  case NodeType::Maximum:
    return 3;
  case NodeType::Regular:
    break;
  }
  return 5;
}

void critical_points_polydata(const TreePolyData &d, vtkPolyData *out) {
  const std::size_t n = d.num_nodes;
  out->SetPoints(make_points(d, n));
  out->SetVerts(make_verts(n));
  vtkPointData *pd = out->GetPointData();
  pd->AddArray(make_array<vtkIntArray>(
      "CriticalType", n, [&](std::size_t i) { return ttk_critical_type(d.type[i]); }));
  pd->AddArray(make_array<vtkStringArray>("TypeName", n,
                                          [&](std::size_t i) { return to_string(d.type[i]); }));
  pd->SetScalars(make_array<vtkDoubleArray>("Value", n, [&](std::size_t i) { return d.value[i]; }));
  pd->AddArray(make_array<vtkDoubleArray>("Persistence", n,
                                          [&](std::size_t i) { return d.persistence[i]; }));
  pd->AddArray(make_array<vtkIdTypeArray>(
      "NodeId", n, [&](std::size_t i) { return static_cast<vtkIdType>(d.node_id[i]); }));
  pd->AddArray(make_array<vtkIdTypeArray>(
      "Cell", n, [&](std::size_t i) { return static_cast<vtkIdType>(d.cell[i]); }));
  pd->AddArray(make_array<vtkIntArray>(
      "Location", n, [&](std::size_t i) { return static_cast<int>(d.location[i]); }));
  pd->AddArray(make_array<vtkIntArray>(
      "Fallback", n, [&](std::size_t i) { return static_cast<int>(d.fallback[i]); }));
}

void arcs_polydata(const TreePolyData &d, bool with_nodes, vtkPolyData *out) {
  const std::size_t np = d.num_points(), m = d.num_lines(), nv = with_nodes ? d.num_nodes : 0;
  out->SetPoints(make_points(d, np));
  if (with_nodes)
    out->SetVerts(make_verts(nv));
  vtkNew<vtkCellArray> lines;
  int64_t begin = 0;
  for (std::size_t a = 0; a < m; ++a) {
    const int64_t end = d.line_offsets[a];
    lines->InsertNextCell(static_cast<vtkIdType>(end - begin));
    for (int64_t k = begin; k < end; ++k)
      lines->InsertCellPoint(static_cast<vtkIdType>(d.line_connectivity[k]));
    begin = end;
  }
  out->SetLines(lines);
  vtkPointData *pd = out->GetPointData();
  pd->SetScalars(
      make_array<vtkDoubleArray>("Value", np, [&](std::size_t i) { return d.value[i]; }));
  pd->AddArray(make_array<vtkDoubleArray>("Persistence", np,
                                          [&](std::size_t i) { return d.persistence[i]; }));
  pd->AddArray(make_array<vtkIntArray>(
      "CriticalType", np, [&](std::size_t i) { return ttk_critical_type(d.type[i]); }));
  pd->AddArray(make_array<vtkIdTypeArray>(
      "NodeId", np, [&](std::size_t i) { return static_cast<vtkIdType>(d.node_id[i]); }));
  // Cell data: the vertices (if any) come first, then the lines.
  vtkCellData *cd = out->GetCellData();
  cd->AddArray(make_array<vtkDoubleArray>("Persistence", nv + m, [&](std::size_t i) {
    return i < nv ? d.node_persistence[i] : d.arc_persistence[i - nv];
  }));
  cd->AddArray(make_array<vtkIdTypeArray>("ArcId", nv + m, [&](std::size_t i) {
    return i < nv ? vtkIdType{-1} : static_cast<vtkIdType>(i - nv);
  }));
}

} // namespace hoct::paraview
