/**
 * @class   vtkGeoShapingSurfaceRepresentation
 * @brief   ParaView's Surface representation with a frame that costs what moved.
 *
 * A drag through ParaView's stock Surface representation re-runs vtkPVGeometryFilter,
 * recomputes bounds over every cell and rebuilds every vertex and index buffer: O(mesh)
 * per frame for a deformation that moved a few thousand vertices. This representation
 * is the stock one (same proxy properties: colouring, opacity, lighting, scalar bar,
 * selection, picking) with two changes:
 *
 * - When its input's points are a vtkGrowingBoundsPoints that lists the changes since
 *   the update it last drew (the ChainMail deformation's are) and nothing but point
 *   coordinates changed (see
 *   vtkSparsePointChanges::AppendSignature), it skips the geometry filter and copies the
 *   listed points into the extracted surface through the surface-to-input point map
 *   (`vtkOriginalPointIds`, identity for polydata), O(changed). A vtkUnstructuredGrid is
 *   extracted once; later frames touch only its moved surface points. Point arrays that
 *   record their changed values (vtkSparseArrayChanges: the malleability a paint dab
 *   changed) are followed the same way, and the mapper re-maps only those colours.
 * - It draws with vtkSparseCompositeMapper, which uploads only those points.
 *
 * Anything else (first update, new topology or arrays, a skipped update, composite
 * data) takes the stock path, so what is drawn is always the input's current shape.
 * So does a process that draws geometry delivered from another one (a client rendering
 * a remote pvserver's data locally): it says so once. With remote rendering the server
 * draws, and the sparse path applies there.
 */
#ifndef vtkGeoShapingSurfaceRepresentation_h
#define vtkGeoShapingSurfaceRepresentation_h

#include "GeoShapingRenderingSparseModule.h" // For export macro
#include "vtkGeometryRepresentationWithFaces.h"
#include "vtkNew.h"          // For vtkNew
#include "vtkSmartPointer.h" // For vtkSmartPointer
#include "vtkWeakPointer.h"  // For vtkWeakPointer

#include <cstdint> // For std::uintptr_t
#include <map>     // For std::map
#include <vector>  // For std::vector

class vtkDataArray;
class vtkGrowingBoundsPoints;
class vtkIdTypeArray;
class vtkPointSet;
class vtkSparseCompositeMapper;
class vtkSparseSurface;

class GEOSHAPINGRENDERINGSPARSE_EXPORT vtkGeoShapingSurfaceRepresentation
  : public vtkGeometryRepresentationWithFaces
{
public:
  static vtkGeoShapingSurfaceRepresentation* New();
  vtkTypeMacro(vtkGeoShapingSurfaceRepresentation, vtkGeometryRepresentationWithFaces);

  ///@{
  /// Updates that followed a sparse change (O(changed)) and that took the stock path,
  /// and the mapper's buffer builds of each kind; for tests and benchmarks.
  vtkGetMacro(NumberOfSparseUpdates, int);
  vtkGetMacro(NumberOfFullUpdates, int);
  int GetNumberOfSparseBuilds();
  int GetNumberOfFullBuilds();
  ///@}

protected:
  vtkGeoShapingSurfaceRepresentation();
  ~vtkGeoShapingSurfaceRepresentation() override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

public:
  /// Overridden to say once when this process draws data another process extracted
  /// (a client rendering a remote server's geometry): those frames take the stock path.
  int ProcessViewRequest(
    vtkInformationRequestKey* request, vtkInformation* inInfo, vtkInformation* outInfo) override;

private:
  vtkGeoShapingSurfaceRepresentation(const vtkGeoShapingSurfaceRepresentation&) = delete;
  void operator=(const vtkGeoShapingSurfaceRepresentation&) = delete;

  // Apply the input's sparse change to the surface; false if it does not follow.
  bool FollowSparse(vtkPointSet* input);
  // Follow the input's point arrays that record their changes; false if one does not.
  bool FollowArrays(vtkPointSet* input);
  // Copy the changed input points to the surface through the point map.
  bool CopyChanged(vtkPointSet* input, vtkIdTypeArray* changed);
  // After the stock path: wrap its surface for sparse updates when the input allows.
  void Adopt(vtkPointSet* input);

  vtkSparseCompositeMapper* SparseMapper;
  vtkSmartPointer<vtkSparseSurface> Surface;
  vtkWeakPointer<vtkGrowingBoundsPoints> InputPoints;
  int InputGeneration = -1;
  std::vector<std::uintptr_t> InputSignature;
  std::vector<vtkIdType> InputToSurface;         // -1: not on the surface
  std::map<vtkDataArray*, int> ArrayGenerations; // recording arrays: the change last seen
  bool SharedCoordinates = false;                // the surface's coordinates are the input's array
  vtkNew<vtkIdTypeArray> SurfaceChanged;
  int NumberOfSparseUpdates = 0;
  int NumberOfFullUpdates = 0;
  bool NoticedRemote = false;
};

#endif
