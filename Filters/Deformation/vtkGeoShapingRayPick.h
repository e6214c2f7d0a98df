/**
 * @class   vtkGeoShapingRayPick
 * @brief   The surface under a pixel on every process of a server: the nearest hit of a
 *          ray with the pieces, reduced across processes.
 *
 * Each process meets the ray RayOrigin + t RayDirection (t >= 0, the input's coordinates)
 * with the polygons of its piece (triangles, quads, polygons; ghost cells left out: their
 * owner meets them), and the
 * processes' nearest hits are reduced to one (the core's ray_pick.h: the least t, then the
 * lower rank) by one AllGather of 10 doubles a process, so every process, and the client
 * reading the information properties from the first, has the same answer: Hit, HitPoint,
 * HitNormal (the polygon's, as its winding gives it), HitRank (the owner) and HitPointId
 * (the polygon's vertex nearest the hit, named by its point GlobalIds when the input has
 * them, so the same on any number of processes, else its index in the piece). The
 * interactor asks it when the view renders remotely (docs/interactor.md, "The pick").
 * An empty piece, or one that is not polygons, meets nothing and still joins the
 * reduction, so no process waits for another. The output is empty.
 */
#ifndef vtkGeoShapingRayPick_h
#define vtkGeoShapingRayPick_h

#include "GeoShapingFiltersDeformationModule.h"
#include "vtkPolyDataAlgorithm.h"

class GEOSHAPINGFILTERSDEFORMATION_EXPORT vtkGeoShapingRayPick : public vtkPolyDataAlgorithm
{
public:
  static vtkGeoShapingRayPick* New();
  vtkTypeMacro(vtkGeoShapingRayPick, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  vtkSetVector3Macro(RayOrigin, double);
  vtkGetVector3Macro(RayOrigin, double);
  vtkSetVector3Macro(RayDirection, double);
  vtkGetVector3Macro(RayDirection, double);

  /// The answer of the last update (the same on every process).
  vtkGetMacro(Hit, int);
  vtkGetVector3Macro(HitPoint, double);
  vtkGetVector3Macro(HitNormal, double);
  vtkGetMacro(HitRank, int);
  vtkGetMacro(HitPointId, vtkIdType);

protected:
  vtkGeoShapingRayPick();
  ~vtkGeoShapingRayPick() override = default;
  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  double RayOrigin[3] = { 0.0, 0.0, 0.0 };
  double RayDirection[3] = { 0.0, 0.0, -1.0 };
  int Hit = 0;
  double HitPoint[3] = { 0.0, 0.0, 0.0 };
  double HitNormal[3] = { 0.0, 0.0, 0.0 };
  int HitRank = -1;
  vtkIdType HitPointId = -1;

private:
  vtkGeoShapingRayPick(const vtkGeoShapingRayPick&) = delete;
  void operator=(const vtkGeoShapingRayPick&) = delete;
};

#endif
