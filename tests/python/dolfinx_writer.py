"""Writes the files test_dolfinx_files.py reads, with DOLFINx itself (python3-dolfinx).

    python3 dolfinx_writer.py OUTDIR            (serial: every file)
    mpirun -np N python3 dolfinx_writer.py OUTDIR --partitioned   (one .pvtu over N ranks)

The field is f(x, y) = (x - A)^2 - (y - B)^2 (and 2 f at the second time step), interpolated
into Lagrange spaces: exact in P2 and P3, whose trees are therefore known analytically. Files:
  p1.pvd / p2.pvd / p3.pvd    VTKFile of a P1, P2, P3 function on a straight 8 x 8 mesh
  p1.xdmf                      XDMFFile, the P1 function at t = 0 and t = 1 (2 f)
  p2curved.xdmf / .pvd        XDMFFile and VTKFile of a P2 function on a second-order (Gmsh)
                               mesh of a disk
  p1_points.npz                the P1 function's values at DOLFINx's geometry nodes (in memory)
  part<N>.pvd, part<N>p3.pvd   VTKFile of the P2 and P3 functions written by N ranks
                               (--partitioned)"""
import os
import sys

import numpy as np
from mpi4py import MPI

import dolfinx
from dolfinx import fem, io, mesh

A, B = 0.4, 0.45


def f(x):
    return (x[0] - A) ** 2 - (x[1] - B) ** 2


def function(msh, degree, name="temperature", scale=1.0):
    V = fem.FunctionSpace(msh, ("Lagrange", degree))
    u = fem.Function(V)
    u.name = name
    u.interpolate(lambda x: scale * f(x))
    return u


def square(comm):
    return mesh.create_unit_square(comm, 8, 8, mesh.CellType.triangle)


def disk(comm):
    """A second-order triangle mesh of the disk of radius 0.5 around (0.5, 0.5), from Gmsh."""
    import gmsh
    from dolfinx.io import gmshio

    gmsh.initialize()
    gmsh.option.setNumber("General.Terminal", 0)
    gmsh.model.add("disk")
    if comm.rank == 0:
        gmsh.model.occ.addDisk(0.5, 0.5, 0, 0.5, 0.5)
        gmsh.model.occ.synchronize()
        gmsh.model.addPhysicalGroup(2, [1], 1)
        gmsh.option.setNumber("Mesh.CharacteristicLengthMax", 0.15)
        gmsh.model.mesh.generate(2)
        gmsh.model.mesh.setOrder(2)
    msh, _, _ = gmshio.model_to_mesh(gmsh.model, comm, 0, gdim=2)
    gmsh.finalize()
    return msh


def main():
    out = sys.argv[1]
    comm = MPI.COMM_WORLD
    if "--partitioned" in sys.argv:
        msh = square(comm)
        for degree, name in ((2, f"part{comm.size}"), (3, f"part{comm.size}p3")):
            with io.VTKFile(comm, os.path.join(out, f"{name}.pvd"), "w") as vf:
                vf.write_function(function(msh, degree), 0.0)
        return
    msh = square(comm)
    for degree in (1, 2, 3):
        u = function(msh, degree)
        with io.VTKFile(comm, os.path.join(out, f"p{degree}.pvd"), "w") as vf:
            vf.write_function(u, 0.0)
    u = function(msh, 1)
    np.savez(os.path.join(out, "p1_points.npz"), x=msh.geometry.x, cells=msh.geometry.dofmap.array
             .reshape(-1, 3), values=u.x.array)
    with io.XDMFFile(comm, os.path.join(out, "p1.xdmf"), "w") as xf:
        xf.write_mesh(msh)
        xf.write_function(u, 0.0)
        u.interpolate(lambda x: 2 * f(x))
        xf.write_function(u, 1.0)
    curved = disk(comm)
    u = function(curved, 2)
    with io.XDMFFile(comm, os.path.join(out, "p2curved.xdmf"), "w") as xf:
        xf.write_mesh(curved)
        xf.write_function(u, 0.0)
    with io.VTKFile(comm, os.path.join(out, "p2curved.pvd"), "w") as vf:
        vf.write_function(u, 0.0)
    print("dolfinx", dolfinx.__version__, "wrote", sorted(os.listdir(out)))


main()
