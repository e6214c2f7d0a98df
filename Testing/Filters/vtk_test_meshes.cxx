#include "vtk_test_meshes.h"

#include "vtkCellArray.h"
#include "vtkFloatArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"

namespace geoshaping::testing
{

vtkSmartPointer<vtkPolyData> TriangleGridPolyData(int nx, int ny, double h,
  const std::function<double(int, int)>& malleability, int type, double x0, double y0)
{
  vtkNew<vtkPoints> pts;
  pts->SetDataType(type);
  pts->SetNumberOfPoints(vtkIdType(nx) * ny);
  vtkNew<vtkFloatArray> mal;
  mal->SetName("Malleability");
  if (malleability)
    mal->SetNumberOfTuples(vtkIdType(nx) * ny);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
    {
      const vtkIdType v = vtkIdType(j) * nx + i;
      pts->SetPoint(v, x0 + i * h, y0 + j * h, 0.0);
      if (malleability)
        mal->SetValue(v, float(malleability(i, j)));
    }
  vtkNew<vtkCellArray> tris;
  tris->AllocateExact(2 * vtkIdType(nx - 1) * (ny - 1), 6 * vtkIdType(nx - 1) * (ny - 1));
  for (int j = 0; j + 1 < ny; ++j)
    for (int i = 0; i + 1 < nx; ++i)
    {
      const vtkIdType a = vtkIdType(j) * nx + i, b = a + 1, c = a + nx + 1, d = a + nx;
      const vtkIdType t0[3] = { a, b, c }, t1[3] = { a, c, d };
      tris->InsertNextCell(3, t0);
      tris->InsertNextCell(3, t1);
    }
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  pd->SetPoints(pts);
  pd->SetPolys(tris);
  if (malleability)
    pd->GetPointData()->AddArray(mal);
  return pd;
}

} // namespace geoshaping::testing
