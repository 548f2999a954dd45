#include "vtkio/grid_input.hpp"

#include "io/vtk_cells.hpp"
#include "util/error.hpp"

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDataSet.h>
#include <vtkDataSetAttributes.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPointSet.h>
#include <vtkPoints.h>
#include <vtkUnsignedCharArray.h>
#include <vtkUnstructuredGrid.h>

#include <cmath>
#include <vector>

namespace hoct::vtkio {
namespace {

bool floating(vtkDataArray *a) {
  return a->GetDataType() == VTK_FLOAT || a->GetDataType() == VTK_DOUBLE;
}

std::string name_of(vtkAbstractArray *a) {
  return a->GetName() ? a->GetName() : std::string("(unnamed)");
}

bool bookkeeping(vtkPointData *pd, vtkDataArray *a) {
  return is_bookkeeping_array(name_of(a)) || a == pd->GetGlobalIds() || a == pd->GetPedigreeIds();
}

// The array of global point ids: the GlobalIds attribute, else one of the names writers use.
vtkDataArray *global_ids(vtkPointData *pd) {
  if (vtkDataArray *a = pd->GetGlobalIds())
    return a;
  for (const char *name : {"GlobalNodeId", "GlobalIds", "GlobalPointIds", "GlobalNodeIds"})
    if (vtkDataArray *a = pd->GetArray(name); a && a->GetNumberOfComponents() == 1)
      return a;
  return nullptr;
}

} // namespace

std::string list_point_arrays(vtkPointData *pd) {
  std::string list;
  for (int i = 0; i < pd->GetNumberOfArrays(); ++i) {
    vtkAbstractArray *a = pd->GetAbstractArray(i);
    list += (list.empty() ? "" : ", ") + name_of(a);
    if (a->GetNumberOfComponents() != 1)
      list += " (" + std::to_string(a->GetNumberOfComponents()) + " components)";
  }
  return list.empty() ? "none" : list;
}

vtkDataArray *find_point_array(vtkPointData *pd, const FieldSelection &field,
                               std::string *problem) {
  const bool vector = field.component != FieldSelection::kScalar;
  auto suitable = [&](vtkDataArray *a) {
    return vector ? a->GetNumberOfComponents() > 1 : a->GetNumberOfComponents() == 1;
  };
  const std::string listed = " (point arrays: " + list_point_arrays(pd) + ")";
  if (!field.name.empty()) {
    vtkDataArray *a = pd->GetArray(field.name.c_str());
    if (!a)
      *problem = "no numeric point array named '" + field.name + "'" + listed;
    return a;
  }
  vtkDataArray *active = vector ? pd->GetVectors() : pd->GetScalars();
  if (active && suitable(active) && !bookkeeping(pd, active))
    return active;
  for (int pass = 0; pass < 2; ++pass)
    for (int i = 0; i < pd->GetNumberOfArrays(); ++i) {
      vtkDataArray *a = pd->GetArray(i); // null for string arrays
      if (a && suitable(a) && (pass == 1 || floating(a)) && !bookkeeping(pd, a))
        return a;
    }
  *problem = std::string("no ") + (vector ? "vector" : "scalar (one-component)") +
             " point array that is not an id, ghost or mask array" + listed;
  return nullptr;
}

FilePiece grid_piece(vtkDataSet *data, vtkDataArray *array, int component,
                     const std::string &where) {
  auto fail = [&](const std::string &what) { throw InputError(where + ": " + what); };
  const vtkIdType np = data->GetNumberOfPoints(), nc = data->GetNumberOfCells();
  if (!array)
    fail("no point array to read");
  const std::string name = name_of(array);
  const int comps = array->GetNumberOfComponents();
  if (component == FieldSelection::kScalar && comps != 1)
    fail("point array '" + name + "' has " + std::to_string(comps) +
         " components; a scalar field needs 1 (choose one with --component N, or --component "
         "magnitude)");
  if (component >= comps)
    fail("--component " + std::to_string(component) + ": point array '" + name + "' has " +
         std::to_string(comps) + " component" + (comps == 1 ? "" : "s"));
  if (array->GetNumberOfTuples() != np)
    fail("point array '" + name + "' has " + std::to_string(array->GetNumberOfTuples()) +
         " values for " + std::to_string(np) + " points");
  FilePiece piece;
  piece.file = where;
  MeshInput &m = piece.input;
  m.source = where;
  FieldSelection described;
  described.component = component;
  m.field_name = described.describe(name);
  m.points.resize(static_cast<std::size_t>(np));
  m.values.resize(static_cast<std::size_t>(np));
  // Float32 data are exact only to their own rounding (Geometry's straightness, Field's
  // precision).
  vtkPointSet *point_set = vtkPointSet::SafeDownCast(data);
  if (point_set && point_set->GetPoints() && point_set->GetPoints()->GetDataType() == VTK_FLOAT)
    m.coordinate_precision = 0x1p-24;
  if (array->GetDataType() == VTK_FLOAT)
    m.value_precision = 0x1p-24;
  std::vector<double> tuple(static_cast<std::size_t>(comps));
  for (vtkIdType i = 0; i < np; ++i) {
    double p[3];
    data->GetPoint(i, p);
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
      fail("point " + std::to_string(i) + " has a NaN or infinite coordinate");
    array->GetTuple(i, tuple.data());
    double v = 0;
    if (component == FieldSelection::kMagnitude) {
      for (double c : tuple)
        v += c * c;
      v = std::sqrt(v);
    } else {
      v = tuple[component < 0 ? 0 : static_cast<std::size_t>(component)];
    }
    if (!std::isfinite(v))
      fail("point " + std::to_string(i) + " has a non-finite value of '" + m.field_name + "'");
    m.points[static_cast<std::size_t>(i)] = {p[0], p[1], p[2]};
    m.values[static_cast<std::size_t>(i)] = v;
  }
  // Cells: the kept ones' ghost levels go with them.
  VtuPieceArrays &arrays = piece.arrays;
  const char *ghost_name = vtkDataSetAttributes::GhostArrayName();
  vtkDataArray *cell_ghost = data->GetCellData()->GetArray(ghost_name);
  vtkDataArray *point_ghost = data->GetPointData()->GetArray(ghost_name);
  auto *grid = vtkUnstructuredGrid::SafeDownCast(data);
  vtkNew<vtkIdList> list;
  std::vector<int64_t> ids;
  std::string problem;
  for (vtkIdType c = 0; c < nc; ++c) {
    vtkIdType n = 0;
    const vtkIdType *pts = nullptr;
    if (grid) {
      grid->GetCellPoints(c, n, pts);
    } else {
      data->GetCellPoints(c, list);
      n = list->GetNumberOfIds();
      pts = list->GetPointer(0);
    }
    ids.assign(pts, pts + n);
    const VtkCellResult r = add_vtk_cell(m, data->GetCellType(c), ids.data(), n, np, 0, &problem);
    if (r == VtkCellResult::Invalid)
      fail("cell " + std::to_string(c) + problem);
    if (r == VtkCellResult::Added && cell_ghost) {
      const auto g = static_cast<uint8_t>(cell_ghost->GetTuple1(c));
      arrays.cell_ghost.push_back(g);
      arrays.ghost_cells += (g & kDuplicateGhost) != 0;
    }
  }
  if (point_ghost && point_ghost->GetNumberOfTuples() == np) {
    arrays.point_ghost.resize(static_cast<std::size_t>(np));
    for (vtkIdType i = 0; i < np; ++i) {
      arrays.point_ghost[static_cast<std::size_t>(i)] =
          static_cast<uint8_t>(point_ghost->GetTuple1(i));
      arrays.ghost_points +=
          (arrays.point_ghost[static_cast<std::size_t>(i)] & kDuplicateGhost) != 0;
    }
  }
  if (vtkDataArray *g = global_ids(data->GetPointData()); g && g->GetNumberOfTuples() == np) {
    arrays.global_ids.resize(static_cast<std::size_t>(np));
    arrays.global_ids_name = name_of(g);
    for (vtkIdType i = 0; i < np; ++i)
      arrays.global_ids[static_cast<std::size_t>(i)] = static_cast<int64_t>(g->GetTuple1(i));
  }
  return piece;
}

} // namespace hoct::vtkio
