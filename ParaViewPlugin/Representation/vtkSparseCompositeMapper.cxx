#include "vtkSparseCompositeMapper.h"

#include "vtkCompositeDataDisplayAttributes.h"
#include "vtkDataObjectTreeRange.h"
#include "vtkInformation.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkObjectFactory.h"
#include "vtkRenderer.h"
#include "vtkScalarsToColors.h"
#include "vtkSelection.h"
#include "vtkSparseSurface.h"
#include "vtkSparseSurfaceMapper.h"

vtkStandardNewMacro(vtkSparseCompositeMapper);

vtkSparseCompositeMapper::vtkSparseCompositeMapper() = default;
vtkSparseCompositeMapper::~vtkSparseCompositeMapper() = default;

vtkSparseSurfaceMapper* vtkSparseCompositeMapper::GetSurfaceMapper()
{
  return this->Surface;
}

vtkPolyData* vtkSparseCompositeMapper::SparseBlock(vtkRenderer* ren)
{
  auto* tree = vtkMultiBlockDataSet::SafeDownCast(this->GetInputDataObject(0, 0));
  if (!tree || tree->GetNumberOfBlocks() != 1 || ren->GetSelector() ||
      (this->Selection && this->Selection->GetNumberOfNodes() > 0))
  {
    return nullptr;
  }
  auto* surface = vtkSparseSurface::SafeDownCast(tree->GetBlock(0));
  vtkCompositeDataDisplayAttributes* attributes = this->GetCompositeDataDisplayAttributes();
  if (!surface ||
      (attributes &&
        (attributes->HasBlockColor(surface) || attributes->HasBlockOpacity(surface) ||
          attributes->HasBlockMaterial(surface) ||
          (attributes->HasBlockVisibility(surface) && !attributes->GetBlockVisibility(surface)))))
  {
    return nullptr;
  }
  return surface;
}

void vtkSparseCompositeMapper::Render(vtkRenderer* ren, vtkActor* act)
{
  vtkPolyData* surface = this->SparseBlock(ren);
  if (!surface)
  {
    this->Superclass::Render(ren, act);
    return;
  }
  // The colouring settings ParaView set on this mapper, copied when they change: a copy
  // modifies the surface mapper, which then rebuilds. (This mapper's own modification
  // time cannot tell: the representation hands it its input again every render.)
  std::vector<std::uintptr_t> settings = vtkSparseSurfaceMapper::Settings(this);
  if (settings != this->CopiedSettings)
  {
    this->Surface->ShallowCopy(this);
    this->Surface->SetInputArrayToProcess(0, this->GetInputArrayInformation(0));
    this->CopiedSettings = std::move(settings);
  }
  if (this->Surface->GetInput() != surface)
  {
    this->Surface->SetInputData(surface); // a new producer each call: modifies the mapper
  }
  this->Surface->Render(ren, act);
}

void vtkSparseCompositeMapper::ReleaseGraphicsResources(vtkWindow* window)
{
  this->Surface->ReleaseGraphicsResources(window);
  this->Superclass::ReleaseGraphicsResources(window);
}
