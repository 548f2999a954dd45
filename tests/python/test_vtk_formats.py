"""Formats read through VTK's own readers (src/vtkio), written by VTK itself.

`hoct generate heater` (12,324 curved cubic cells, VTK_LAGRANGE_TRIANGLE) and `hoct generate
gauss --degree 1` are read by VTK's XML reader and written again by VTK's writers: legacy .vtk
(binary and ascii, an unstructured grid; the linear one also as polydata), .vtu with LZ4 and
LZMA compression, a .vtm of two blocks (the cells split in two; the shared points joined by
position) and XDMF 3 (vtkXdmf3Writer, linear cells only). Each gives the same tree as hoct's
own reader of the original .vtu: the same nodes (type, value, position) and persistence pairs.
XDMF's linear data is read with the warning that it holds vertex values only. Bad files end with
exit status 1 and a message naming the file, never a crash: empty and foreign files, every
truncation of a legacy file on a grid of offsets, an XDMF file without its HDF5 file, a foreign
.e, a step or array that is not there.

Run by ctest with /usr/bin/python3 and HOCT_BIN set to the hoct executable."""
import os
import sys

import vtk

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from hoct_testing import Results, compare_trees, run, tempdir, tree_json  # noqa: E402

r = Results()


def read_vtu(path):
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput()


def same_tree(name, path, reference, *extra, tol=1e-12):
    """The tree of path (with extra options) against reference, within tol (ascii files round
    their values)."""
    try:
        j, res = tree_json(path, *extra)
    except RuntimeError as e:
        r.check(False, f"{name}: {e}")
        return None
    compare_trees(r, name, j, reference, tol)
    return res


def write(writer, path, data):
    writer.SetFileName(path)
    writer.SetInputData(data)
    r.check(writer.Write() == 1, f"VTK could not write {path}")


def expect_error(name, args, needle):
    res = run(*args, check=False)
    r.check(res.returncode == 1, f"{name}: exit status {res.returncode}, expected 1 "
            f"({res.stderr.strip()[-300:]})")
    r.check(needle in res.stderr, f"{name}: expected '{needle}' in: {res.stderr.strip()[-300:]}")


