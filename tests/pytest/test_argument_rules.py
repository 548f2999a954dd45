"""The Python module's arguments follow the command line's rules: nothing is truncated, wrapped,
unmasked or cut at a NUL silently; each refusal names the argument, the position and the value
(HoctError, a ValueError, for a bad value; TypeError for a wrong type)."""
import os
import pathlib
import subprocess

import numpy as np
import pytest

import hoct

HOCT = os.environ.get("HOCT_BIN", "hoct")
POINTS = np.array([[0, 0], [1, 0], [0, 1], [1, 1]], float)
CELLS = np.array([[0, 1, 2], [1, 3, 2]])
VALUES = np.array([0.0, 1.0, 2.0, 3.0])


def cells_with(x, dtype=float):
    c = CELLS.astype(dtype)
    c[0, 1] = x
    return c


@pytest.fixture(scope="module")
def vtu(tmp_path_factory):
    path = str(tmp_path_factory.mktemp("args") / "heater.vtu")
    subprocess.run([HOCT, "generate", "heater", "--cells", "600", "-o", path], check=True,
                   capture_output=True)
    return path


def test_float_cell_indices_must_be_whole_not_truncated():
    # As a .vtu file's Float64 connectivity: 1.0 is point 1, 1.5 is refused (was: point 1).
    assert hoct.from_arrays(POINTS, cells_with(1.0), VALUES).num_cells == 2
    for cells in (cells_with(1.5), [[0, 1.5, 2], [1, 3, 2]]):
        with pytest.raises(hoct.HoctError, match=r"^from_arrays: cells\[0, 1\] is 1\.5, not an "
                                                 r"integer$"):
            hoct.from_arrays(POINTS, cells, VALUES)
    with pytest.raises(hoct.HoctError, match=r"cell_types\[0\] is 5\.5, not an integer"):
        hoct.from_arrays(POINTS, CELLS, VALUES, cell_types=[5.5, 5])
    with pytest.raises(TypeError, match="from_arrays: degree must be an integer, not float"):
        hoct.from_arrays(POINTS, CELLS, VALUES, degree=1.5)


@pytest.mark.parametrize("value,quoted,why", [
    (np.nan, "nan", "not an integer"),
    (np.inf, "inf", "not an integer"),
    (1e20, r"1e\+20", "outside the int64 range"),
    (2.0**63, r"9\.223372036854776e\+18", "outside the int64 range"),
])
def test_non_finite_and_huge_float_indices_are_quoted_not_wrapped(value, quoted, why):
    with pytest.raises(hoct.HoctError, match=r"cells\[0, 1\] is %s, %s" % (quoted, why)) as e:
        hoct.from_arrays(POINTS, cells_with(value), VALUES)
    assert "-9223372036854775808" not in str(e.value)  # was: "refers to point -9223372036854775808"


def test_integer_indices_beyond_int64_are_quoted_not_wrapped():
    for cells, quoted in ((cells_with(2**63, np.uint64), "9223372036854775808"),
                          (cells_with(2**64 - 1, np.uint64), "18446744073709551615"),
                          ([[0, 2**70, 2], [1, 3, 2]], "1180591620717411303424")):
        with pytest.raises(hoct.HoctError, match=r"cells\[0, 1\] is %s, outside the int64 range"
                           % quoted):
            hoct.from_arrays(POINTS, cells, VALUES)


@pytest.mark.parametrize("dtype", [bool, complex, str])
def test_cell_indices_of_other_types_are_type_errors(dtype):
    with pytest.raises(TypeError, match="from_arrays: cells must be an array of integers, not of "
                                        "dtype"):
        hoct.from_arrays(POINTS, CELLS.astype(dtype), VALUES)
    # The native function converts only safely: no float is truncated there either.
    with pytest.raises(TypeError):
        hoct._hoct.from_arrays(POINTS, cells_with(1.5), VALUES)


