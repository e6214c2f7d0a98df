#pragma once
// What ParaView users expect after DEM Surface > Apply on a raster (issue 40): the render
// view it is shown in leaves the 2D mode ParaView chose for the flat raster and becomes a
// 3D view, the surface coloured by its Elevation. Done once per DEM Surface, the first time
// it is shown in a render view; never while a state is loaded or an undo/redo replays
// (the state's or the user's view stays). The first DEM Surface shown in a view also
// gets an oblique camera framed on it (from the south, looking north 35 degrees down,
// Reset Camera); later ones leave that view's camera as the user set it. The dock makes
// one for the session.
#include <QObject>

class pqDataRepresentation;
class pqPipelineSource;

class pqDEMSurfaceBehavior : public QObject
{
  Q_OBJECT

public:
  explicit pqDEMSurfaceBehavior(QObject* parent = nullptr);

private:
  void onSourceAdded(pqPipelineSource* source);
  void onRepresentationAdded(pqPipelineSource* source, pqDataRepresentation* repr, int port);
};
