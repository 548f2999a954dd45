#include "vtkHoctContourTree.h"

#include "hoct_vtk_convert.h"
#include "io/tree_polydata.hpp"
#include "mesh/mesh.hpp"
#include "pipeline/compute_tree.hpp"
#include "util/parallel_for.hpp"

#include <vtkDataArray.h>
#include <vtkDataObject.h>
#include <vtkDataSetAttributes.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>
#include <vtkUnstructuredGrid.h>

#include <exception>
#include <utility>

vtkStandardNewMacro(vtkHoctContourTree);

vtkHoctContourTree::vtkHoctContourTree() {
  this->SetNumberOfInputPorts(1);
  this->SetNumberOfOutputPorts(3);
  // Default scalar: the active point scalars.
  this->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS,
                               vtkDataSetAttributes::SCALARS);
}

int vtkHoctContourTree::FillInputPortInformation(int, vtkInformation *info) {
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkUnstructuredGrid");
  return 1;
}

namespace {

// The tree's statistics (counts, fallbacks, timings) as one-value field-data arrays, and why it
// was forced (Force), if it was, as the string array ForcedReasons.
void add_stats(const hoct::TreeResult &tree, vtkPolyData *out) {
  if (!tree.forced.empty()) {
    vtkNew<vtkStringArray> reasons;
    reasons->SetName("ForcedReasons");
    for (const auto &why : tree.forced)
      reasons->InsertNextValue(why);
    out->GetFieldData()->AddArray(reasons);
  }
  for (const auto &[name, value] : tree.stats.entries()) {
    vtkNew<vtkDoubleArray> a;
    a->SetName(name.c_str());
    a->InsertNextValue(value);
    out->GetFieldData()->AddArray(a);
  }
}

} // namespace

int vtkHoctContourTree::RequestData(vtkInformation *, vtkInformationVector **inputVector,
                                    vtkInformationVector *outputVector) {
  vtkUnstructuredGrid *grid = vtkUnstructuredGrid::GetData(inputVector[0]);
  vtkPolyData *points = vtkPolyData::GetData(outputVector, 0);
  vtkPolyData *arcs = vtkPolyData::GetData(outputVector, 1);
  vtkPolyData *simplified = vtkPolyData::GetData(outputVector, 2);
  if (!grid || !points || !arcs || !simplified) {
    vtkErrorMacro("Higher-Order Contour Tree: missing input or output");
    return 0;
  }
  try {
    // The properties as a library request: the same call as `hoct tree` (pipeline/compute_tree).
    hoct::TreeRequest rq;
    rq.method = this->Method == LINEAR   ? hoct::TreeMethod::Linear
                : this->Method == REFINE ? hoct::TreeMethod::Refine
                                         : hoct::TreeMethod::Exact;
    rq.refine = this->RefineLevel;
    rq.augmented = this->Augmented;
    rq.keep_flat = this->KeepFlat;
    rq.force = this->Force;
    rq.threads = this->Threads;
    rq.arcs = hoct::ArcGeometry::AllPaths;
    if (this->PersistenceThreshold > 0 && !this->Augmented)
      rq.simplify =
          hoct::Threshold{this->PersistenceThreshold, this->ThresholdMode == PERCENT_OF_RANGE};
    else if (this->PersistenceThreshold > 0)
      vtkWarningMacro("Higher-Order Contour Tree: simplification works on the reduced tree; "
                      "turn Augmented off to get output 2");
    hoct::MeshInput input =
        hoct::paraview::mesh_input_from_grid(grid, this->GetInputArrayToProcess(0, inputVector));
    this->UpdateProgress(0.1);
    // Only the linear method reads the input's nodes again; else the build consumes them.
    const hoct::MeshBuildOptions build{.throw_on_error = false,
                                       .threads = hoct::thread_count(this->Threads)};
    const bool keep_input = rq.method == hoct::TreeMethod::Linear;
    const hoct::Mesh mesh =
        keep_input ? hoct::build_mesh(input, build) : hoct::build_mesh(std::move(input), build);
    const hoct::TreeOutcome out = hoct::compute_tree(mesh, rq, keep_input ? &input : nullptr);
    for (const auto &why : out.warnings)
      vtkWarningMacro("Higher-Order Contour Tree: Force: " << why);
    this->UpdateProgress(0.8);
    const hoct::TreePolyData layout = hoct::tree_polydata(out.tree);
    hoct::paraview::critical_points_polydata(layout, points);
    hoct::paraview::arcs_polydata(layout, /*with_nodes=*/false, arcs);
    add_stats(out.tree, points);
    if (out.simplified) {
      hoct::paraview::arcs_polydata(hoct::tree_polydata(*out.simplified), /*with_nodes=*/true,
                                    simplified);
      add_stats(*out.simplified, simplified);
    }
  } catch (const std::exception &e) {
    points->Initialize();
    arcs->Initialize();
    simplified->Initialize();
    vtkErrorMacro("Higher-Order Contour Tree: " << e.what());
    return 0;
  }
  return 1;
}

void vtkHoctContourTree::PrintSelf(ostream &os, vtkIndent indent) {
  this->Superclass::PrintSelf(os, indent);
  os << indent << "PersistenceThreshold: " << this->PersistenceThreshold << "\n";
  os << indent << "ThresholdMode: "
     << (this->ThresholdMode == PERCENT_OF_RANGE ? "percent of range" : "absolute") << "\n";
  os << indent << "Method: "
     << (this->Method == LINEAR   ? "linear"
         : this->Method == REFINE ? "refine"
                                  : "exact")
     << "\n";
  os << indent << "RefineLevel: " << this->RefineLevel << "\n";
  os << indent << "Augmented: " << this->Augmented << "\n";
  os << indent << "KeepFlat: " << this->KeepFlat << "\n";
  os << indent << "Force: " << this->Force << "\n";
  os << indent << "Threads: " << this->Threads << "\n";
}
