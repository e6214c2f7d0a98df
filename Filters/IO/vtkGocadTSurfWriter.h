/**
 * @class   vtkGocadTSurfWriter
 * @brief   Write a triangulated vtkPolyData as a GOCAD TSurf (`.ts`) file.
 *
 * Writes what vtkGocadTSurfReader reads: one `GOCAD TSurf` object per value of the
 * cell array `Surface` (one object when it is absent), `TFACE` blocks from the cell
 * array `TFace`, a HEADER with the field-data `Name` of the surface (else the file
 * name's stem), a `GOCAD_ORIGINAL_COORDINATE_SYSTEM` block from the field data
 * `AxisName`, `AxisUnit`, `CoordinateSystemName` (else X Y Z, m, Default) with
 * `ZPOSITIVE Elevation` (the data's z is elevation), and every named numeric point
 * array (`Malleability` among them) as a `PVRTX` property with its `ESIZES`. NaN and
 * infinite property values are written as the property's `NO_DATA_VALUES` entry (a
 * value the array does not contain), so they read back as NaN.
 *
 * Numbers are written as the shortest decimal that parses back to the same double,
 * so writer -> reader is bit-exact for coordinates and property values. Polygons
 * that are not triangles and triangle strips are refused with an error (apply
 * Triangulate first); vertices and lines are left out with a warning; other cell data
 * is not written. Non-finite coordinates are refused. See docs/tsurf.md.
 *
 * Pieces of a surface gathered from several processes (ParaView's
 * vtkParallelSerialWriter appends them to the first process; docs/mpi.md) are written as
 * the one surface they are cut from: when the input has vtkGhostType arrays, ghost cells
 * are left out, the copies of a point (equal point GlobalIds) are one vertex, ghost
 * points no triangle uses are left out, and vtkGhostType is not written as a property.
 */
#ifndef vtkGocadTSurfWriter_h
#define vtkGocadTSurfWriter_h

#include "GeoShapingIOModule.h" // For export macro
#include "vtkWriter.h"

class vtkPolyData;

class GEOSHAPINGIO_EXPORT vtkGocadTSurfWriter : public vtkWriter
{
public:
  static vtkGocadTSurfWriter* New();
  vtkTypeMacro(vtkGocadTSurfWriter, vtkWriter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The `.ts` file to write.
  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);
  ///@}

  vtkPolyData* GetInput();

protected:
  vtkGocadTSurfWriter() = default;
  ~vtkGocadTSurfWriter() override;

  void WriteData() override;
  int FillInputPortInformation(int port, vtkInformation* info) override;

  char* FileName = nullptr;

private:
  vtkGocadTSurfWriter(const vtkGocadTSurfWriter&) = delete;
  void operator=(const vtkGocadTSurfWriter&) = delete;
};

#endif
