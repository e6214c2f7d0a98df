/**
 * @class   vtkSparseSurfaceMapper
 * @brief   An OpenGL polydata mapper that uploads only the points that moved.
 *
 * vtkOpenGLPolyDataMapper rebuilds every vertex buffer (positions, normals, colours)
 * and, through vtkMapper::MapScalars, re-maps every scalar whenever its input is
 * modified: O(points) per frame for a drag that moves a few thousand vertices. When the
 * input's points are the vtkGrowingBoundsPoints it last drew and list the changes of
 * the next update (ChangesAfter), and nothing else the buffers are built from has
 * changed (see Signature()), this mapper writes only the listed positions (and normals,
 * which the producer lists with them) into their buffers (glBufferSubData over runs of
 * nearby ids, with the buffer's own shift and scale) and keeps every other buffer (index,
 * colours): O(changed). When the colouring array records changed values
 * (vtkSparseArrayChanges: a paint dab), only those are re-mapped, by VTK's own
 * MapScalars on the changed subset, and uploaded into the colour buffer. Anything else takes the
 * full build, so what is drawn is always what the stock mapper draws.
 *
 * Cost of a sparse update: sort the k ids, O(k log k); one glBufferSubData per run,
 * where ids closer than MergeGap are one run (the unchanged points between them are
 * rewritten with their current values).
 */
#ifndef vtkSparseSurfaceMapper_h
#define vtkSparseSurfaceMapper_h

#include "GeoShapingRenderingSparseModule.h" // For export macro
#include "vtkNew.h"                          // For vtkNew
#include "vtkOpenGLPolyDataMapper.h"
#include "vtkWeakPointer.h" // For vtkWeakPointer

#include <cstdint> // For std::uintptr_t
#include <vector>  // For std::vector

class vtkDataArray;
class vtkGrowingBoundsPoints;
class vtkOpenGLVertexBufferObject;
class vtkIdTypeArray;

class GEOSHAPINGRENDERINGSPARSE_EXPORT vtkSparseSurfaceMapper : public vtkOpenGLPolyDataMapper
{
public:
  static vtkSparseSurfaceMapper* New();
  vtkTypeMacro(vtkSparseSurfaceMapper, vtkOpenGLPolyDataMapper);

  ///@{
  /// Buffer builds so far: full (every buffer) and sparse (changed positions only), and
  /// the points the last sparse build uploaded.
  vtkGetMacro(NumberOfFullBuilds, int);
  vtkGetMacro(NumberOfSparseBuilds, int);
  vtkGetMacro(LastSparsePoints, vtkIdType);
  ///@}

  /// What of a mapper's settings its buffers depend on (colouring array and mode, lookup
  /// table, scalar range, clipping planes); equal lists, equal buffers.
  static std::vector<std::uintptr_t> Settings(vtkPolyDataMapper* mapper);

  /// Ids closer than this are uploaded as one run. Default 64.
  vtkSetMacro(MergeGap, vtkIdType);
  vtkGetMacro(MergeGap, vtkIdType);

protected:
  vtkSparseSurfaceMapper() = default;
  ~vtkSparseSurfaceMapper() override = default;

  void BuildBufferObjects(vtkRenderer* ren, vtkActor* act) override;

private:
  vtkSparseSurfaceMapper(const vtkSparseSurfaceMapper&) = delete;
  void operator=(const vtkSparseSurfaceMapper&) = delete;

  // Everything the buffers are built from except the point coordinates.
  std::vector<std::uintptr_t> Signature(vtkPolyData* poly, vtkActor* act);
  // Write the positions (and normals) of `ids` into their buffers; false if it cannot.
  bool UploadChanged(vtkPolyData* poly, vtkIdTypeArray* ids);
  // The point scalars this mapper colours by (nullptr: none, or cell scalars).
  vtkDataArray* ColorScalars(vtkPolyData* poly);
  // Re-map and upload the colours of the scalars' changed tuples (vtkSparseArrayChanges);
  // true if none changed; false if it cannot (a full build follows).
  bool UploadChangedColors(vtkPolyData* poly);
  // A buffer this writes: one float triple per point.
  static bool Writable(vtkOpenGLVertexBufferObject* vbo, vtkIdType n);
  // Write the Sorted ids' values into `vbo`, in runs, with its shift and scale.
  void UploadRuns(vtkOpenGLVertexBufferObject* vbo, vtkDataArray* values);

  std::vector<std::uintptr_t> BuiltFrom;
  vtkWeakPointer<vtkGrowingBoundsPoints> BuiltPoints;
  int BuiltGeneration = -1;
  std::vector<vtkIdType> Sorted;
  std::vector<unsigned char> Staging;
  int BuiltScalarsGeneration = 0;
  vtkNew<vtkPolyDataMapper> ColorHelper; // maps the changed scalars only
  vtkIdType MergeGap = 64;
  int NumberOfFullBuilds = 0;
  int NumberOfSparseBuilds = 0;
  vtkIdType LastSparsePoints = 0;
};

#endif
