#include "vtkHoctContourTree.h"

#include "hoct_vtk_convert.h"
#include "hoct_vtk_gather.h"
#include "io/tree_polydata.hpp"
#include "mesh/gll_nodes.hpp"
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
#include <vtkMultiProcessController.h>
#ifdef HOCT_WITH_MPI
#include "distributed/distributed_tree.hpp"
#include "distributed/pieces_gather.hpp"
#include "distributed/rank_join.hpp"

#include <vtkMPI.h>
#include <vtkMPICommunicator.h>
#include <vtkMPIController.h>
#endif
#include <vtkObjectFactory.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>
#include <vtkUnstructuredGrid.h>

#include <cstdio>
#include <exception>
#include <string>
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

// The tree's statistics (counts, fallbacks, timings) as one-value field-data arrays, what it is
// (Kind: "contour tree" or "Reeb graph", and Loops), and why it was forced (Force), if it was,
// as the string array ForcedReasons.
void add_stats(const hoct::TreeResult &tree, vtkPolyData *out) {
  vtkNew<vtkStringArray> kind;
  kind->SetName("Kind");
  kind->InsertNextValue(tree.reeb_graph ? "Reeb graph" : "contour tree");
  out->GetFieldData()->AddArray(kind);
  vtkNew<vtkDoubleArray> loops;
  loops->SetName("Loops");
  loops->InsertNextValue(static_cast<double>(tree.loops));
  out->GetFieldData()->AddArray(loops);
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

// The string `value` as the one-value field-data array `name` of out.
void add_string(vtkPolyData *out, const char *name, const std::string &value) {
  vtkNew<vtkStringArray> a;
  a->SetName(name);
  a->InsertNextValue(value);
  out->GetFieldData()->AddArray(a);
}

// What `hoct tree` says of cells read with their nodes at Gauss-Lobatto-Legendre points, in
// one string (empty for none).
std::string gll_note_text(const hoct::GllResampling &g) {
  std::string notes;
  for (const std::string &note : hoct::gll_notes(g))
    notes += (notes.empty() ? "" : "; ") + note;
  return notes;
}

// The notes as field data "Notes" of the outputs (none without notes).
void add_notes(const std::string &notes, vtkPolyData *points, vtkPolyData *arcs,
               vtkPolyData *simplified) {
  if (notes.empty())
    return;
  for (vtkPolyData *out : {points, arcs, simplified})
    add_string(out, "Notes", notes);
}

// How the input is spread over the processes (pvbatch, pvserver under MPI): this process's rank,
// the cells of all pieces and how many pieces have cells. Collective: every process of the global
// controller runs the filter's RequestData (ParaView executes a pipeline on all of them), so it
// is the first thing RequestData does, before anything that can fail. One process (pvpython,
// the GUI's built-in server, no controller): the local piece alone.
struct Pieces {
  int rank = 0;
  vtkIdType cells = 0, with_cells = 0;
};
Pieces pieces(vtkIdType local_cells) {
  Pieces p{0, local_cells, local_cells > 0 ? 1 : 0};
  vtkMultiProcessController *c = vtkMultiProcessController::GetGlobalController();
  if (!c || c->GetNumberOfProcesses() < 2)
    return p;
  p.rank = c->GetLocalProcessId();
  const vtkIdType send[2] = {p.cells, p.with_cells};
  vtkIdType sum[2] = {0, 0};
  c->AllReduce(send, sum, 2, vtkCommunicator::SUM_OP);
  p.cells = sum[0];
  p.with_cells = sum[1];
  return p;
}

// The outputs of a piece without cells: empty, with the arrays of a tree (so that appending the
// pieces, as ParaView does to fetch or render them, keeps the other pieces' arrays).
void empty_outputs(bool simplified_output, vtkPolyData *points, vtkPolyData *arcs,
                   vtkPolyData *simplified) {
  const hoct::TreePolyData none;
  hoct::paraview::critical_points_polydata(none, points);
  hoct::paraview::arcs_polydata(none, /*with_nodes=*/false, arcs);
  if (simplified_output)
    hoct::paraview::arcs_polydata(none, /*with_nodes=*/true, simplified);
}

// The array name the filter's input array 0 asks for ("" when none: the property is unset, or
// the request is for the active scalars).
std::string requested_name(vtkInformation *info) {
  const char *name = info && info->Has(vtkDataObject::FIELD_NAME())
                         ? info->Get(vtkDataObject::FIELD_NAME())
                         : nullptr;
  return name ? name : "";
}

// The tree (and its simplification) as the three outputs, with the statistics and the scalar's
// name as field data.
void tree_outputs(const hoct::TreeOutcome &out, const std::string &scalar_name, vtkPolyData *points,
                  vtkPolyData *arcs, vtkPolyData *simplified) {
  const hoct::TreePolyData layout = hoct::tree_polydata(out.tree);
  hoct::paraview::critical_points_polydata(layout, points);
  hoct::paraview::arcs_polydata(layout, /*with_nodes=*/false, arcs);
  add_stats(out.tree, points);
  add_string(points, "Scalar", scalar_name);
  add_string(arcs, "Scalar", scalar_name);
  if (out.simplified) {
    hoct::paraview::arcs_polydata(hoct::tree_polydata(*out.simplified), /*with_nodes=*/true,
                                  simplified);
    add_stats(*out.simplified, simplified);
    add_string(simplified, "Scalar", scalar_name);
  }
}

} // namespace

