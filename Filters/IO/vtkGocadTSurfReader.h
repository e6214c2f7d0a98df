/**
 * @class   vtkGocadTSurfReader
 * @brief   Read GOCAD TSurf (`.ts`) triangulated surfaces, and VSet (`.vs`) point sets
 *          such as well markers, into vtkPolyData.
 *
 * Reads every `GOCAD TSurf ... END` and `GOCAD VSet ... END` object of the file (a VSet's
 * points become vertex cells, numbered before the triangles as vtkPolyData orders them;
 * a TRGL inside a VSet is an error): `VRTX` and `PVRTX` vertices,
 * `ATOM`/`PATOM` (another id for an earlier vertex: it shares that point, so the
 * surface stays connected across TFACE borders), `TRGL` triangles and `TFACE` parts.
 * `PROPERTIES` (with `ESIZES`) become double point arrays; values equal to
 * `NO_DATA_VALUES` become NaN. Output:
 *
 * - points in double precision, always (UTM-sized coordinates);
 * - cell arrays `Surface` (index of the TSurf or VSet object in the file) and `TFace`
 *   (index of the TFACE within its surface; 0 for a VSet's vertices), both int;
 * - field data `Name` (HEADER `name:`, one string per surface) and, from the first
 *   surface that has them, `AxisName`, `AxisUnit` (3 strings), `CoordinateSystemName`;
 *   `ZPositive` (one string per surface, as written in the file).
 *
 * `ZPOSITIVE Depth` is honoured by negating z, so the output z is always elevation.
 * `BSTONE`, `BORDER`, `HEADER` and other `{ }` blocks, comments and CRLF line ends are
 * accepted. A bad file (unknown vertex id, non-numeric or non-finite number, truncated,
 * empty, binary or missing) gives an error naming the line and an empty output.
 * See docs/tsurf.md.
 */
#ifndef vtkGocadTSurfReader_h
#define vtkGocadTSurfReader_h

#include "GeoShapingIOModule.h" // For export macro
#include "vtkPolyDataAlgorithm.h"

class GEOSHAPINGIO_EXPORT vtkGocadTSurfReader : public vtkPolyDataAlgorithm
{
public:
  static vtkGocadTSurfReader* New();
  vtkTypeMacro(vtkGocadTSurfReader, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The `.ts` (or `.vs`) file to read.
  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);
  ///@}

  /// 1 when the file's first non-comment line starts a GOCAD TSurf, else 0.
  int CanReadFile(const char* fileName);

protected:
  vtkGocadTSurfReader();
  ~vtkGocadTSurfReader() override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  char* FileName = nullptr;

private:
  vtkGocadTSurfReader(const vtkGocadTSurfReader&) = delete;
  void operator=(const vtkGocadTSurfReader&) = delete;
};

#endif
