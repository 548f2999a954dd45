#include "vtkHoctContourTree.h"

#include "error.hpp"
#include "hoct_vtk_convert.h"
#include "io/tree_polydata.hpp"
#include "mesh/domain_check.hpp"
#include "mesh/mesh.hpp"
#include "tree/exact_contour_tree.hpp"
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

// The tree's statistics (counts, fallbacks, timings) as one-value field-data arrays.
void add_stats(const hoct::TreeResult &tree, vtkPolyData *out) {
  for (const auto &[name, value] : tree.stats) {
    vtkNew<vtkDoubleArray> a;
    a->SetName(name.c_str());
    a->InsertNextValue(value);
    out->GetFieldData()->AddArray(a);
  }
}

} // namespace

int vtkHoctContourTree::RequestData(vtkInformation *, vtkInformationVector **inputVector,
                                    vtkInformationVector *outputVector) {
  vtkUnstructuredGrid *input = vtkUnstructuredGrid::GetData(inputVector[0]);
  vtkPolyData *points = vtkPolyData::GetData(outputVector, 0);
  vtkPolyData *arcs = vtkPolyData::GetData(outputVector, 1);
  vtkPolyData *simplified = vtkPolyData::GetData(outputVector, 2);
  if (!input || !points || !arcs || !simplified) {
    vtkErrorMacro("Higher-Order Contour Tree: missing input or output");
    return 0;
  }
  try {
    // The same library calls as `hoct tree` (apps/hoct/cmd_tree.cpp), the mesh built from an
    // input it consumes (its arrays released as the mesh takes their place).
    hoct::MeshInput mesh_input =
        hoct::paraview::mesh_input_from_grid(input, this->GetInputArrayToProcess(0, inputVector));
    this->UpdateProgress(0.1);
    const int threads = hoct::thread_count(this->Threads);
    const hoct::Mesh mesh =
        hoct::build_mesh(std::move(mesh_input), {.throw_on_error = true, .threads = threads});
    const std::string problem = hoct::domain_problem(mesh.topology);
    if (!problem.empty()) {
      throw hoct::Error("the input grid: " + problem);
    }
    hoct::ExactTreeOptions options;
    options.augmented = this->Augmented;
    options.threads = threads;
    options.arc_geometry = !this->Augmented; // as hoct tree: an augmented tree's arcs straight
    hoct::TreeResult tree = hoct::exact_contour_tree(mesh, options);
    this->UpdateProgress(0.7);
    if (!this->Augmented) {
      tree = hoct::contract_flat(tree); // one node per flat region, as the CLI
    }
    hoct::compute_arc_paths(tree, threads);
    const hoct::TreePolyData layout = hoct::tree_polydata(tree);
    hoct::paraview::critical_points_polydata(layout, points);
    hoct::paraview::arcs_polydata(layout, /*with_nodes=*/false, arcs);
    add_stats(tree, points);
    if (this->PersistenceThreshold > 0) {
      if (this->Augmented) {
        vtkWarningMacro("Higher-Order Contour Tree: simplification works on the reduced tree; "
                        "turn Augmented off to get output 2");
      } else {
        const double range =
            tree.nodes.empty() ? 0.0 : tree.nodes.back().value - tree.nodes.front().value;
        const double threshold = this->ThresholdMode == PERCENT_OF_RANGE
                                     ? this->PersistenceThreshold / 100 * range
                                     : this->PersistenceThreshold;
        hoct::TreeResult simple = hoct::simplify_tree(tree, threshold);
        hoct::compute_arc_paths(simple, threads);
        hoct::paraview::arcs_polydata(hoct::tree_polydata(simple), /*with_nodes=*/true, simplified);
        add_stats(simple, simplified);
      }
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
  os << indent << "Augmented: " << this->Augmented << "\n";
  os << indent << "Threads: " << this->Threads << "\n";
}
