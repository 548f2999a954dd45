#include "hoct_vtk_convert.h"

#include "io/vtk_cells.hpp"
#include "util/error.hpp"

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

// One of VTK's bookkeeping arrays, never a field: vtkGhostType, vtkOriginalPointIds, ...
bool bookkeeping(vtkPointData *pd, vtkDataArray *a) {
  const char *name = a->GetName();
  return (name && std::string(name).rfind("vtk", 0) == 0) || a == pd->GetGlobalIds() ||
         a == pd->GetPedigreeIds();
}

// "a, b (3 components), c" for the messages.
std::string point_arrays(vtkPointData *pd) {
  std::string list;
  for (int i = 0; i < pd->GetNumberOfArrays(); ++i) {
    vtkAbstractArray *a = pd->GetAbstractArray(i);
    list += (list.empty() ? "" : ", ") + std::string(a->GetName() ? a->GetName() : "(unnamed)");
    if (a->GetNumberOfComponents() != 1)
      list += " (" + std::to_string(a->GetNumberOfComponents()) + " components)";
  }
  return list.empty() ? "the grid has no point data" : "point arrays: " + list;
}

} // namespace

vtkDataArray *point_scalar(vtkUnstructuredGrid *grid, vtkDataArray *selected,
                           const std::string &requested, bool *by_default) {
  *by_default = false;
  if (selected)
    return selected;
  vtkPointData *pd = grid->GetPointData();
  if (!requested.empty())
    fail("no point array named '" + requested + "' (" + point_arrays(pd) + ")");
  *by_default = true;
  vtkDataArray *active = pd->GetScalars();
  if (active && active->GetNumberOfComponents() == 1 && !bookkeeping(pd, active))
    return active;
  vtkDataArray *other = nullptr;
  for (int i = 0; i < pd->GetNumberOfArrays(); ++i) {
    vtkDataArray *a = pd->GetArray(i); // null for string arrays
    if (!a || a->GetNumberOfComponents() != 1 || bookkeeping(pd, a))
      continue;
    if (a->GetDataType() == VTK_FLOAT || a->GetDataType() == VTK_DOUBLE)
      return a;
    if (!other)
      other = a;
  }
  if (!other)
    fail("no point scalar array selected and no one-component point array to default to (" +
         point_arrays(pd) + ")");
  return other;
}

MeshInput mesh_input_from_grid(vtkUnstructuredGrid *grid, vtkDataArray *scalar) {
  const vtkIdType np = grid->GetNumberOfPoints(), nc = grid->GetNumberOfCells();
  if (!scalar)
    fail("no point scalar array selected");
  const std::string name = scalar->GetName() ? scalar->GetName() : "(unnamed)";
  if (scalar->GetNumberOfComponents() != 1)
    fail("point array '" + name + "' has " + std::to_string(scalar->GetNumberOfComponents()) +
         " components; a scalar field needs 1");
  if (scalar->GetNumberOfTuples() != np)
    fail("array '" + name + "' has " + std::to_string(scalar->GetNumberOfTuples()) +
         " values for " + std::to_string(np) + " points (select a point array)");
  MeshInput m;
  m.source = "the input grid";
  m.field_name = name;
  m.points.resize(static_cast<std::size_t>(np));
  m.values.resize(static_cast<std::size_t>(np));
  for (vtkIdType i = 0; i < np; ++i) {
    double p[3];
    grid->GetPoint(i, p);
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
      fail("point " + std::to_string(i) + " has a NaN or infinite coordinate");
    const double v = scalar->GetTuple1(i);
    if (!std::isfinite(v))
      fail("point " + std::to_string(i) + " has a non-finite value of '" + name + "'");
    m.points[static_cast<std::size_t>(i)] = {p[0], p[1], p[2]};
    m.values[static_cast<std::size_t>(i)] = v;
  }
  std::vector<int64_t> ids;
  std::string problem;
  for (vtkIdType c = 0; c < nc; ++c) {
    vtkIdType n = 0;
    const vtkIdType *pts = nullptr;
    grid->GetCellPoints(c, n, pts);
    ids.assign(pts, pts + n);
    if (add_vtk_cell(m, grid->GetCellType(c), ids.data(), n, np, 0, &problem) ==
        VtkCellResult::Invalid)
      fail("cell " + std::to_string(c) + problem);
  }
  if (m.num_cells() == 0)
    fail("no triangle cells (VTK_TRIANGLE 5, VTK_QUADRATIC_TRIANGLE 22 or VTK_LAGRANGE_TRIANGLE "
         "69)");
  return m;
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