def test_masked_entries_are_refused_with_their_count_and_first_position():
    masked = np.ma.masked_array(CELLS, mask=[[0, 1, 0], [0, 0, 1]])
    with pytest.raises(hoct.HoctError, match=r"^from_arrays: cells has 2 masked entries \(the "
                                             r"first at \[0, 1\]\)"):
        hoct.from_arrays(POINTS, masked, VALUES)
    with pytest.raises(hoct.HoctError, match=r"values has 1 masked entry \(the first at \[2\]\)"):
        hoct.from_arrays(POINTS, CELLS, np.ma.masked_array(VALUES, mask=[0, 0, 1, 0]))
    with pytest.raises(hoct.HoctError, match=r"points has 1 masked entry \(the first at \[3, 0\]"):
        hoct.from_arrays(np.ma.masked_invalid(np.r_[POINTS[:3], [[np.nan, 1]]]), CELLS, VALUES)
    # Nothing masked: the data as they are.
    mesh = hoct.from_arrays(np.ma.masked_array(POINTS), np.ma.masked_array(CELLS, mask=False),
                            VALUES)
    assert mesh.num_cells == 2


@pytest.mark.parametrize("simplify", [float("nan"), -1, float("inf"), 1e400])
def test_tree_simplify_refuses_what_simplify_refuses(simplify):
    tree = hoct.contour_tree(hoct.generate("sphere"))
    with pytest.raises(hoct.HoctError, match=r"^simplify: (nan|-1|inf) is not a threshold \(a "
                                             r"finite number >= 0"):
        tree.simplify(simplify)  # was: accepted (nan kept every pair, -1 too)
    with pytest.raises(TypeError, match="simplify: the threshold must be a number, not str"):
        tree.simplify("1")


@pytest.mark.parametrize("spec,quoted", [(float("nan"), "nan"), (-1, "-1.0"), ("-5%", "-5%"),
                                         ("nan%", "nan%"), ("inf", "inf"), ("5 %", "5 %")])
def test_simplify_specs_are_parsed_as_the_cli_parses_them(spec, quoted):
    mesh = hoct.generate("sphere")
    with pytest.raises(hoct.HoctError, match="contour_tree: simplify: '%s' is not a threshold"
                       % quoted):
        hoct.contour_tree(mesh, simplify=spec)
    with pytest.raises(hoct.HoctError, match="simplify_by: '%s' is not a threshold" % quoted):
        hoct.contour_tree(mesh).simplify_by(spec)
    with pytest.raises(TypeError, match="contour_tree: simplify must be a number or a text"):
        hoct.contour_tree(mesh, simplify=[1])
    # What `--simplify` accepts (any finite percentage, as the CLI).
    assert len(hoct.contour_tree(mesh, simplify="150%").values) == 2


@pytest.mark.parametrize("spec", ["nan", "-1", "-5%", "inf", "5 %", "5%%", "150%", "0x10",
                                  " 5", "1e3%", "0.5%", "0"])
def test_simplify_refuses_exactly_what_the_cli_refuses(vtu, tmp_path, spec):
    out = str(tmp_path / "t.json")
    cli = subprocess.run([HOCT, "tree", vtu, "-q", "--no-timings", "--simplify=" + spec, "--json",
                          out], capture_output=True, text=True)
    mesh = hoct.read(vtu)
    if cli.returncode == 0:
        with open(out) as f:
            assert hoct.contour_tree(mesh, simplify=spec).to_json(timings=False) + "\n" == f.read()
    else:
        assert "--simplify: '%s' is not a threshold" % spec in cli.stderr
        with pytest.raises(hoct.HoctError, match="simplify: '%s' is not a threshold" % spec):
            hoct.contour_tree(mesh, simplify=spec)


