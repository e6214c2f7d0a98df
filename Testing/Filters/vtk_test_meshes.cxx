#include "vtk_test_meshes.h"

#include "vtkCellArray.h"
#include "vtkCellType.h"
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

vtkSmartPointer<vtkUnstructuredGrid> TetSlabUnstructuredGrid(
  int nx, int ny, int nz, double h, const std::function<double(int, int, int)>& malleability)
{
  auto ug = vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkNew<vtkPoints> pts;
  pts->SetDataType(VTK_DOUBLE);
  vtkNew<vtkFloatArray> mal;
  mal->SetName("Malleability");
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
      {
        pts->InsertNextPoint(i * h, j * h, k * h);
        if (malleability)
          mal->InsertNextValue(float(malleability(i, j, k)));
      }
  ug->SetPoints(pts);
  if (malleability)
    ug->GetPointData()->AddArray(mal);
  auto id = [&](int i, int j, int k) { return vtkIdType((k * ny + j) * nx + i); };
  const int tets[6][4] = { { 0, 1, 2, 6 }, { 0, 2, 3, 6 }, { 0, 3, 7, 6 }, { 0, 7, 4, 6 },
    { 0, 4, 5, 6 }, { 0, 5, 1, 6 } };
  for (int k = 0; k + 1 < nz; ++k)
    for (int j = 0; j + 1 < ny; ++j)
      for (int i = 0; i + 1 < nx; ++i)
      {
        const vtkIdType v[8] = { id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k), id(i, j + 1, k),
          id(i, j, k + 1), id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1) };
        for (const auto& t : tets)
        {
          const vtkIdType ids[4] = { v[t[0]], v[t[1]], v[t[2]], v[t[3]] };
          ug->InsertNextCell(VTK_TETRA, 4, ids);
        }
      }
  return ug;
}

} // namespace geoshaping::testing
