"""Partitioned outputs written by VTK itself, for the tests: a .vtu read with VTK's reader, and
split into pieces by VTK's streaming pipeline (vtkExtractUnstructuredGridPiece) written by
vtkXMLPUnstructuredGridWriter. Needs VTK's Python module (python3-paraview's vtkmodules)."""
import os

import vtk


def read_grid(path):
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput()


def with_ids(grid, name):
    """The grid with an id array `name` (ids that are no point indices)."""
    gid = vtk.vtkIdTypeArray()
    gid.SetName(name)
    for i in range(grid.GetNumberOfPoints()):
        gid.InsertNextValue(1000 + 7 * i)
    grid.GetPointData().AddArray(gid)
    return grid


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


def write_hand_cut(grid, directory, name="hand"):
    """The grid cut by hand into 3 pieces of consecutive cells, the middle one empty, each
    piece's points given a plain array named GlobalIds (not the GlobalIds attribute), listed by
    `directory/name.pvtu`; returns that path."""
    n = grid.GetNumberOfCells()
    plain = vtk.vtkIdTypeArray()
    plain.SetName("GlobalIds")
    for i in range(grid.GetNumberOfPoints()):
        plain.InsertNextValue(5 + 3 * i)
    grid.GetPointData().AddArray(plain)
    return write_cell_ranges(grid, directory, name, [(0, n // 3), (n // 3, n // 3), (n // 3, n)])


def write_consecutive(grid, directory, name, pieces):
    """The grid cut into `pieces` pieces of consecutive cells (as `mpirun -np pieces hoct tree`
    cuts a .vtu), each piece's points with the GlobalIds attribute (their ids in the grid),
    listed by `directory/name.pvtu`; returns that path."""
    n = grid.GetNumberOfCells()
    ids = vtk.vtkIdTypeArray()
    ids.SetName("GlobalIds")
    for i in range(grid.GetNumberOfPoints()):
        ids.InsertNextValue(i)
    grid.GetPointData().SetGlobalIds(ids)
    return write_cell_ranges(grid, directory, name,
                             [(k * n // pieces, (k + 1) * n // pieces) for k in range(pieces)],
                             attribute="GlobalIds")


def write_cell_ranges(grid, directory, name, ranges, attribute=None):
    """Piece k: the grid's cells [lo, hi) of ranges[k], as directory/name_k.vtu (its array
    `attribute`, if given, declared the GlobalIds attribute again: extracting drops it), listed
    by directory/name.pvtu; returns that path."""
    files = []
    for k, (lo, hi) in enumerate(ranges):
        cells = vtk.vtkIdList()
        for c in range(lo, hi):
            cells.InsertNextId(c)
        ex = vtk.vtkExtractCells()
        ex.SetInputData(grid)
        ex.SetCellList(cells)
        ex.Update()
        piece = ex.GetOutput()
        if attribute:
            piece.GetPointData().SetGlobalIds(piece.GetPointData().GetArray(attribute))
        w = vtk.vtkXMLUnstructuredGridWriter()
        w.SetInputData(piece)
        files.append(f"{name}_{k}.vtu")
        w.SetFileName(os.path.join(directory, files[-1]))
        w.Write()
    path = os.path.join(directory, f"{name}.pvtu")
    write_listing(path, files)
    return path


def write_listing(path, files, field="f"):
    """A .pvtu listing `files` (relative to its directory), ghost level 0, point data `field`."""
    with open(path, "w") as f:
        f.write('<?xml version="1.0"?>\n<VTKFile type="PUnstructuredGrid" version="0.1">\n'
                f' <PUnstructuredGrid GhostLevel="0">\n  <PPointData Scalars="{field}">\n'
                f'   <PDataArray type="Float64" Name="{field}"/>\n  </PPointData>\n'
                '  <PPoints><PDataArray type="Float64" NumberOfComponents="3"/></PPoints>\n'
                + "".join(f'  <Piece Source="{p}"/>\n' for p in files)
                + " </PUnstructuredGrid>\n</VTKFile>\n")
