"""The --max-memory guard of the commands that read a mesh: an input whose header counts need more
than the budget is refused before it is read, with "needs ~X, limit Y" and no output file; bad
sizes are refused; the default (80% of the physical memory) and a generous budget let it run.
zlib bombs (blocks that inflate to gigabytes) are refused before anything inflates."""
import os
import resource
import struct
import time
import zlib

from hoct_testing import Results, run, tempdir



def zlib_array(blocks, block_size, last_size):
    """A vtkZLibDataCompressor array (UInt64 header): the given compressed blocks."""
    header = struct.pack(f"<{3 + len(blocks)}Q", len(blocks), block_size, last_size,
                         *map(len, blocks))
    return header + b"".join(blocks)


def bomb_vtu(path, points, bomb_blocks):
    """One P1 triangle whose Points array (3 x `points` Float64 declared by NumberOfPoints) is
    `bomb_blocks` identical blocks of 1 MiB of zeros, each ~1 KB compressed (zlib's ~1000:1): a
    ~1 MB file per GiB declared. The other arrays are honest."""
    mib = 1 << 20
    zero = zlib.compress(bytes(mib), 9)
    arrays = [
        zlib_array([zero] * bomb_blocks, mib, mib),  # Points
        zlib_array([zlib.compress(struct.pack("<3d", 0.0, 1.0, 2.0))], 24, 24),  # f
        zlib_array([zlib.compress(struct.pack("<3q", 0, 1, 2))], 24, 24),  # connectivity
        zlib_array([zlib.compress(struct.pack("<q", 3))], 8, 8),  # offsets
        zlib_array([zlib.compress(struct.pack("<B", 5))], 1, 1),  # types
    ]
    offsets = [0]
    for a in arrays[:-1]:
        offsets.append(offsets[-1] + len(a))
    o = offsets
    xml = f"""<?xml version="1.0"?>
<VTKFile type="UnstructuredGrid" version="1.0" byte_order="LittleEndian" header_type="UInt64"
 compressor="vtkZLibDataCompressor">
<UnstructuredGrid><Piece NumberOfPoints="{points}" NumberOfCells="1">
<Points><DataArray type="Float64" NumberOfComponents="3" format="appended" offset="{o[0]}"/></Points>
<PointData><DataArray type="Float64" Name="f" format="appended" offset="{o[1]}"/></PointData>
<Cells>
<DataArray type="Int64" Name="connectivity" format="appended" offset="{o[2]}"/>
<DataArray type="Int64" Name="offsets" format="appended" offset="{o[3]}"/>
<DataArray type="UInt8" Name="types" format="appended" offset="{o[4]}"/>
</Cells></Piece></UnstructuredGrid>
<AppendedData encoding="raw">_"""
    with open(path, "wb") as f:
        f.write(xml.encode() + b"".join(arrays) + b"\n</AppendedData>\n</VTKFile>\n")


res = Results()
with tempdir() as d:
    # zlib bombs (issue 27, item 3). A 4 MB file whose Points blocks declare 4 GiB for the 3
    # points its header counts: refused from the compression header, nothing inflated. Before:
    # 3.9 GB and 24 s despite --max-memory 100M, then "has 536870912 values, expected 9".
    bomb = os.path.join(d, "bomb.vtu")
    bomb_vtu(bomb, 3, 4096)
    out = os.path.join(d, "bomb.json")
    for command in (["info", bomb], ["tree", bomb, "--json", out]):
        start = time.monotonic()
        r = run(*command, "--max-memory", "100M", check=False)
        took = time.monotonic() - start
        res.check(r.returncode == 1 and "bomb.vtu: DataArray in <Points> has 536870912 values (as "
                  "its compression header declares, before inflating), expected 9 Float64 values"
                  in r.stderr, f"bomb {command[0]}: exit {r.returncode}, {r.stderr!r}")
        res.check(took < 5, f"bomb {command[0]} took {took:.1f} s")
    res.check(not os.path.exists(out), "the bomb's tree wrote its output")
    # An honest header that needs more than the budget (1M points in a 1 MB file): the budget's
    # estimate refuses it before anything inflates.
    big = os.path.join(d, "big.vtu")
    bomb_vtu(big, 1_000_000, 1024)
    r = run("info", big, "--max-memory", "100M", check=False)
    res.check(r.returncode == 1 and "big.vtu: piece 0: " in r.stderr and "need ~" in r.stderr,
              f"big header: exit {r.returncode}, {r.stderr!r}")
    # Memory stayed small (the children's peak; the bombs would have taken gigabytes).
    peak_mb = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss / 1024
    res.check(peak_mb < 300, f"peak memory of the bomb runs {peak_mb:.0f} MB")
    mesh = os.path.join(d, "gauss.vtu")
    run("generate", "gauss", "--cells", "2000", "--degree", "3", "-o", mesh)
    out = os.path.join(d, "tree.json")
    for command in (["tree", mesh, "--json", out], ["info", mesh], ["eval", mesh, "--points", "-"],
                    ["render", mesh, "-o", os.path.join(d, "p.png")]):
        r = run(*command, "--max-memory", "1M", check=False, stdin="")
        res.check(r.returncode == 1, f"{command[0]} --max-memory 1M: exit {r.returncode}")
        res.check("gauss.vtu: piece 0: " in r.stderr and "need ~" in r.stderr
                  and "limit 1 MiB" in r.stderr, f"{command[0]}: message {r.stderr!r}")
    res.check(not os.path.exists(out), "tree refused by the guard wrote its output")
    for bad in ("lots", "0", "150%", "-5G"):
        r = run("tree", mesh, "--max-memory", bad, check=False)
        res.check(r.returncode == 1 and "bad memory size" in r.stderr,
                  f"--max-memory {bad}: exit {r.returncode}, {r.stderr!r}")
    for ok in ([], ["--max-memory", "4G"], ["--max-memory", "50%"]):
        r = run("tree", mesh, "--json", out, *ok, check=False)
        res.check(r.returncode == 0 and os.path.exists(out), f"tree {ok}: {r.stderr!r}")
        if os.path.exists(out):
            os.remove(out)
    # The refinement's own memory (issue 27, item 9), estimated before it is built: --refine 1024
    # on this 90 KB file would take ~100 GB.
    r = run("tree", mesh, "--refine", "1024", "--max-memory", "1G", "--json", out, check=False)
    res.check(r.returncode == 1 and "--refine 1024" in r.stderr and "sub-triangles need ~" in r.stderr
              and "limit 1 GiB" in r.stderr, f"--refine 1024: {r.returncode} {r.stderr!r}")
    res.check(not os.path.exists(out), "the refused refinement wrote its output")
    r = run("tree", mesh, "--refine", "4", "--max-memory", "1G", "--json", out, check=False)
    res.check(r.returncode == 0 and os.path.exists(out), f"--refine 4 within 1G: {r.stderr!r}")
res.finish()
