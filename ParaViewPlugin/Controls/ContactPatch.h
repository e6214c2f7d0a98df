#pragma once
// The haptic contact patch (docs/haptics.md): the triangles of a shown surface near the
// stylus, handed to the haptics layer's force model each frame. VTK only, no Qt; the
// dock's proxy facade (pqHapticsProxies) is its one user, Testing/GUI/TestContactPatch its test.
#include <vtkType.h>

#include <vector>

class vtkAbstractCellLocator;
class vtkDataSet;

namespace geoshaping
{
namespace contact
{

/// Appends to `xyz` (9 doubles per triangle) the triangles of the surface cells of
/// `surface` that `locator` (built on it) finds in the box of half-size `radius`
/// around `center`: triangles, quads, pixels, polygons (as fans) and strips; other
/// cells (lines, volumes) are skipped. Nothing for a null surface or locator, or a
/// radius or centre that is negative or not finite. Cost: the locator's query plus the
/// cells it returns. Returns the number of triangles appended.
vtkIdType AppendTrianglesNear(vtkDataSet* surface, vtkAbstractCellLocator* locator,
  const double center[3], double radius, std::vector<double>& xyz);

} // namespace contact
} // namespace geoshaping
