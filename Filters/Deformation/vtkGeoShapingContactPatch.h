/**
 * @class   vtkGeoShapingContactPatch
 * @brief   The haptic contact patch on every process of a server: the surface triangles
 *          near the stylus, gathered to the first process.
 *
 * The stylus's contact patch (docs/haptics.md, "The contact patch on a server"): the
 * triangles of the surface cells whose bounds meet the box of half-size Radius around
 * Center (the input's coordinates), fanned as AppendTrianglesNear says. Each process
 * selects the owned cells of its piece (ghost cells left out: their owner sends them, so
 * every triangle comes once), and one GatherV collects the pieces' triangles, rank by
 * rank, on the first process, whose Triangles (9 doubles a triangle) the client reads as
 * an information property: one push of the stylus and one pull of the patch a graphics
 * frame when the client holds no geometry. With MaxTriangles only the nearest triangles
 * travel. A Center that is not finite or a negative Radius is an error: no triangles
 * (every process still joins the gather). An empty piece, or one that is not surface
 * cells, selects nothing and still joins the gather. A cell locator per piece is kept
 * and rebuilt when the input's geometry changes. The output is empty.
 */
#ifndef vtkGeoShapingContactPatch_h
#define vtkGeoShapingContactPatch_h

#include "GeoShapingFiltersDeformationModule.h"
#include "vtkPolyDataAlgorithm.h"
#include "vtkSmartPointer.h"

#include <vector>

class vtkAbstractCellLocator;
class vtkDataSet;
class vtkDoubleArray;
class vtkStaticCellLocator;

class GEOSHAPINGFILTERSDEFORMATION_EXPORT vtkGeoShapingContactPatch : public vtkPolyDataAlgorithm
{
public:
  static vtkGeoShapingContactPatch* New();
  vtkTypeMacro(vtkGeoShapingContactPatch, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  vtkSetVector3Macro(Center, double);
  vtkGetVector3Macro(Center, double);
  vtkSetMacro(Radius, double);
  vtkGetMacro(Radius, double);
  /// When > 0, only the MaxTriangles triangles nearest to Center are sent (the core's
  /// keep_nearest, mesh/nearest_triangles.h, on each process and again on the first): what the
  /// interactor keeps of a patch anyway when distances in the input's coordinates order the
  /// triangles as the device's do. 0 (default): every triangle of the box.
  vtkSetClampMacro(MaxTriangles, int, 0, VTK_INT_MAX);
  vtkGetMacro(MaxTriangles, int);

  /// The patch of the last update, 9 doubles a triangle (the first process's holds every
  /// process's, rank by rank; the others hold none).
  vtkDoubleArray* GetTriangles();

  /**
   * The selection rule, shared with the client's own patch (pqHapticsProxies): appends to
   * `xyz` (9 doubles per triangle) the triangles of the surface cells of `surface` that
   * `locator` (built on it) finds in the box of half-size `radius` around `center` and
   * whose own bounds meet that box: triangles, quads, pixels, polygons (as fans) and
   * strips; other cells (lines, volumes) are skipped, and with `ownedOnly` the ghost
   * cells (DUPLICATECELL) too. Nothing for a null surface or locator, or a radius or
   * centre that is negative or not finite. Cost: the locator's query plus the cells it
   * returns. Returns the number of triangles appended.
   */
  static vtkIdType AppendTrianglesNear(vtkDataSet* surface, vtkAbstractCellLocator* locator,
    const double center[3], double radius, std::vector<double>& xyz, bool ownedOnly = false);

protected:
  vtkGeoShapingContactPatch();
  ~vtkGeoShapingContactPatch() override;
  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  double Center[3] = { 0.0, 0.0, 0.0 };
  double Radius = 0.0;
  int MaxTriangles = 0;
  vtkSmartPointer<vtkDoubleArray> Triangles;
  vtkSmartPointer<vtkStaticCellLocator> Locator;
  vtkDataSet* LocatorData = nullptr;
  vtkMTimeType LocatorTime = 0;

private:
  vtkGeoShapingContactPatch(const vtkGeoShapingContactPatch&) = delete;
  void operator=(const vtkGeoShapingContactPatch&) = delete;
};

#endif
