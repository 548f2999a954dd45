// The ParaView filter "Higher-Order Contour Tree": the exact contour tree (hoct) of a point scalar
// on an unstructured grid of linear, quadratic or Lagrange triangles. Output 0: the critical
// points as vertices; output 1: the arcs as polylines on the surface; output 2: the simplified
// tree (nodes and arcs) when PersistenceThreshold > 0. All outputs are vtkPolyData; the input is
// a vtkUnstructuredGrid (FillInputPortInformation).
#ifndef vtkHoctContourTree_h
#define vtkHoctContourTree_h

#include "HoctParaViewModule.h"
#include "vtkPolyDataAlgorithm.h"

namespace hoct {
struct TreeRequest;
}

class vtkPolyData;
class vtkUnstructuredGrid;

class HOCTPARAVIEW_EXPORT vtkHoctContourTree : public vtkPolyDataAlgorithm {
public:
  static vtkHoctContourTree *New();
  vtkTypeMacro(vtkHoctContourTree, vtkPolyDataAlgorithm);
  void PrintSelf(ostream &os, vtkIndent indent) override;

  // Leaf branches with persistence below this are removed in output 2 (0: no output 2).
  vtkSetClampMacro(PersistenceThreshold, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(PersistenceThreshold, double);

  // How PersistenceThreshold is read: PERCENT_OF_RANGE (of the tree's value range, as
  // `hoct tree --simplify 1%`) or ABSOLUTE.
  enum ThresholdModes { PERCENT_OF_RANGE = 0, ABSOLUTE = 1 };
  vtkSetClampMacro(ThresholdMode, int, PERCENT_OF_RANGE, ABSOLUTE);
  vtkGetMacro(ThresholdMode, int);

  // Keep the regular (degree-2) nodes (`hoct tree --augmented`); no simplification then.
  vtkSetMacro(Augmented, bool);
  vtkGetMacro(Augmented, bool);
  vtkBooleanMacro(Augmented, bool);

  // The tree's method: EXACT (the piecewise-polynomial field), LINEAR (PL of the input's nodes,
  // `hoct tree --linear`) or REFINE (PL of the exact field on RefineLevel x RefineLevel
  // sub-triangles per cell, `hoct tree --refine K`).
  enum Methods { EXACT = 0, LINEAR = 1, REFINE = 2 };
  vtkSetClampMacro(Method, int, EXACT, REFINE);
  vtkGetMacro(Method, int);
  vtkSetClampMacro(RefineLevel, int, 1, 1024);
  vtkGetMacro(RefineLevel, int);

  // Keep the nodes and zero-length arcs of plateaus (`hoct tree --keep-flat`).
  vtkSetMacro(KeepFlat, bool);
  vtkGetMacro(KeepFlat, bool);
  vtkBooleanMacro(KeepFlat, bool);

  // Compute what is well defined on a domain that is not one disk or sphere, or past inverted
  // cells and unmerged duplicate vertices (`hoct tree --force`); the outputs' field data say why.
  vtkSetMacro(Force, bool);
  vtkGetMacro(Force, bool);
  vtkBooleanMacro(Force, bool);

  // On several processes with cells: draw the arcs on the surface, as on one process (as
  // `mpirun hoct tree --vtp` does): the pieces draw the arcs together, no process holding the
  // whole mesh (the default). Off: straight arcs.
  vtkSetMacro(ArcPathsOverProcesses, bool);
  vtkGetMacro(ArcPathsOverProcesses, bool);
  vtkBooleanMacro(ArcPathsOverProcesses, bool);

  // Threads for the mesh build, the tree and the arcs (0: all cores). The result does not
  // depend on it.
  vtkSetClampMacro(Threads, int, 0, 1024);
  vtkGetMacro(Threads, int);

protected:
  vtkHoctContourTree();
  ~vtkHoctContourTree() override = default;

  int FillInputPortInformation(int port, vtkInformation *info) override;
  int RequestData(vtkInformation *request, vtkInformationVector **inputVector,
                  vtkInformationVector *outputVector) override;

  double PersistenceThreshold = 0.0;
  int ThresholdMode = PERCENT_OF_RANGE;
  bool Augmented = false;
  int Method = EXACT;
  int RefineLevel = 4;
  bool KeepFlat = false;
  bool Force = false;
  bool ArcPathsOverProcesses = true;
  int Threads = 0;
  bool WarnedPerPiece = false; // the per-piece warning (a build without MPI) is given once

private:
  // The properties as a library request (the arcs' geometry left to the caller).
  hoct::TreeRequest MakeRequest() const;
  // The input spread over the processes (pvbatch, pvserver under MPI): the pieces gathered and
  // the tree computed over the processes (distributed/distributed_tree), its outputs on rank 0.
  int RequestDistributed(vtkInformationVector **inputVector, vtkUnstructuredGrid *grid,
                         vtkPolyData *points, vtkPolyData *arcs, vtkPolyData *simplified);

  vtkHoctContourTree(const vtkHoctContourTree &) = delete;
  void operator=(const vtkHoctContourTree &) = delete;
};

#endif