int vtkHoctContourTree::RequestData(vtkInformation *, vtkInformationVector **inputVector,
                                    vtkInformationVector *outputVector) {
  vtkUnstructuredGrid *grid = vtkUnstructuredGrid::GetData(inputVector[0]);
  vtkPolyData *points = vtkPolyData::GetData(outputVector, 0);
  vtkPolyData *arcs = vtkPolyData::GetData(outputVector, 1);
  vtkPolyData *simplified = vtkPolyData::GetData(outputVector, 2);
  const Pieces all = pieces(grid ? grid->GetNumberOfCells() : 0);
#ifdef HOCT_WITH_MPI
  if (all.with_cells > 1)
    return this->RequestDistributed(inputVector, grid, points, arcs, simplified);
#else
  if (all.with_cells > 1 && !this->WarnedPerPiece && all.rank == 0) {
    this->WarnedPerPiece = true;
    vtkWarningMacro("Higher-Order Contour Tree: the input is split into "
                    << all.with_cells
                    << " pieces with cells over the processes; this plugin was built without "
                       "MPI, so each process computes the tree of its own piece, not of the "
                       "whole domain. For the whole domain's tree, run on one process or "
                       "gather the cells onto one.");
  }
#endif
  if (!grid || !points || !arcs || !simplified) {
    vtkErrorMacro("Higher-Order Contour Tree: missing input or output");
    return 0;
  }
  const bool simplified_output = this->PersistenceThreshold > 0 && !this->Augmented;
  if (grid->GetNumberOfCells() == 0) {
    // An empty piece (a process the input's cells are not on, an empty upstream selection):
    // empty outputs, no error.
    if (all.cells == 0 && all.rank == 0)
      vtkWarningMacro("Higher-Order Contour Tree: the input has no cells; the outputs are empty");
    empty_outputs(simplified_output, points, arcs, simplified);
    return 1;
  }
  try {
    // The properties as a library request: the same call as `hoct tree` (pipeline/compute_tree).
    hoct::TreeRequest rq = this->MakeRequest();
    rq.arcs = hoct::ArcGeometry::AllPaths;
    if (!simplified_output && this->PersistenceThreshold > 0)
      vtkWarningMacro("Higher-Order Contour Tree: simplification works on the reduced tree; "
                      "turn Augmented off to get output 2");
    bool by_default = false;
    vtkDataArray *scalar = hoct::paraview::point_scalar(
        grid, this->GetInputArrayToProcess(0, inputVector),
        requested_name(this->GetInputArrayInformation(0)), &by_default);
    const std::string scalar_name = scalar->GetName() ? scalar->GetName() : "";
    vtkDebugMacro("Higher-Order Contour Tree: the tree of point array '"
                  << scalar_name << "'" << (by_default ? " (the default: none was named)" : ""));
    hoct::MeshInput input = hoct::paraview::mesh_input_from_grid(grid, scalar);
    // DOLFINx's degree >= 3 nodes at GLL points, resampled as `hoct tree` reads them.
    const std::string notes = gll_note_text(hoct::resample_gll_cells(input));
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
    tree_outputs(out, scalar_name, points, arcs, simplified);
    add_notes(notes, points, arcs, simplified);
  } catch (const std::exception &e) {
    points->Initialize();
    arcs->Initialize();
    simplified->Initialize();
    vtkErrorMacro("Higher-Order Contour Tree: " << e.what());
    return 0;
  }
  return 1;
}

