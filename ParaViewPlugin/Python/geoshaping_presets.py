"""The "Malleability (black-body)" colour map for ParaView 5.11.

ParaView 5.11 cannot ship a colour-map preset from a plugin's CMake, so this helper
imports the preset file that sits next to it (../Presets) and applies it with the
0-1 range fixed. From the Python shell or a pvpython/pvbatch script:

    import sys; sys.path.append("<GeoShaping source>/ParaViewPlugin/Python")
    import geoshaping_presets
    geoshaping_presets.show_malleability(display)          # colour a display by it
    geoshaping_presets.malleability_lookup_table()         # or just get the LUT
    geoshaping_presets.show_pins(chain)                    # pinned vertices in cyan
"""
import os

from paraview import simple

PRESET_NAME = "Malleability (black-body)"
PRESET_FILE = os.path.join(os.path.dirname(os.path.abspath(__file__)), os.pardir,
                           "Presets", "Malleability_black-body.json")


def import_preset(path=PRESET_FILE):
    """Adds the preset to ParaView's list (once per session); returns True when present."""
    presets = simple.servermanager.vtkSMTransferFunctionPresets.GetInstance()
    if not presets.HasPreset(PRESET_NAME):
        simple.ImportPresets(os.path.normpath(path))
    return presets.HasPreset(PRESET_NAME)


def malleability_lookup_table(array_name="Malleability"):
    """The colour map of `array_name` with the preset applied, range fixed to [0, 1]."""
    if not import_preset():
        raise RuntimeError("cannot import " + PRESET_FILE)
    lut = simple.GetColorTransferFunction(array_name)
    lut.ApplyPreset(PRESET_NAME, True)
    lut.AutomaticRescaleRangeMode = "Never"
    lut.RescaleTransferFunction(0.0, 1.0)
    simple.GetOpacityTransferFunction(array_name).RescaleTransferFunction(0.0, 1.0)
    return lut


def show_malleability(display, array_name="Malleability"):
    """Colours `display` by the point array `array_name` with the black-body map."""
    simple.ColorBy(display, ("POINTS", array_name))
    lut = malleability_lookup_table(array_name)
    display.LookupTable = lut
    return lut


PIN_COLOR = [0.0, 1.0, 1.0]  # cyan: absent from the black-body map


def show_pins(source, view=None, array_name="Pinned"):
    """Shows the pinned vertices of `source` (its point mask `array_name`, non-zero =
    pinned) distinctly from the heat map: exactly those vertices, extracted by a query
    selection, drawn as cyan spheres (point size 6) over the surface, which keeps its
    Malleability colours. Returns (extract, display)."""
    view = view or simple.GetActiveViewOrCreate("RenderView")
    query = simple.SelectionQuerySource(ElementType="Point Data",
                                        QueryString="(%s > 0)" % array_name)
    pins = simple.ExtractSelection(Input=source, Selection=query)
    display = simple.Show(pins, view)
    display.SetRepresentationType("Points")
    simple.ColorBy(display, None)
    display.AmbientColor = PIN_COLOR
    display.DiffuseColor = PIN_COLOR
    display.PointSize = 6.0
    display.RenderPointsAsSpheres = 1
    return pins, display
