"""The "Malleability (black-body)" colour map for ParaView 5.11.

ParaView 5.11 cannot ship a colour-map preset from a plugin's CMake, so this helper
imports the preset file that sits next to it (../Presets) and applies it with the
0-1 range fixed. From the Python shell or a pvpython/pvbatch script:

    import sys; sys.path.append("<GeoShaping source>/ParaViewPlugin/Python")
    import geoshaping_presets
    geoshaping_presets.show_malleability(display)          # colour a display by it
    geoshaping_presets.malleability_lookup_table()         # or just get the LUT
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
