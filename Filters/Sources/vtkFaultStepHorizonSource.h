/**
 * @class   vtkFaultStepHorizonSource
 * @brief   The sample scene of the paper's Figure 5: a horizon with a near-vertical
 *          fault step, as triangles or as a tetrahedral slab.
 *
 * A horizontal surface of Length (x) by Width (y) whose upper half (z = Throw) drops to
 * z = 0 through a smooth step StepRun wide centred at StepPosition x Length; vertices
 * are about Spacing apart along the surface, so the step gets rows in proportion to its
 * height. OutputMeshType SURFACE gives vtkPolyData triangles; SLAB gives a
 * vtkUnstructuredGrid of tetrahedra filling Thickness below the horizon in Layers
 * layers (its top layer of points is the surface's). Everything is shifted by Origin,
 * e.g. to UTM-sized coordinates.
 *
 * With PaintFigure5C on, a float point array "Malleability" holds the default painting
 * of Figure 5C: red (0.4) everywhere, a white (1) band BorderWidth wide on both sides
 * of the step, the step black (0). It is painted by vtkMalleabilityPaintFilter from the
 * dab list of geoshaping::fault_step_painting, so the same dabs given to the
 * MalleabilityPaint filter reproduce it exactly.
 *
 * The geometry comes from geoshaping/scenes/sample_scenes.h (VTK-free, shared with the unit
 * tests and benchmarks). Bad parameters give an error and an empty output.
 */
#ifndef vtkFaultStepHorizonSource_h
#define vtkFaultStepHorizonSource_h

#include "GeoShapingFiltersSourcesModule.h" // For export macro
#include "vtkPointSetAlgorithm.h"

class GEOSHAPINGFILTERSSOURCES_EXPORT vtkFaultStepHorizonSource : public vtkPointSetAlgorithm
{
public:
  static vtkFaultStepHorizonSource* New();
  vtkTypeMacro(vtkFaultStepHorizonSource, vtkPointSetAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum MeshTypes
  {
    SURFACE = 0,
    SLAB = 1
  };

  ///@{
  /// SURFACE (vtkPolyData triangles, default) or SLAB (vtkUnstructuredGrid tetrahedra).
  vtkSetClampMacro(OutputMeshType, int, SURFACE, SLAB);
  vtkGetMacro(OutputMeshType, int);
  ///@}

  ///@{
  /// Size of the horizon: x extent (100), y extent (60), height of the step (20),
  /// horizontal extent of the step (6: near-vertical), centre of the step as a fraction
  /// of Length (0.5) and the target edge length (1).
  vtkSetMacro(Length, double);
  vtkGetMacro(Length, double);
  vtkSetMacro(Width, double);
  vtkGetMacro(Width, double);
  vtkSetMacro(Throw, double);
  vtkGetMacro(Throw, double);
  vtkSetMacro(StepRun, double);
  vtkGetMacro(StepRun, double);
  vtkSetMacro(StepPosition, double);
  vtkGetMacro(StepPosition, double);
  vtkSetMacro(Spacing, double);
  vtkGetMacro(Spacing, double);
  ///@}

  ///@{
  /// SLAB only: thickness below the horizon (6) and number of cell layers (3).
  vtkSetMacro(Thickness, double);
  vtkGetMacro(Thickness, double);
  vtkSetMacro(Layers, int);
  vtkGetMacro(Layers, int);
  ///@}

  ///@{
  /// Offset added to every point. Default (0, 0, 0).
  vtkSetVector3Macro(Origin, double);
  vtkGetVector3Macro(Origin, double);
  ///@}

  ///@{
  /// Add the "Malleability" array of Figure 5C (off by default) with a white band of
  /// BorderWidth (6) on both sides of the black step.
  vtkSetMacro(PaintFigure5C, bool);
  vtkGetMacro(PaintFigure5C, bool);
  vtkBooleanMacro(PaintFigure5C, bool);
  vtkSetMacro(BorderWidth, double);
  vtkGetMacro(BorderWidth, double);
  ///@}

protected:
  vtkFaultStepHorizonSource();
  ~vtkFaultStepHorizonSource() override = default;

  int FillOutputPortInformation(int port, vtkInformation* info) override;
  int RequestDataObject(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int OutputMeshType = SURFACE;
  // Defaults from geoshaping::FaultStepParams, set in the constructor.
  double Length;
  double Width;
  double Throw;
  double StepRun;
  double StepPosition;
  double Spacing;
  double Thickness;
  int Layers;
  double Origin[3] = { 0.0, 0.0, 0.0 };
  bool PaintFigure5C = false;
  double BorderWidth = 6.0;

private:
  vtkFaultStepHorizonSource(const vtkFaultStepHorizonSource&) = delete;
  void operator=(const vtkFaultStepHorizonSource&) = delete;
};

#endif