hoct::TreeRequest vtkHoctContourTree::MakeRequest() const {
  hoct::TreeRequest rq;
  rq.method = this->Method == LINEAR   ? hoct::TreeMethod::Linear
              : this->Method == REFINE ? hoct::TreeMethod::Refine
                                       : hoct::TreeMethod::Exact;
  rq.refine = this->RefineLevel;
  rq.augmented = this->Augmented;
  rq.keep_flat = this->KeepFlat;
  rq.force = this->Force;
  rq.threads = this->Threads;
  if (this->PersistenceThreshold > 0 && !this->Augmented) // output 2, the simplified tree
    rq.simplify =
        hoct::Threshold{this->PersistenceThreshold, this->ThresholdMode == PERCENT_OF_RANGE};
  return rq;
}

#ifdef HOCT_WITH_MPI
int vtkHoctContourTree::RequestDistributed(vtkInformationVector **inputVector,
                                           vtkUnstructuredGrid *grid, vtkPolyData *points,
                                           vtkPolyData *arcs, vtkPolyData *simplified) {
  // Every process of the global controller is here (ParaView runs the pipeline on all of them):
  // the collective steps below are reached by each, whatever fails.
  auto *controller =
      vtkMPIController::SafeDownCast(vtkMultiProcessController::GetGlobalController());
  const int rank = controller ? controller->GetLocalProcessId() : 0;
  const bool simplified_output = this->PersistenceThreshold > 0 && !this->Augmented;
  empty_outputs(simplified_output, points, arcs, simplified);
  if (!controller) {
    vtkErrorMacro("Higher-Order Contour Tree: the input is spread over processes without an MPI "
                  "controller; run on one process");
    return 0;
  }
  const MPI_Comm comm =
      *static_cast<vtkMPICommunicator *>(controller->GetCommunicator())->GetMPIComm()->GetHandle();
  std::string scalar_name;
  bool collectives_done = false;
  try {
    // This process's scalar (a failure travels with its piece, so that every process stops).
    std::string failure;
    vtkDataArray *scalar = nullptr;
    if (grid && grid->GetNumberOfCells() > 0) {
      try {
        bool by_default = false;
        scalar = hoct::paraview::point_scalar(grid, this->GetInputArrayToProcess(0, inputVector),
                                              requested_name(this->GetInputArrayInformation(0)),
                                              &by_default);
      } catch (const std::exception &e) {
        failure = e.what();
      }
    }
    const int threads = hoct::thread_count(this->Threads);
    // The properties as a request, as `mpirun hoct tree` makes it; the arcs drawn straight
    // unless asked for (the pieces draw them: distributed_arc_paths).
    hoct::TreeRequest rq = this->MakeRequest();
    rq.arcs = this->ArcPathsOverProcesses ? hoct::ArcGeometry::AllPaths : hoct::ArcGeometry::None;
    // Each process keeps its own piece, joined with the others' as `mpirun hoct tree` joins a
    // .pvtu's pieces; where the processes cannot join them alone (or one failed), every process
    // gathers the whole mesh, which reports what is wrong as one process would.
    std::vector<hoct::FilePiece> own;
    if (failure.empty()) {
      try {
        own = hoct::paraview::own_piece(grid, scalar, rank);
      } catch (const std::exception &e) {
        failure = e.what();
      }
    }
    hoct::ReadLimits limits;
    limits.threads = threads;
    hoct::RankRead read =
        hoct::join_rank_pieces(std::move(own), failure, "the input's pieces", limits, comm);
    this->UpdateProgress(0.2);
    hoct::DistributedOutcome d;
    // How the mesh was spread (field data "Distribution" of rank 0's outputs).
    std::string distribution;
    std::string notes;
    if (read.input) {
      distribution = "each process its own piece";
      scalar_name = read.input->field_name;
      // The whole on rank 0 (a mesh the pieces found a problem in): the pieces again, joined
      // there.
      read.input->read_whole = [grid, scalar, rank, threads, comm] {
        return hoct::join_pieces_on_root(hoct::paraview::own_piece(grid, scalar, rank),
                                         "the input's pieces", threads, comm);
      };
      // DOLFINx's degree >= 3 nodes at GLL points: each process resamples its piece, as one
      // process resamples the whole (and the whole where rank 0 needs it).
      notes = gll_note_text(hoct::resample_gll_share(*read.input, comm));
      d = hoct::distributed_tree(std::move(*read.input), rq, comm);
    } else {
      distribution = "the whole mesh on every process (" + read.fallback + ")";
      hoct::MeshInput whole =
          hoct::paraview::gather_whole(controller, grid, scalar, failure, threads, &scalar_name);
      notes = gll_note_text(hoct::resample_gll_cells(whole));
      d = hoct::distributed_tree(whole, rq, comm);
    }
    collectives_done = true;
    if (rank != 0)
      return 1;
    for (const auto &why : d.outcome.warnings)
      vtkWarningMacro("Higher-Order Contour Tree: Force: " << why);
    tree_outputs(d.outcome, scalar_name, points, arcs, simplified);
    if (!d.whole_check.empty())
      distribution += "; checks: the whole mesh on process 0 (" + d.whole_check + ")";
    if (!d.whole_tree.empty())
      distribution += "; tree: the whole mesh on process 0 (" + d.whole_tree + ")";
    if (d.arc_paths.arcs > 0)
      distribution += "; arcs: drawn by the processes' pieces (" +
                      std::to_string(d.arc_paths.straight) + " straight)";
    add_string(points, "Distribution", distribution);
    add_string(arcs, "Distribution", distribution);
    if (simplified_output)
      add_string(simplified, "Distribution", distribution);
    add_notes(notes, points, arcs, simplified);
  } catch (const hoct::AgreedError &e) {
    // Every process has it: reported once, by rank 0.
    if (rank == 0)
      vtkErrorMacro("Higher-Order Contour Tree: " << e.what());
    empty_outputs(simplified_output, points, arcs, simplified);
    return rank == 0 ? 0 : 1;
  } catch (const hoct::InputError &e) {
    // From the gathered pieces, which every process sees alike: every process has it too.
    if (rank == 0)
      vtkErrorMacro("Higher-Order Contour Tree: " << e.what());
    empty_outputs(simplified_output, points, arcs, simplified);
    return rank == 0 ? 0 : 1;
  } catch (const std::exception &e) {
    if (!collectives_done) {
      // This process's alone, and the others would wait for it at the next collective step.
      std::fprintf(stderr, "Higher-Order Contour Tree: error (process %d): %s\n", rank, e.what());
      MPI_Abort(comm, 1);
    }
    vtkErrorMacro("Higher-Order Contour Tree: " << e.what());
    return 0;
  }
  return 1;
}
#endif

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
