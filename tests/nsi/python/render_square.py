"""nsi.py end to end: a red square moved right by a double matrix, lit by a
hidden uniform environment, rendered through libnsi to a PFM whose pixels
are checked. Usage: render_square.py OUTPUT.pfm"""

import struct
import sys

import nsi

output = sys.argv[1]
ctx = nsi.Context()
ctx.Begin()
ctx.Create("cam", "perspectivecamera")
ctx.Connect("cam", "", nsi.SCENE_ROOT, "objects")
ctx.SetAttribute("cam", fov=nsi.FloatArg(30))
ctx.Create("scr", "screen")
ctx.Connect("scr", "", "cam", "screens")
ctx.SetAttribute("scr", resolution=nsi.Arg((16, 16), arraylength=2),
                 oversampling=4)
ctx.Create("layer", "outputlayer")
ctx.Connect("layer", "", "scr", "outputlayers")
ctx.SetAttribute("layer", variablename="Ci")
ctx.Create("file", "outputdriver")
ctx.Connect("file", "", "layer", "outputdrivers")
ctx.SetAttribute("file", drivername="pfm", imagefilename=output)

ctx.Create("move", "transform")
ctx.Connect("move", "", nsi.SCENE_ROOT, "objects")
ctx.SetAttribute("move", transformationmatrix=nsi.DoubleMatrixArg(
    (1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 1.5, 0, 0, 1)))
ctx.Create("shape", "mesh")
ctx.Connect("shape", "", "move", "objects")
ctx.SetAttribute("shape", nvertices=4, P=nsi.Arg(
    (-1, -1, -10, 1, -1, -10, 1, 1, -10, -1, 1, -10), type=nsi.Type.Point))
ctx.Create("red", "shader")
ctx.SetAttribute("red", shaderfilename="lambert",
                 i_color=nsi.ColorArg(1, 0, 0))
ctx.Create("attr", "attributes")
ctx.Connect("red", "", "attr", "surfaceshader")
ctx.Connect("attr", "", "shape", "geometryattributes")

ctx.Create("sky", "environment")
ctx.Connect("sky", "", nsi.SCENE_ROOT, "objects")
ctx.Create("light", "shader")
ctx.SetAttribute("light", shaderfilename="environmentLight")
ctx.Create("sky_attr", "attributes")
ctx.Connect("light", "", "sky_attr", "surfaceshader")
ctx.Connect("sky_attr", "", "sky", "geometryattributes")
ctx.SetAttribute("sky_attr", **{"visibility.camera": nsi.IntegerArg(0)})

ctx.RenderControl(action="start")
ctx.RenderControl(action="wait")
ctx.End()

with open(output, "rb") as f:
    data = f.read()
header = data.split(b"\n", 3)
assert header[0] == b"PF", header[0]
width, height = (int(v) for v in header[1].split())
assert (width, height) == (16, 16), (width, height)
pixels = header[3]


def rgb(x, y_from_top):
    row = height - 1 - y_from_top  # PFM rows run bottom to top
    return struct.unpack_from("<3f", pixels, 12 * (row * width + x))


# 0.335 units per pixel: the square, x from 0.5 to 2.5, covers columns 9-15.
failures = []
r, g, b = rgb(12, 8)
if not (r > 0.8 and g == 0 and b == 0):
    failures.append("column 12 should be red: %r" % ((r, g, b),))
if rgb(5, 8) != (0, 0, 0):
    failures.append("column 5 should be black: %r" % (rgb(5, 8),))
if rgb(12, 0) != (0, 0, 0):
    failures.append("the top row should be black: %r" % (rgb(12, 0),))
for failure in failures:
    print(failure)
sys.exit(1 if failures else 0)
