/**
 * @class   vtkLayeredFaultSceneSource
 * @brief   The paper's Figure 1: two horizons cut by a dipping fault, as triangles.
 *
 * Two horizontal horizons (footwall elevations HorizonUpper and HorizonLower) of Length
 * (x) by Width (y), cut by a planar fault that strikes along y, crosses z = Top at
 * FaultX and dips DipDegrees toward +x; the hanging wall is dropped by Throw. The fault
 * surface spans Top to Bottom. The parts are separate components (they share no
 * vertex), and an int point array "Part" says which part a vertex is on (0 upper
 * horizon, 1 lower horizon, 2 fault), so each can be painted, extracted or grasped on
 * its own. Vertices are about Spacing apart; everything is shifted by Origin.
 *
 * The geometry comes from geoshaping/scenes/layered_scene.h. Bad parameters give an error and
 * an empty output.
 */
#ifndef vtkLayeredFaultSceneSource_h
#define vtkLayeredFaultSceneSource_h

#include "GeoShapingFiltersSourcesModule.h" // For export macro
#include "vtkPolyDataAlgorithm.h"

class GEOSHAPINGFILTERSSOURCES_EXPORT vtkLayeredFaultSceneSource : public vtkPolyDataAlgorithm
{
public:
  static vtkLayeredFaultSceneSource* New();
  vtkTypeMacro(vtkLayeredFaultSceneSource, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Scene size (200 x 100), fault trace at the top (90), dip (70 degrees), fault top
  /// and bottom (0, -120), footwall horizon elevations (-30, -80), hanging-wall drop
  /// (15), target edge length (2) and a shift of everything (0 0 0).
  vtkSetMacro(Length, double);
  vtkGetMacro(Length, double);
  vtkSetMacro(Width, double);
  vtkGetMacro(Width, double);
  vtkSetMacro(FaultX, double);
  vtkGetMacro(FaultX, double);
  vtkSetMacro(DipDegrees, double);
  vtkGetMacro(DipDegrees, double);
  vtkSetMacro(Top, double);
  vtkGetMacro(Top, double);
  vtkSetMacro(Bottom, double);
  vtkGetMacro(Bottom, double);
  vtkSetMacro(HorizonUpper, double);
  vtkGetMacro(HorizonUpper, double);
  vtkSetMacro(HorizonLower, double);
  vtkGetMacro(HorizonLower, double);
  vtkSetMacro(Throw, double);
  vtkGetMacro(Throw, double);
  vtkSetMacro(Spacing, double);
  vtkGetMacro(Spacing, double);
  vtkSetVector3Macro(Origin, double);
  vtkGetVector3Macro(Origin, double);
  ///@}

protected:
  vtkLayeredFaultSceneSource();
  ~vtkLayeredFaultSceneSource() override = default;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  double Length = 200.0;
  double Width = 100.0;
  double FaultX = 90.0;
  double DipDegrees = 70.0;
  double Top = 0.0;
  double Bottom = -120.0;
  double HorizonUpper = -30.0;
  double HorizonLower = -80.0;
  double Throw = 15.0;
  double Spacing = 2.0;
  double Origin[3] = { 0.0, 0.0, 0.0 };

private:
  vtkLayeredFaultSceneSource(const vtkLayeredFaultSceneSource&) = delete;
  void operator=(const vtkLayeredFaultSceneSource&) = delete;
};

#endif
