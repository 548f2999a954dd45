"""A small Exodus II writer for the tests (netCDF through python3-netcdf4): one element block of
TRI3, TRI6, TRI7, QUAD4, QUAD8, QUAD9 (or BAR2) elements and nodal fields at several times, laid out as the SEACAS
Exodus library writes its files (separate coordx/coordy, 1-based connect1 with its elem_type,
one vals_nod_varN per field). Exodus and VTK order a quadratic triangle's nodes alike: corners,
then the midpoints of edges 01, 12, 20; TRI7 adds the centroid."""
import netCDF4
import numpy as np

NODES = {"TRI3": 3, "TRI6": 6, "TRI7": 7, "BAR2": 2, "QUAD4": 4, "QUAD8": 8, "QUAD9": 9}


def write_exodus(path, points, cells, kind, fields, times=(0.0,)):
    """points (n, 2|3), cells (m, nodes) from 0, fields {name: [values per time]}."""
    pts = np.asarray(points, dtype=np.float64)
    con = np.asarray(cells, dtype=np.int64)
    n, dim = pts.shape
    m, k = con.shape
    assert k == NODES[kind], (kind, k)
    names = list(fields)
    with netCDF4.Dataset(path, "w", format="NETCDF3_64BIT_OFFSET") as d:
        d.set_auto_mask(False)
        d.api_version = np.float32(8.03)
        d.version = np.float32(8.03)
        d.floating_point_word_size = np.int32(8)
        d.file_size = np.int32(1)
        d.maximum_name_length = np.int32(32)
        d.int64_status = np.int32(0)
        d.title = "hoct test"
        for name, size in (("len_string", 33), ("len_line", 81), ("four", 4), ("len_name", 33),
                           ("time_step", None), ("num_dim", dim), ("num_nodes", n),
                           ("num_elem", m), ("num_el_blk", 1), ("num_el_in_blk1", m),
                           ("num_nod_per_el1", k)):
            d.createDimension(name, size)
        if names:
            d.createDimension("num_nod_var", len(names))

        def strings(var, dimension, values):
            v = d.createVariable(var, "S1", (dimension, "len_name"))
            v[:] = netCDF4.stringtochar(np.array([s[:32] for s in values], dtype="S33"))

        time_whole = d.createVariable("time_whole", "f8", ("time_step",))
        d.createVariable("eb_status", "i4", ("num_el_blk",))[:] = 1
        prop = d.createVariable("eb_prop1", "i4", ("num_el_blk",))
        prop.setncattr("name", "ID")
        prop[:] = 1
        strings("eb_names", "num_el_blk", ["block_1"])
        for i, axis in enumerate("xyz"[:dim]):
            d.createVariable("coord" + axis, "f8", ("num_nodes",))[:] = pts[:, i]
        strings("coor_names", "num_dim", ["x", "y", "z"][:dim])
        d.createVariable("node_num_map", "i4", ("num_nodes",))[:] = np.arange(1, n + 1)
        d.createVariable("elem_num_map", "i4", ("num_elem",))[:] = np.arange(1, m + 1)
        connect = d.createVariable("connect1", "i4", ("num_el_in_blk1", "num_nod_per_el1"))
        connect.elem_type = kind
        connect[:] = (con + 1).astype(np.int32)
        if names:
            strings("name_nod_var", "num_nod_var", names)
            values = [d.createVariable(f"vals_nod_var{j + 1}", "f8", ("time_step", "num_nodes"))
                      for j in range(len(names))]
        for s, t in enumerate(times):
            time_whole[s] = t
            for j, name in enumerate(names):
                values[j][s, :] = np.asarray(fields[name][s], dtype=np.float64)


if __name__ == "__main__":
    # python3 exodus_writer.py IN.npz OUT.e KIND: points, cells, times, name, values (steps, n).
    # Its own process: netCDF4's HDF5 and VTK's (MPI) HDF5 do not share one process.
    import sys

    z = np.load(sys.argv[1])
    write_exodus(sys.argv[2], z["points"], z["cells"], sys.argv[3],
                 {str(z["name"]): list(z["values"])}, times=list(z["times"]))
