/**
 * @class   vtkGeoShapingGhostRing
 * @brief   The ghost ring a distributed GeoShaping filter needs, made when its input lacks it.
 *
 * On several processes ChainMailDeformation and the geodesic MalleabilityPaint need every
 * neighbour of a point a process owns on that process, and `vtkGhostType` to tell the
 * points it owns from the ghosts (docs/mpi.md, "Ghosts"). ParaView's readers and
 * `RedistributeDataSet` give neither. Ensure() decides on every process alike: the input
 * is used as it is when every process holding points has point and cell `vtkGhostType`
 * arrays (a `GhostCellsGenerator` or `D3` upstream), or when at most one process holds
 * points (nothing is shared); otherwise VTK's vtkGhostCellsGenerator makes one ghost level.
 * The generator matches the pieces' points by point `GlobalIds`: without them (on every
 * process) they are numbered by coordinates first (geoshaping/parallel/coordinate_ids.h, what the
 * filters would number them by; matching by coordinates alone left surfaces without
 * their ghosts in VTK 9.2), and a piece holding two points at one position (split nodes)
 * is refused, since no numbering by coordinates can keep them apart. The copy is kept
 * while the input object, its points, cells and arrays stay (each by its own
 * modification time), so a drag frame does not make it again. Not wrapped.
 */
#ifndef vtkGeoShapingGhostRing_h
#define vtkGeoShapingGhostRing_h

#include "GeoShapingAdapterModule.h" // For export macro
#include "vtkType.h"

#include <memory>
#include <string>

class vtkMultiProcessController;
class vtkPointSet;

class GEOSHAPINGADAPTER_EXPORT vtkGeoShapingGhostRing
{
public:
  vtkGeoShapingGhostRing();
  ~vtkGeoShapingGhostRing();
  vtkGeoShapingGhostRing(const vtkGeoShapingGhostRing&) = delete;
  vtkGeoShapingGhostRing& operator=(const vtkGeoShapingGhostRing&) = delete;

  /// Collective over `controller`. The data to work on: `input`, or its copy with one
  /// ghost level; null, with `error` (the same text on every process), when the input is
  /// refused or the generator failed.
  vtkPointSet* Ensure(
    vtkPointSet* input, vtkMultiProcessController* controller, std::string& error);

private:
  struct vtkInternals;
  std::unique_ptr<vtkInternals> Internals;
};

#endif
