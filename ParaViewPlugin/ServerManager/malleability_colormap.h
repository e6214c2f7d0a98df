#pragma once
// The black-body heat map is the default colouring of every point array named
// Malleability, in the paraview GUI and in pvpython/pvbatch (docs/painting.md).
//
// ParaView creates one colour map per array name (vtkSMTransferFunctionManager) and,
// when it does, applies the preset named by the setting `.standard_presets.<array>`, then
// the settings under `.array_lookup_tables.<array>.PVLookupTable`; the scalar bar takes
// its title from `.array_lookup_tables.<array>.Title`. This library registers, when it is
// loaded (the plugin's load), the preset (ParaViewPlugin/Presets, embedded at build time)
// and one settings collection below the user's and the site's (their own choices win):
//
//   standard_presets.Malleability              = "Malleability (black-body)"
//   array_lookup_tables.Malleability.Title     = "Malleability"
//   ...Malleability.PVLookupTable.AutomaticRescaleRangeMode = Never   (0 and 1 mean the
//                                                                       same on every surface)
//   ...Malleability.PVLookupTable.Annotations  = 0 "rigid", 1 "soft"  (on the scalar bar)
namespace geoshaping::colormap
{

// Adds the preset (once) and the settings collection (once). Returns false, with a VTK
// error, when the embedded preset cannot be read. Called when the library is loaded.
bool register_malleability_colormap();

} // namespace geoshaping::colormap
