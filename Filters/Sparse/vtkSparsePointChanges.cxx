#include "vtkSparsePointChanges.h"

#include "vtkSparseArrayChanges.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDataSet.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"

vtkStandardNewMacro(vtkSparsePointChanges);

void vtkSparsePointChanges::AppendObject(vtkObject* object, std::vector<std::uintptr_t>& signature)
{
  signature.push_back(reinterpret_cast<std::uintptr_t>(object));
  signature.push_back(object ? std::uintptr_t(object->GetMTime()) : 0);
}

void vtkSparsePointChanges::AppendSignature(
  vtkDataSet* data, std::vector<std::uintptr_t>& signature)
{
  if (!data)
  {
    signature.push_back(0);
    return;
  }
  signature.push_back(std::uintptr_t(data->GetNumberOfPoints()));
  signature.push_back(std::uintptr_t(data->GetNumberOfCells()));
  if (auto* poly = vtkPolyData::SafeDownCast(data))
  {
    for (vtkCellArray* cells :
      { poly->GetVerts(), poly->GetLines(), poly->GetPolys(), poly->GetStrips() })
      AppendObject(cells, signature);
  }
  else if (auto* grid = vtkUnstructuredGrid::SafeDownCast(data))
  {
    AppendObject(grid->GetCells(), signature);
    AppendObject(grid->GetCellTypesArray(), signature);
  }
  // The attribute containers themselves are modified by every shallow copy on the way;
  // what they hold is compared instead: each array and the active attributes.
  for (vtkDataSetAttributes* fields : { static_cast<vtkDataSetAttributes*>(data->GetPointData()),
         static_cast<vtkDataSetAttributes*>(data->GetCellData()) })
  {
    signature.push_back(std::uintptr_t(fields->GetNumberOfArrays()));
    const bool points = fields == data->GetPointData();
    vtkDataArray* normals = points ? fields->GetNormals() : nullptr;
    for (int i = 0; i < fields->GetNumberOfArrays(); ++i)
    {
      vtkAbstractArray* array = fields->GetAbstractArray(i);
      if (array == normals ||
          (points && vtkSparseArrayChanges::GetGeneration(vtkDataArray::SafeDownCast(array)) > 0))
      {
        // Values may change: listed with the points (normals) or by the array itself.
        signature.push_back(reinterpret_cast<std::uintptr_t>(array));
        continue;
      }
      AppendObject(array, signature);
    }
    for (int a = 0; a < vtkDataSetAttributes::NUM_ATTRIBUTES; ++a)
    {
      signature.push_back(reinterpret_cast<std::uintptr_t>(fields->GetAbstractAttribute(a)));
    }
  }
}
