"""The black-body heat map is the default colouring of Malleability: a plain
Show of a painted surface, with nothing imported by hand, colours it with the plugin's
preset over a fixed [0, 1] range whatever the data's range, and the scalar bar says which
end is rigid and which soft. Another array keeps ParaView's default."""
import json
import os

from geoshaping_testing import check, load, triangulated_plane
from paraview.simple import *  # noqa: F401,F403

PRESET = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "ParaViewPlugin",
                      "Presets", "Malleability_black-body.json")

load(ns=globals())
with open(PRESET) as f:
    preset = json.load(f)[0]
presets = servermanager.vtkSMTransferFunctionPresets.GetInstance()
check(presets.HasPreset(preset["Name"]), "the plugin put '%s' in the preset list" % preset["Name"])

plane = triangulated_plane(10)
# Painted values span 0.5 .. 0.9 only: the map must not stretch over them.
paint = MalleabilityPaint(Input=plane, Dabs=[5.0, 5.0, 0.0, 3.0, 0.9, 1.0])  # noqa: F405
view = CreateRenderView()
display = Show(paint, view)
check(list(display.ColorArrayName) == ["POINTS", "Malleability"], "coloured by Malleability")
lut = GetColorTransferFunction("Malleability")
check(list(lut.RGBPoints) == [float(v) for v in preset["RGBPoints"]],
      "the colour map is the black-body preset over [0, 1]: %s" % list(lut.RGBPoints))
check(lut.AutomaticRescaleRangeMode == "Never", "the range stays [0, 1] (rescale Never)")
check(list(lut.Annotations) == ["0", "rigid", "1", "soft"], "0 is marked rigid and 1 soft")
display.SetScalarBarVisibility(view, True)
check(GetScalarBar(lut, view).Title == "Malleability", "the scalar bar is titled Malleability")
Render(view)
check(list(lut.RGBPoints)[0] == 0.0 and list(lut.RGBPoints)[-4] == 1.0,
      "a render does not rescale it to the data (0.5 .. 0.9)")

other = Elevation(Input=plane)
Show(other, view)
ColorBy(GetDisplayProperties(other, view), ("POINTS", "Elevation"))
check(GetColorTransferFunction("Elevation").AutomaticRescaleRangeMode != "Never",
      "other arrays keep ParaView's own default")
