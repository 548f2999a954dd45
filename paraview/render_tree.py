"""Render a field with its exact contour tree in ParaView (pvpython), through the hoct plugin.

    xvfb-run -a pvpython paraview/render_tree.py INPUT.vtu -o picture.png [--simplify 1%]

The field is coloured (Viridis) with a few isolines, the critical points are spheres coloured by
type (minima blue, saddles green, maxima red, as `hoct render`) and the arcs are tubes drawn on
the surface. INPUT is any file ParaView reads as an unstructured grid of triangles (.vtu, ...);
other files hoct reads (.msh) are converted first with `hoct convert` (--hoct, or $HOCT_BIN, or
build/bin/hoct). The plugin is --plugin, or $HOCT_PARAVIEW_PLUGIN, or the one in build/.
"""

import argparse
import os
import subprocess
import sys
import tempfile

from paraview import simple as pv

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DEFAULT_PLUGIN = os.path.join(ROOT, "build", "lib", "paraview-plugins", "HoctContourTree",
                              "HoctContourTree.so")
DEFAULT_HOCT = os.path.join(ROOT, "build", "bin", "hoct")
# TTK's critical type codes (the plugin's CriticalType) and hoct render's colours.
TYPE_COLOURS = {0: (0.13, 0.35, 0.85), 1: (0.10, 0.65, 0.20), 3: (0.85, 0.12, 0.12),
                5: (0.6, 0.6, 0.6)}
TYPE_NAMES = {0: "minimum", 1: "saddle", 3: "maximum", 5: "regular"}


def load_plugin(path=None):
    """Loads the hoct plugin (once) and returns its path."""
    path = path or os.environ.get("HOCT_PARAVIEW_PLUGIN") or DEFAULT_PLUGIN
    if not os.path.exists(path):
        sys.exit(f"render_tree: no ParaView plugin at {path} (build hoct with ParaView installed, "
                 "or pass --plugin)")
    if not hasattr(pv, "HigherOrderContourTree"):
        pv.LoadPlugin(path, remote=False, ns=vars(pv))
    return path


def open_grid(path, hoct=None, scalar=None):
    """A ParaView source for `path`: read by ParaView, or converted to .vtu by hoct first."""
    if not os.path.exists(path):
        sys.exit(f"render_tree: {path}: no such file")
    if not path.lower().endswith((".vtu", ".pvtu", ".vtk")):
        hoct = hoct or os.environ.get("HOCT_BIN") or DEFAULT_HOCT
        vtu = os.path.join(tempfile.mkdtemp(prefix="hoct-render-"), "input.vtu")
        cmd = [hoct, "convert", path, "-o", vtu] + (["--scalar", scalar] if scalar else [])
        done = subprocess.run(cmd, capture_output=True, text=True)
        if done.returncode != 0:
            sys.exit(f"render_tree: {done.stderr.strip()}")
        path = vtu
    reader = pv.OpenDataFile(path)
    if reader is None:
        sys.exit(f"render_tree: ParaView cannot read {path}")
    reader.UpdatePipeline()
    return reader


def parse_threshold(text):
    """'1%' -> (1.0, percent mode), '0.05' -> (0.05, absolute mode)."""
    percent = text.endswith("%")
    value = float(text[:-1] if percent else text)
    if not value >= 0:
        raise ValueError(f"--simplify: '{text}' is not a threshold")
    return value, ("Percent of value range" if percent else "Absolute")


def contour_tree(source, scalar=None, simplify=None, augmented=False, threads=0):
    """The plugin's filter on `source`, updated."""
    pv.SetActiveSource(source)  # the default scalar comes from the active source
    tree = pv.HigherOrderContourTree(Input=source)
    if scalar:
        tree.Scalars = ["POINTS", scalar]
    if simplify:
        tree.PersistenceThreshold, tree.ThresholdMode = parse_threshold(simplify)
    tree.Augmented = int(augmented)
    tree.Threads = threads
    tree.UpdatePipeline()
    if tree.GetDataInformation(0).GetNumberOfPoints() == 0:
        sys.exit("render_tree: the Higher-Order Contour Tree filter failed (its error is above)")
    return tree


def _type_lookup_table(augmented):
    lut = pv.GetColorTransferFunction("CriticalType")
    lut.InterpretValuesAsCategories = 1
    codes = sorted(TYPE_NAMES) if augmented else [0, 1, 3]
    lut.Annotations = sum(([str(k), TYPE_NAMES[k]] for k in codes), [])
    lut.IndexedColors = sum((list(TYPE_COLOURS[k]) for k in codes), [])
    return lut