with tempdir() as d:
    p = lambda name: os.path.join(d, name)  # noqa: E731
    run("generate", "heater", "-o", p("heater.vtu"))
    run("generate", "gauss", "--degree", "1", "-o", p("gauss1.vtu"))
    heater, _ = tree_json(p("heater.vtu"))
    gauss1, _ = tree_json(p("gauss1.vtu"))
    g = read_vtu(p("heater.vtu"))
    g1 = read_vtu(p("gauss1.vtu"))

    # Legacy .vtk, binary and ascii.
    for kind in ("Binary", "ASCII"):
        w = vtk.vtkUnstructuredGridWriter()
        getattr(w, "SetFileTypeTo" + kind)()
        write(w, p(f"heater_{kind}.vtk"), g)
        same_tree(f"legacy {kind}", p(f"heater_{kind}.vtk"), heater,
                  tol=1e-12 if kind == "Binary" else 1e-5)
    # Legacy polydata of the linear triangles.
    geometry = vtk.vtkGeometryFilter()
    geometry.SetInputData(g1)
    geometry.Update()
    write(vtk.vtkPolyDataWriter(), p("gauss1_poly.vtk"), geometry.GetOutput())
    same_tree("legacy polydata (ascii)", p("gauss1_poly.vtk"), gauss1, tol=1e-5)

    # .vtu compressed with LZ4 and LZMA (hoct's reader hands them to VTK's).
    for comp in ("LZ4", "LZMA"):
        w = vtk.vtkXMLUnstructuredGridWriter()
        getattr(w, "SetCompressorTypeTo" + comp)()
        write(w, p(f"heater_{comp}.vtu"), g)
        same_tree(f".vtu {comp}", p(f"heater_{comp}.vtu"), heater)
        res = run("info", p(f"heater_{comp}.vtu"))
        r.check("12324" in res.stdout, f".vtu {comp}: hoct info: {res.stdout[:200]}")

    # A .vtm of two blocks: the cells left and right of x = 1, each block with its own points.
    def block(keep):
        ids = vtk.vtkIdTypeArray()
        for c in range(g.GetNumberOfCells()):
            b = g.GetCell(c).GetBounds()
            if keep(0.5 * (b[0] + b[1])):
                ids.InsertNextValue(c)
        sel = vtk.vtkSelectionNode()
        sel.SetFieldType(vtk.vtkSelectionNode.CELL)
        sel.SetContentType(vtk.vtkSelectionNode.INDICES)
        sel.SetSelectionList(ids)
        s = vtk.vtkSelection()
        s.AddNode(sel)
        e = vtk.vtkExtractSelection()
        e.SetInputData(0, g)
        e.SetInputData(1, s)
        e.Update()
        out = vtk.vtkUnstructuredGrid()
        out.DeepCopy(e.GetOutput())
        for name in ("vtkOriginalPointIds", "vtkOriginalCellIds"):
            out.GetPointData().RemoveArray(name)
            out.GetCellData().RemoveArray(name)
        return out
    mid = 0.5 * (g.GetBounds()[0] + g.GetBounds()[1])
    mb = vtk.vtkMultiBlockDataSet()
    mb.SetBlock(0, block(lambda x: x < mid))
    mb.SetBlock(1, block(lambda x: x >= mid))
    r.check(mb.GetBlock(0).GetNumberOfCells() + mb.GetBlock(1).GetNumberOfCells() ==
            g.GetNumberOfCells() and mb.GetBlock(0).GetNumberOfCells() > 0,
            "the two blocks hold every cell once")
    write(vtk.vtkXMLMultiBlockDataWriter(), p("heater.vtm"), mb)
    same_tree(".vtm of two blocks", p("heater.vtm"), heater)

    # XDMF 3 (linear cells: vtkXdmf3Writer writes no Lagrange cells).
    write(vtk.vtkXdmf3Writer(), p("gauss1.xdmf"), g1)
    res = same_tree("XDMF", p("gauss1.xdmf"), gauss1)
    r.check(res is not None and "XDMF holds values at the mesh's nodes only" in res.stderr,
            "XDMF: the vertex-values warning")
    res = run("info", p("gauss1.xdmf"))
    r.check("fields:" in res.stdout and "point data" in res.stdout,
            f"XDMF: hoct info lists the point arrays: {res.stdout[:300]}")

    # Bad files.
    open(p("empty.vtk"), "w").close()
    expect_error("empty .vtk", ["tree", p("empty.vtk")], "empty.vtk: the file is empty")
    with open(p("foreign.vtk"), "w") as f:
        f.write("solid cube\nfacet normal 0 0 1\n")
    expect_error("foreign .vtk", ["tree", p("foreign.vtk")], "not a legacy VTK file")
    with open(p("foreign.e"), "w") as f:
        f.write("not netcdf at all\n")
    expect_error("foreign .e", ["info", p("foreign.e")], "not an Exodus II file")
    os.makedirs(p("alone"))
    with open(p("gauss1.xdmf")) as src, open(p("alone/gauss1.xdmf"), "w") as dst:
        dst.write(src.read())
    expect_error("XDMF without HDF5", ["tree", p("alone/gauss1.xdmf")], "is missing")
    expect_error("--step on one step", ["tree", p("heater_Binary.vtk"), "--step", "3"],
                 "--step 3: the file has 1 step")
    expect_error("missing array", ["tree", p("heater_Binary.vtk"), "--scalar", "nope"],
                 "no numeric point array named 'nope'")
    # Truncations of the ascii legacy file: each read fails cleanly or reads a valid prefix
    # (VTK's legacy reader stops at the end of the data); never a crash.
    with open(p("heater_ASCII.vtk"), "rb") as f:
        data = f.read()
    crashes = 0
    for k in range(1, 24):
        cut = len(data) * k // 24
        with open(p("cut.vtk"), "wb") as f:
            f.write(data[:cut])
        res = run("info", p("cut.vtk"), check=False)
        if res.returncode not in (0, 1) or (res.returncode == 1 and "cut.vtk" not in res.stderr):
            crashes += 1
            print(f"truncated at {cut}: exit {res.returncode}: {res.stderr.strip()[-200:]}")
    r.check(crashes == 0, f"{crashes} truncations of a legacy file crashed or gave no message")

r.finish()
