#pragma once
/**
 * @class vtkSMGeoShapingSourceProxy
 * @brief The client-side proxy of GeoShaping's filters: says when a list property holds
 *        an incomplete last entry.
 *
 * A repeatable property sent N values per command (Dabs: 6, PointDabs: 3, the transfer
 * curves: 2) drops an incomplete tail silently on its way to the filter. This proxy
 * watches every property it pushes (vtkCommand::UpdatePropertyEvent) and warns when the
 * number of values is not a whole number of entries, naming the property and what is
 * ignored; the panel's table keeps one column per value of an entry. ParaView
 * instantiates it from the XML element `<GeoShapingSourceProxy>`.
 */
#include "GeoShapingServerManagerModule.h"
#include "vtkSMSourceProxy.h"

class GEOSHAPINGSERVERMANAGER_EXPORT vtkSMGeoShapingSourceProxy : public vtkSMSourceProxy
{
public:
  static vtkSMGeoShapingSourceProxy* New();
  vtkTypeMacro(vtkSMGeoShapingSourceProxy, vtkSMSourceProxy);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * The number of values of property `name` that do not make a whole entry (0 when it
   * is not a repeatable list of entries of several values).
   */
  int GetIncompleteTail(const char* name);

protected:
  vtkSMGeoShapingSourceProxy();
  ~vtkSMGeoShapingSourceProxy() override;

private:
  vtkSMGeoShapingSourceProxy(const vtkSMGeoShapingSourceProxy&) = delete;
  void operator=(const vtkSMGeoShapingSourceProxy&) = delete;

  void CheckEntries(vtkObject*, unsigned long, void* name);
};
