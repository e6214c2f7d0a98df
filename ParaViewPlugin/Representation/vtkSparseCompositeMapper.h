/**
 * @class   vtkSparseCompositeMapper
 * @brief   vtkCompositePolyDataMapper2 that draws a lone vtkSparseSurface block with a
 *          vtkSparseSurfaceMapper, so a drag uploads only what moved.
 *
 * ParaView's geometry representations hand their mapper a one-block composite data set
 * and configure it as a vtkCompositePolyDataMapper2 (colouring, selection, block
 * attributes). This mapper keeps that interface. When its input is a single visible
 * vtkSparseSurface without block colour or opacity, no hardware selector is active and
 * no selection is shown, it copies its colouring settings to an internal
 * vtkSparseSurfaceMapper and lets it draw the surface; otherwise (picking, selections,
 * multi-block data) it draws as vtkCompositePolyDataMapper2 does.
 */
#ifndef vtkSparseCompositeMapper_h
#define vtkSparseCompositeMapper_h

#include "GeoShapingRenderingSparseModule.h" // For export macro
#include "vtkCompositePolyDataMapper2.h"
#include "vtkNew.h" // For vtkNew

#include <cstdint> // For std::uintptr_t
#include <vector>  // For std::vector

class vtkSparseSurfaceMapper;

class GEOSHAPINGRENDERINGSPARSE_EXPORT vtkSparseCompositeMapper : public vtkCompositePolyDataMapper2
{
public:
  static vtkSparseCompositeMapper* New();
  vtkTypeMacro(vtkSparseCompositeMapper, vtkCompositePolyDataMapper2);

  void Render(vtkRenderer* ren, vtkActor* act) override;
  void ReleaseGraphicsResources(vtkWindow* window) override;

  /// The mapper that draws a vtkSparseSurface (its build counters tell what a frame cost).
  vtkSparseSurfaceMapper* GetSurfaceMapper();

protected:
  vtkSparseCompositeMapper();
  ~vtkSparseCompositeMapper() override;

private:
  vtkSparseCompositeMapper(const vtkSparseCompositeMapper&) = delete;
  void operator=(const vtkSparseCompositeMapper&) = delete;

  // The input's only block when the sparse path can draw it, else nullptr.
  vtkPolyData* SparseBlock(vtkRenderer* ren);

  vtkNew<vtkSparseSurfaceMapper> Surface;
  std::vector<std::uintptr_t> CopiedSettings;
};

#endif
