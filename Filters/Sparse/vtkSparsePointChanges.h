/**
 * @class   vtkSparsePointChanges
 * @brief   What a consumer must compare before it applies a sparse point change.
 *
 * vtkGrowingBoundsPoints says which coordinates changed between two updates; a
 * consumer that keeps a copy of a data set (an extracted surface, GPU buffers) may
 * apply only those when nothing else about the data set changed. AppendSignature()
 * lists that "nothing else": the point and cell counts, the cell arrays and every point
 * and cell data array (each object and its modification time; the object only for the
 * active point normals and for point arrays that record their changes with
 * vtkSparseArrayChanges). Two equal signatures mean the data sets can differ only in
 * point coordinates and normals, which the producer lists together, and in the values
 * of recording arrays, which the consumer follows with vtkSparseArrayChanges.
 */
#ifndef vtkSparsePointChanges_h
#define vtkSparsePointChanges_h

#include "GeoShapingFiltersSparseModule.h" // For export macro
#include "vtkObject.h"

#include <cstdint> // For std::uintptr_t
#include <vector>  // For std::vector

class vtkDataSet;

class GEOSHAPINGFILTERSSPARSE_EXPORT vtkSparsePointChanges : public vtkObject
{
public:
  static vtkSparsePointChanges* New();
  vtkTypeMacro(vtkSparsePointChanges, vtkObject);

  /// Append to `signature` what identifies `data` apart from its point coordinates.
  static void AppendSignature(vtkDataSet* data, std::vector<std::uintptr_t>& signature);

  /// Append an object and its modification time (0, 0 for nullptr).
  static void AppendObject(vtkObject* object, std::vector<std::uintptr_t>& signature);

protected:
  vtkSparsePointChanges() = default;
  ~vtkSparsePointChanges() override = default;

private:
  vtkSparsePointChanges(const vtkSparsePointChanges&) = delete;
  void operator=(const vtkSparsePointChanges&) = delete;
};

#endif
