"""`mpirun -np N hoct tree FILE.vtu`: each rank reads its own part of one .vtu (issue 31).

The ranks read a .vtu whose arrays are raw appended data by parts (io/vtu_cell_range,
distributed/vtu_by_ranks): rank r reads the r-th share of the cells, the points they use and the
r-th share of the points, which it checks and hashes; no rank reads the whole. The independent
truth is hoct's own single-process tree, computed without MPI: the JSON (--no-timings, with the
input's fingerprint) must be byte-identical for 1, 2, 3, 4 and 7 ranks, and the summary must not
say that rank 0 read the whole. Files written by VTK's own writer (python3-vtk9) are read by
parts too: zlib-compressed in blocks of 1 KiB (so that every part's range crosses blocks), a
UInt32 header, Float32 points, a vector field by component and by magnitude, vertex and line
cells among the triangles (skipped, as one process skips them), points numbered at random
(every rank's points spread over the whole file; in a file of 30,000 cells, on 4 and 7 ranks each
rank gets its cells' points from the ranks that read them, and says so), and DOLFINx's edge
nodes at Gauss-Lobatto points (each rank resamples its part). A file that cannot be read by parts (inline
arrays, appended base64) is read whole by rank 0, which says so and why, with the same JSON. A
problem a part finds (a NaN among its points, a cell naming a point the file does not have) is
reported as one process reports it, once.

Skipped (exit 77) without mpirun or an MPI build of hoct."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from hoct_testing import Results, run, tempdir  # noqa: E402
from mpi_testing import PYTHON, mpi, read, require_mpi_hoct  # noqa: E402

r = Results()
WHOLE = "reads the whole of"
NUMBERED_FAR = "numbered far from their cells"


def same_tree(label, path, ranks, extra=(), by_parts=True):
    want = path + ".want.json"
    run("tree", path, "--json", want, "--no-timings", "-q", *extra)
    for n in ranks:
        got = f"{path}.{n}.json"
        p = mpi(n, "tree", path, "--json", got, "--no-timings", *extra)
        r.check(p.returncode == 0, f"{label}, {n} ranks: exit {p.returncode}: {p.stderr[-1500:]}")
        if p.returncode != 0:
            continue
        r.check(read(got) == read(want), f"{label}, {n} ranks: JSON differs from one process")
        if by_parts:
            r.check(WHOLE not in p.stderr, f"{label}, {n} ranks: read whole:\n{p.stderr[-800:]}")
        else:
            r.check(WHOLE in p.stderr, f"{label}, {n} ranks: no note that rank 0 read it whole:\n{p.stderr[-800:]}")
    print(f"{label}: {list(ranks)} ranks checked", flush=True)


def same_error(label, path, ranks=(2, 3)):
    plain = run("tree", path, check=False)
    first = plain.stderr.strip().splitlines()[0] if plain.stderr.strip() else ""
    for n in ranks:
        p = mpi(n, "tree", path)
        r.check(plain.returncode != 0 and p.returncode != 0 and first and first in p.stderr
                and p.stderr.count("hoct: error:") == 1,
                f"{label}, {n} ranks: {first!r} once in\n{p.stderr[-1500:]}")
    print(f"{label}: the error of one process", flush=True)


# VTK's writer: the generated file read by VTK, changed, written zlib-compressed in small blocks.
VTK_REWRITE = r'''
import sys
import numpy as np
import vtk
from vtk.util import numpy_support as ns

src, dst, mode = sys.argv[1:4]
reader = vtk.vtkXMLUnstructuredGridReader()
reader.SetFileName(src)
reader.Update()
grid = reader.GetOutput()
n = grid.GetNumberOfPoints()
f = ns.vtk_to_numpy(grid.GetPointData().GetArray("f")).astype(np.float64)
xyz = ns.vtk_to_numpy(grid.GetPoints().GetData()).astype(np.float64)
out = vtk.vtkUnstructuredGrid()
perm = np.arange(n)
if mode == "shuffled":
    perm = np.random.default_rng(5).permutation(n)  # new id of old point i
inverse = np.empty(n, dtype=np.int64)
inverse[perm] = np.arange(n)
pts = vtk.vtkPoints()
pts.SetDataTypeToFloat()  # Float32 points
pts.SetData(ns.numpy_to_vtk(xyz[inverse].astype(np.float32), deep=1))
out.SetPoints(pts)
out.Allocate(grid.GetNumberOfCells() + 4)
for c in range(grid.GetNumberOfCells()):
    cell = grid.GetCell(c)
    ids = [int(perm[cell.GetPointId(k)]) for k in range(cell.GetNumberOfPoints())]
    if mode == "mixed" and c % 97 == 5:  # vertex and line cells among the triangles: skipped
        out.InsertNextCell(vtk.VTK_VERTEX, 1, ids[:1])
        out.InsertNextCell(vtk.VTK_LINE, 2, ids[:2])
    out.InsertNextCell(grid.GetCellType(c), len(ids), ids)
if mode == "gll":  # edge nodes moved to the GLL points of their (straight) edges, as DOLFINx
    t = (1 - 1 / np.sqrt(5)) / 2  # degree 3: GLL points t and 1 - t of each edge
    xyz = xyz.copy()
    for c in range(grid.GetNumberOfCells()):
        cell = grid.GetCell(c)
        ids = [cell.GetPointId(k) for k in range(cell.GetNumberOfPoints())]
        for e, (a, b) in enumerate(((0, 1), (1, 2), (2, 0))):
            pa, pb = xyz[ids[a]], xyz[ids[b]]
            xyz[ids[3 + 2 * e]] = pa + t * (pb - pa)
            xyz[ids[4 + 2 * e]] = pa + (1 - t) * (pb - pa)
    pts.SetData(ns.numpy_to_vtk(xyz[inverse].astype(np.float64), deep=1))
vec = np.stack([f[inverse], np.cos(3 * xyz[inverse, 0]) * f[inverse], xyz[inverse, 1]], axis=1)
a = ns.numpy_to_vtk(vec, deep=1)
a.SetName("u")
out.GetPointData().AddArray(a)
s = ns.numpy_to_vtk(f[inverse].copy(), deep=1)
s.SetName("f")
out.GetPointData().AddArray(s)
w = vtk.vtkXMLUnstructuredGridWriter()
w.SetFileName(dst)
w.SetInputData(out)
w.SetDataModeToAppended()
w.EncodeAppendedDataOff()
w.SetCompressorTypeToZLib()
w.SetBlockSize(1024)
w.SetHeaderTypeToUInt32()
assert w.Write() == 1
'''

with tempdir() as d:
    require_mpi_hoct()
    # hoct's own files (raw appended, uncompressed): triangles, a plateau, quadrilaterals.
    for k, (name, gen, extra) in enumerate([
            ("random", ["--cells", "3000", "--plateau", "30"], []),
            ("sphere", ["--cells", "2000"], []),
            ("random", ["--cells", "1500", "--quads", "--degree", "3"], ["--linear"])]):
        path = os.path.join(d, f"{name}{k}.vtu")
        run("generate", name, *gen, "-o", path)
        same_tree(f"{name} {' '.join(gen + extra)}", path, (1, 2, 3, 4, 7), extra)

    # Files rank 0 reads whole, saying why: inline arrays, appended base64.
    base = os.path.join(d, "base.vtu")
    for encoding in ("zlib", "appended-base64"):
        path = os.path.join(d, f"{encoding}.vtu")
        run("generate", "random", "--cells", "2000", "--encoding", encoding, "-o", path)
        same_tree(f"--encoding {encoding}", path, (2, 3), by_parts=False)
        p = mpi(2, "tree", path)
        r.check("its arrays are not raw appended data" in p.stderr, f"{encoding}: why:\n{p.stderr}")

    # Written by VTK: zlib blocks of 1 KiB, UInt32 headers, Float32 points, a vector field.
    run("generate", "random", "--cells", "3000", "-o", base)
    import subprocess
    if subprocess.run([PYTHON, "-c", "import vtk"], capture_output=True).returncode == 0:
        for mode in ("plain", "mixed", "shuffled", "gll"):
            path = os.path.join(d, f"vtk-{mode}.vtu")
            p = subprocess.run([PYTHON, "-c", VTK_REWRITE, base, path, mode], capture_output=True,
                               text=True)
            r.check(p.returncode == 0, f"VTK's writer ({mode}): {p.stderr[-1500:]}")
            head = read(path)[:4000]
            r.check(b'compressor="vtkZLibDataCompressor"' in head and b'encoding="raw"' in read(path)[-2000:] + head,
                    f"VTK's writer ({mode}): not zlib-compressed raw appended data")
            same_tree(f"VTK's zlib blocks, {mode}", path, (1, 2, 3, 7), ["--scalar", "f"])
            if mode == "gll":  # each rank resamples its part, as one process the whole
                p = mpi(2, "tree", path, "--scalar", "f")
                r.check("Gauss-Lobatto" in p.stderr + p.stdout,
                        f"GLL nodes: no note of their resampling:\n{p.stderr[-800:]}")
            if mode == "plain":
                same_tree("VTK's zlib blocks, a component", path, (2, 3), ["--scalar", "u", "--component", "1"])
                same_tree("VTK's zlib blocks, the magnitude", path, (2, 3),
                          ["--scalar", "u", "--component", "magnitude"])
        # Points numbered at random over a larger file: on 4 and 7 ranks a part's cells use
        # points in nearly every block of ids, so each rank reads only its share of the points
        # and gets its cells' points from the ranks that read them (with a note); on 2 and 3
        # ranks the parts read the blocks they use.
        big = os.path.join(d, "big.vtu")
        run("generate", "random", "--cells", "30000", "-o", big)
        path = os.path.join(d, "vtk-big-shuffled.vtu")
        p = subprocess.run([PYTHON, "-c", VTK_REWRITE, big, path, "shuffled"], capture_output=True,
                           text=True)
        r.check(p.returncode == 0, f"VTK's writer (big, shuffled): {p.stderr[-1500:]}")
        same_tree("VTK's zlib blocks, 30,000 cells, points numbered at random", path,
                  (1, 2, 3, 4, 7), ["--scalar", "f"])
        for n, owners in ((2, False), (3, False), (4, True), (7, True)):
            p = mpi(n, "tree", path, "--scalar", "f")
            r.check((NUMBERED_FAR in p.stderr) == owners,
                    f"points numbered at random, {n} ranks: the note "
                    f"{'missing' if owners else 'given'}:\n{p.stderr[-800:]}")
    else:
        print("VTK's writer: skipped (no python3-vtk9)")

    # Problems a part finds: one process's message, once (rank 0 reads the whole and reports).
    import numpy as np
    data = bytearray(read(base))
    text = data[:data.index(b"<AppendedData")].decode()

    def appended_at(name):
        import re
        m = re.search(r'<DataArray[^>]*Name="%s"[^>]*offset="(\d+)"' % name, text)
        return data.index(b"_", data.index(b"<AppendedData")) + 1 + int(m.group(1)) + 8

    nan = bytearray(data)
    at = appended_at("f") + 8 * 5000  # the value of point 5000 (UInt64 header, Float64 values)
    nan[at:at + 8] = np.array([np.nan]).tobytes()
    with open(os.path.join(d, "nan.vtu"), "wb") as f:
        f.write(nan)
    same_error("a NaN value", os.path.join(d, "nan.vtu"))
    beyond = bytearray(data)
    at = appended_at("connectivity") + 8 * 20000  # a node of a cell in the middle
    beyond[at:at + 8] = np.array([10**9], dtype=np.int64).tobytes()
    with open(os.path.join(d, "beyond.vtu"), "wb") as f:
        f.write(beyond)
    same_error("a cell naming a point the file does not have", os.path.join(d, "beyond.vtu"))
r.finish()