def test_paths_with_a_nul_are_refused_not_cut_to_their_prefix(vtu, tmp_path):
    # Was: hoct.read(vtu + "\0.vtu") read the file `vtu`; write_json wrote "t.json".
    for path in (vtu + "\0.vtu", (vtu + "\0.vtu").encode(), pathlib.Path(vtu + "\0.vtu")):
        with pytest.raises(hoct.HoctError, match=r"^read: path contains a NUL (character|byte) "
                                                 r"at position %d" % len(vtu)):
            hoct.read(path)
    with pytest.raises(hoct.HoctError, match="read: path contains a NUL byte at position"):
        hoct._hoct.read(vtu + "\0.vtu", "", "", 0, -1.0)  # the native function checks too
    with pytest.raises(hoct.HoctError, match=r"read: scalar contains a NUL character at position 1"):
        hoct.read(vtu, scalar="f\0x")
    tree = hoct.contour_tree(hoct.read(pathlib.Path(vtu)))
    for write, name in ((tree.write_json, "t.json"), (tree.write_vtp, "t.vtp"),
                        (tree.write_svg, "t.svg")):
        with pytest.raises(hoct.HoctError, match="path contains a NUL"):
            write(str(tmp_path / name) + "\0x")
    assert os.listdir(tmp_path) == []
    tree.write_json(tmp_path / "t.json")  # an os.PathLike, as read takes
    tree.write_svg(os.fsencode(tmp_path / "t.svg"))
    assert sorted(os.listdir(tmp_path)) == ["t.json", "t.svg"]
    with pytest.raises(TypeError, match="read: path must be a str, bytes or os.PathLike, not int"):
        hoct.read(3)


def test_integer_options_follow_the_flags_ranges(vtu):
    mesh = hoct.generate("sphere")
    for bad, error, phrase in ((1.5, TypeError, "must be an integer, not float"),
                               (True, TypeError, "must be an integer, not a bool"),
                               ("4", TypeError, "must be an integer, not str"),
                               (0, hoct.HoctError, "must be between 1 and 1024, got 0"),
                               (1025, hoct.HoctError, "must be between 1 and 1024, got 1025")):
        with pytest.raises(error, match="contour_tree: refine " + phrase):  # was: int(1.5) = 1
            hoct.contour_tree(mesh, method="refine", refine=bad)
    for call in (lambda t: hoct.contour_tree(mesh, threads=t), lambda t: hoct.read(vtu, threads=t)):
        with pytest.raises(hoct.HoctError, match=r"threads must be a positive integer, got 1025 "
                                                 r"\(at most 1024, as --threads\)"):
            call(1025)
        assert call(np.int64(2)) is not None  # numpy integers are integers
    with pytest.raises(TypeError, match="generate: degree must be an integer, not float"):
        hoct.generate("sphere", degree=2.5)
    with pytest.raises(TypeError, match="generate: seed must be an integer, not float"):
        hoct.generate("random", seed=1.5)
    with pytest.raises(hoct.HoctError, match="generate: cells must be a positive whole number, "
                                             "got 1000.5"):
        hoct.generate("random", cells=1000.5)
    assert hoct.generate("random", cells=1e3).num_cells == hoct.generate("random", cells=1000).num_cells
    with pytest.raises(TypeError, match="contour_tree: keep_flat must be True or False, not 'no'"):
        hoct.contour_tree(mesh, keep_flat="no")  # was: bool('no'), True


def test_mesh_value_takes_the_points_hoct_eval_takes():
    mesh = hoct.generate("sphere")
    assert np.isfinite(mesh.value(0, 0.25, 0.25))
    for u, v, quoted in ((5, 5, r"\(5, 5\)"), (float("nan"), 0.1, r"\(nan, 0\.1\)"),
                         (-0.5, 0.2, r"\(-0\.5, 0\.2\)")):
        with pytest.raises(hoct.HoctError, match=r"value: \(u, v\) = %s is outside the reference "
                                                 r"triangle" % quoted):
            mesh.value(0, u, v)  # was: the polynomial extrapolated, or nan
    with pytest.raises(hoct.HoctError, match=r"value: cell 980 out of range \(the mesh has 980 "
                                             r"cells\)"):
        mesh.value(980, 0.2, 0.2)


def test_messages_keep_what_follows_a_nul_or_an_invalid_byte(tmp_path):
    # The file name is quoted as it is: a byte that is not UTF-8 is shown, not a decoding error.
    with pytest.raises(hoct.HoctError, match=r"\\xff\.vtu: cannot open"):
        hoct.read(os.fsencode(tmp_path) + b"/\xff.vtu")
