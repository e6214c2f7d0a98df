#pragma once
// What every stability case checks (docs/stability.md): run the filter, then assert no
// NaN/Inf introduced, the input unmodified, and the ChainMail invariants.
#include "vtkChainMailDeformationFilter.h"

#include "vtkSmartPointer.h"
#include "vtkTestErrorObserver.h"

#include <string>

class vtkPointSet;
class vtkPolyData;
class vtkUnstructuredGrid;

namespace stability
{

// nx * ny triangle grid at (x0 + i h, y0 + j h, 0); "Malleability" filled with `m`.
vtkSmartPointer<vtkPolyData> Grid(int nx, int ny, double h, double m, int type = 11 /*VTK_DOUBLE*/,
  double x0 = 0.0, double y0 = 0.0);
// nx * ny * nz tetrahedral slab, spacing h, "Malleability" = m.
vtkSmartPointer<vtkUnstructuredGrid> Slab(int nx, int ny, int nz, double h, double m);

struct Outcome
{
  vtkPointSet* output = nullptr;
  bool error = false, warning = false;
  std::string messages;
};

// Runs `f` on `input` (diagnostics on) and checks, with gtest assertions:
// - the input's points and point arrays are bit-identical afterwards;
// - output has the input's point count; every output coordinate is finite where the
//   input's is (nothing non-finite is introduced);
// - each vertex moved at most once (the sponsors form a tree rooted at the grasp:
//   every moved vertex but the grasp has a moved sponsor that is its neighbour);
// - each moved vertex lies in its sponsor's valid region (to 1e-9 of the scale);
// - with the FIFO Priority queue, rigid regions (malleability 0) translate exactly.
// The filter's ValidRegionFrame is set from the environment variable
// GEOSHAPING_STABILITY_FRAME when it is defined (0 Axes, 1 Link).
// `check_invariants` false: only the first two (for inputs the filter refuses).
Outcome Check(vtkChainMailDeformationFilter* f, vtkPointSet* input, bool check_invariants = true);

} // namespace stability
