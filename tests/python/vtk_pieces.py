"""Partitioned outputs written by VTK itself, for the tests: a .vtu read with VTK's reader, and
split into pieces by VTK's streaming pipeline (vtkExtractUnstructuredGridPiece) written by
vtkXMLPUnstructuredGridWriter. Needs VTK's Python module (python3-paraview's vtkmodules)."""
import vtk


def read_grid(path):
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput()


def write_pieces(grid, path, pieces, ghost_level, ids=None):
    """grid split into `pieces` by VTK's streaming pipeline; ids: the name of an id array of the
    grid to declare as the point data's GlobalIds attribute in every piece."""
    extract = vtk.vtkExtractUnstructuredGridPiece()
    extract.SetInputData(grid)
    last = extract
    if ids:
        # Filters do not pass the GlobalIds attribute on: declared again after the split.
        declare = vtk.vtkProgrammableFilter()
        declare.SetInputConnection(extract.GetOutputPort())

        def execute():
            out = declare.GetUnstructuredGridOutput()
            out.ShallowCopy(declare.GetUnstructuredGridInput())
            out.GetPointData().SetGlobalIds(out.GetPointData().GetArray(ids))

        declare.SetExecuteMethod(execute)
        last = declare
    w = vtk.vtkXMLPUnstructuredGridWriter()
    w.SetInputConnection(last.GetOutputPort())
    w.SetFileName(path)
    w.SetNumberOfPieces(pieces)
    w.SetStartPiece(0)
    w.SetEndPiece(pieces - 1)
    w.SetGhostLevel(ghost_level)
    w.Write()
