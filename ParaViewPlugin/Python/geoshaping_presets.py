"""Colour helpers for GeoShaping scenes in pvpython/pvbatch and the GUI's Python shell.

The plugin makes the "Malleability (black-body)" colour map the default of every array
named Malleability (ParaViewPlugin/ServerManager/malleability_colormap.h): a plain
Show + ColorBy gives it. These helpers apply it to an array of another name and show the
pinned vertices apart from the heat map:

    import sys; sys.path.append("<GeoShaping source>/ParaViewPlugin/Python")
    import geoshaping_presets
    geoshaping_presets.show_malleability(display, "MyMalleability")  # black-body, 0-1
    geoshaping_presets.show_pins(chain)                              # pinned vertices in cyan
"""
from paraview import simple

PRESET_NAME = "Malleability (black-body)"


def malleability_lookup_table(array_name="Malleability"):
    """The colour map of `array_name` with the preset applied, range fixed to [0, 1]."""
    presets = simple.servermanager.vtkSMTransferFunctionPresets.GetInstance()
    if not presets.HasPreset(PRESET_NAME):
        raise RuntimeError("the GeoShaping plugin is not loaded (no preset %r)" % PRESET_NAME)
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