def render(source, tree, output, size=(1000, 750), isolines=12, view_direction=None,
           title=None):
    """Saves a picture of `source` (its field), `tree`'s critical points and arcs to `output`."""
    scalar = tree.Scalars[1]
    simplified = tree.PersistenceThreshold > 0 and not tree.Augmented
    nodes_port, arcs_port = (2, 2) if simplified else (0, 1)
    view = pv.CreateView("RenderView")
    view.ViewSize = list(size)
    view.OrientationAxesVisibility = 0
    view.Background = [1, 1, 1]
    if hasattr(view, "UseColorPaletteForBackground"):
        view.UseColorPaletteForBackground = 0
    bounds = source.GetDataInformation().GetBounds()
    diag = sum((bounds[2 * i + 1] - bounds[2 * i]) ** 2 for i in range(3)) ** 0.5
    lo, hi = source.PointData[scalar].GetRange()

    # The field on its curved cells, tessellated to follow the polynomial; the isolines are cut
    # from the same triangles, so they lie on the drawn surface.
    fine = pv.Tessellate(Input=source)
    fine.ChordError = 2e-4 * diag
    fine.FieldError = [2e-3 * (hi - lo)]
    fine.MaximumNumberofSubdivisions = 4
    field = pv.Show(fine, view)
    field.Representation = "Surface"
    pv.ColorBy(field, ("POINTS", scalar))
    lut = pv.GetColorTransferFunction(scalar)
    lut.ApplyPreset("Viridis (matplotlib)", True)
    lut.RescaleTransferFunction(lo, hi)
    bar = pv.GetScalarBar(lut, view)
    bar.Title, bar.ComponentTitle = scalar, ""
    bar.TitleColor = bar.LabelColor = [0.1, 0.1, 0.1]
    bar.RangeLabelFormat = "%-#.3g"
    bar.WindowLocation = "Any Location"
    bar.Position, bar.ScalarBarLength = [0.89, 0.15], 0.7
    field.SetScalarBarVisibility(view, True)

    if isolines > 0 and hi > lo:
        step = (hi - lo) / (isolines + 1)
        lines = pv.Contour(Input=fine, ContourBy=["POINTS", scalar],
                           Isosurfaces=[lo + step * (k + 1) for k in range(isolines)])
        shown = pv.Show(lines, view)
        pv.ColorBy(shown, None)
        shown.AmbientColor = shown.DiffuseColor = [0.95, 0.95, 0.95]
        shown.LineWidth = 1.5

    arcs = pv.Tube(Input=pv.OutputPort(tree, arcs_port))
    arcs.Radius = 0.003 * diag
    arcs.NumberofSides = 10
    shown = pv.Show(arcs, view)
    pv.ColorBy(shown, None)
    shown.AmbientColor = shown.DiffuseColor = [0.12, 0.12, 0.12]

    nodes = pv.OutputPort(tree, nodes_port)
    if simplified:
        # Output 2 holds the polylines' points too: keep the nodes' vertices.
        nodes = pv.ExtractCellsByType(Input=nodes, CellTypes=["Vertex"])
    glyphs = pv.Glyph(Input=nodes, GlyphType="Sphere")
    glyphs.ScaleArray = ["POINTS", "No scale array"]
    glyphs.ScaleFactor = 0.022 * diag
    glyphs.GlyphMode = "All Points"
    glyphs.GlyphType.ThetaResolution = glyphs.GlyphType.PhiResolution = 16
    shown = pv.Show(glyphs, view)
    pv.ColorBy(shown, ("POINTS", "CriticalType"))
    shown.LookupTable = _type_lookup_table(bool(tree.Augmented))
    legend = pv.GetScalarBar(shown.LookupTable, view)
    legend.Title, legend.ComponentTitle = "critical points", ""
    legend.TitleColor = legend.LabelColor = [0.1, 0.1, 0.1]
    legend.WindowLocation = "Any Location"
    legend.TextPosition = "Ticks left/bottom, annotations right/top"
    legend.HorizontalTitle = 1
    legend.TitleJustification = "Left"
    legend.Position, legend.ScalarBarLength = [0.02, 0.05], 0.16
    shown.SetScalarBarVisibility(view, True)

    if title:
        text = pv.Text(Text=title)
        shown = pv.Show(text, view)
        shown.Color = [0.1, 0.1, 0.1]
        shown.FontSize = 16
        shown.WindowLocation = "Upper Left Corner"

    flat = bounds[5] - bounds[4] < 1e-9 * max(diag, 1e-300)
    direction = view_direction or ((0, 0, 1) if flat else (1.0, -1.6, 0.9))
    centre = [(bounds[2 * i] + bounds[2 * i + 1]) / 2 for i in range(3)]
    view.CameraFocalPoint = centre
    view.CameraPosition = [centre[i] + direction[i] for i in range(3)]
    view.CameraViewUp = [0, 1, 0] if flat else [0, 0, 1]
    view.ResetCamera(False)
    view.GetActiveCamera().Dolly(1.5)
    pv.Render(view)
    pv.SaveScreenshot(output, view, ImageResolution=list(size), CompressionLevel="9")
    return view


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("input", help="Input file (.vtu; .msh and others through `hoct convert`)")
    ap.add_argument("-o", "--output", required=True, help="Picture (.png)")
    ap.add_argument("--scalar", help="Point array (default: the active scalars / the first)")
    ap.add_argument("--simplify", help="Persistence threshold: absolute, or %% of the range (1%%)")
    ap.add_argument("--augmented", action="store_true", help="Keep the regular nodes")
    ap.add_argument("--isolines", type=int, default=12, help="Number of isolines (default 12)")
    ap.add_argument("--size", default="1000x750", help="Picture size WxH (default 1000x750)")
    ap.add_argument("--view", help="Viewing direction x,y,z (default: from +z if planar)")
    ap.add_argument("--title", help="Text in the upper left corner")
    ap.add_argument("--plugin", help="Path of HoctContourTree.so")
    ap.add_argument("--hoct", help="Path of the hoct tool (to convert .msh)")
    a = ap.parse_args(argv)
    load_plugin(a.plugin)
    source = open_grid(a.input, a.hoct, a.scalar)
    tree = contour_tree(source, a.scalar, a.simplify, a.augmented)
    w, h = (int(x) for x in a.size.lower().split("x"))
    direction = [float(x) for x in a.view.split(",")] if a.view else None
    render(source, tree, a.output, (w, h), a.isolines, direction, a.title)
    print(f"render_tree: wrote {a.output}")


if __name__ == "__main__":
    main()
