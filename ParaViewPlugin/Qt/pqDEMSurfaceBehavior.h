#pragma once
// What ParaView users expect after DEM Surface > Apply on a raster (issue 40): the render
// view it is shown in leaves the 2D mode ParaView chose for the flat raster and becomes a
// 3D view framed on the surface (Reset Camera), the surface coloured by its Elevation.
// Done once, the first time a DEM Surface is shown in a render view; never while a state
// is loaded or an undo/redo replays (the state's or the user's view stays). The dock
// makes one for the session.
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
