// Private to the GeoShaping::FiltersDeformation module: the filter's cached core state
// and small helpers shared by its implementation files.
#ifndef vtkChainMailDeformationFilterInternals_h
#define vtkChainMailDeformationFilterInternals_h

#include "vtkChainMailDeformationFilter.h"

#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkGeoShapingAdapter.h"
#include "vtkGrowingBoundsPoints.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationStringKey.h"
#include "vtkInformationVector.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkSmartPointer.h"
#include "vtkSparseArrayChanges.h"
#include "vtkStaticPointLocator.h"

#include "geoshaping/chainmail_deformer.h"
#include "geoshaping/edit_history.h"
#include "geoshaping/link_projection.h"
#include "geoshaping/partitioned_chainmail.h"
#include "geoshaping/relaxation.h"
#include "geoshaping/sparse_normals.h"

#include <chrono>
#include <initializer_list>
#include <set>
#include <string>
#include <unordered_map>
#include <vector>

struct vtkChainMailDeformationFilter::vtkInternals
{
  geoshaping::ChainMailDeformer Deformer;
  geoshaping::Curve StretchCurve, CompressionCurve, ShearCurve; // only .points used

  // What the cached core state was built from.
  vtkPoints* GeometryPoints = nullptr;
  vtkIdType GeometrySize = -1;
  vtkMTimeType GeometryTime = 0;
  int GeometryPrecision = -1;
  bool GeometryValid = false;
  vtkDataArray* MalleabilitySource = nullptr;
  vtkMTimeType MalleabilityTime = 0;
  double MalleabilityDefault = -1.0;
  vtkDataArray* PinSource = nullptr;
  vtkMTimeType PinTime = 0;

  // The refinement pass: per-vertex link data (rebuilt when the geometry, malleability,
  // pins or curves change), the projector's scratch, and the vertices the last pass
  // moved off the ChainMail result (restored to rest next update, with the moved ones).
  geoshaping::LinkMesh Links;
  std::unique_ptr<geoshaping::LinkProjector> Projector;
  geoshaping::TransferFunction LinksTransfer;
  std::vector<geoshaping::index_t> Refined;
  bool Refining = false; // the last update wrote the projector's result
  // The relaxation pass (after the refinement, on the same link data) and the vertices it
  // moved (its region grows beyond the frame's, so they are written and restored as the
  // refined ones are).
  std::unique_ptr<geoshaping::Relaxer> Relaxer;
  std::vector<geoshaping::index_t> Relaxed; // as Refined, for the relaxer's changes
  bool Relaxing = false;                    // the last update wrote the relaxer's result

  // The link data and both passes' scratch, rebuilt when Projector was reset or the
  // transfer curves changed.
  void EnsureLinks();

  // Cache invalidation, in one place. Links: the link data of the refinement and the
  // relaxation (malleability, pins or the rest shape changed; rebuilt by EnsureLinks on
  // next use). Geometry: everything derived from the input's points and cells, the
  // links, the array sources, the locator, the passes' written vertices, the edit
  // history (replayed from EditRecords) and the once-only warnings.
  enum class Stale
  {
    Links,
    Geometry
  };
  void Invalidate(Stale level);

  // Editing: the applied edits' records (the EditHistory property), the history that
  // applies them (with the undone tail kept for redo), and the last frame's recipe.
  std::vector<std::string> EditRecords;
  bool EditsDirty = false;
  geoshaping::EditHistory History;
  geoshaping::EditRecipe FrameRecipe;
  std::string LastEdit;

  // Displacement of v from its rest position in the last frame (refined or not).
  const Eigen::Vector3d& FinalDisplacement(geoshaping::index_t v) const
  {
    return this->Relaxing   ? this->Relaxer->displacement(v)
           : this->Refining ? this->Projector->displacement(v)
                            : this->Deformer.displacement(v);
  }

  // Whether input point v moved by u lands where the output's point type holds it:
  // positions are computed in double, and a double beyond FLT_MAX cast to float is
  // undefined behaviour (in practice inf). x receives the position.
  bool Fits(geoshaping::index_t v, const Eigen::Vector3d& u, Eigen::Vector3d& x) const
  {
    this->GeometryPoints->GetPoint(v, x.data());
    x += u;
    return x.cwiseAbs().maxCoeff() <= this->OutputPoints->GetData()->GetDataTypeMax();
  }

  // The output points persist between updates; each update rewrites only the changed
  // vertices and lists them (vtkGrowingBoundsPoints::PointsChanged), so bounds and a
  // consumer that saw the previous update (the GeoShaping Surface representation)
  // follow in O(changed).
  vtkSmartPointer<vtkGrowingBoundsPoints> OutputPoints;
  vtkNew<vtkIdTypeArray> Changed;
  // Lighting follows the shape: when the input is polygons with point normals, the
  // output carries its own copy, recomputed for the vertices each update's changes
  // affect (the changed ones and those sharing a face with them), which are listed
  // with the changed points.
  geoshaping::SparseNormals Normals;
  vtkSmartPointer<vtkDataArray> OutputNormals;
  std::vector<geoshaping::index_t> Affected;
  vtkSmartPointer<vtkStaticPointLocator> Locator;
  // The distributed path (more than one process): drives Deformer over this piece.
  std::unique_ptr<geoshaping::PartitionedChainMail> Partition;
  // Its point GlobalIds when the input has none (geoshaping::coordinate_ids), shown in
  // the output; null when the input has its own.
  vtkSmartPointer<vtkIdTypeArray> GeneratedIds;
  // Point GlobalIds of the input, when it has them: global id -> point id.
  std::unordered_map<std::int64_t, geoshaping::index_t> LocalOfGlobal;
  std::set<std::string> Warned; // WarnOnce's messages, cleared when the geometry changes
};

namespace vtkChainMailDeformationFilterDetail
{
inline void SetCurvePoints(geoshaping::Curve& curve, vtkPiecewiseFunction* f)
{
  curve.points.clear();
  if (!f)
    return;
  double node[4];
  for (int i = 0; i < f->GetSize(); ++i)
  {
    f->GetNodeValue(i, node);
    curve.points.emplace_back(node[0], node[1]);
  }
}

using IdList = std::vector<geoshaping::index_t>;
using IdLists = std::initializer_list<const IdList*>;

inline bool SameCurve(const geoshaping::Curve& a, const geoshaping::Curve& b)
{
  return a.at_rigid == b.at_rigid && a.at_soft == b.at_soft && a.shape == b.shape &&
         a.threshold == b.threshold && a.points == b.points;
}

inline bool SameTransfer(
  const geoshaping::TransferFunction& a, const geoshaping::TransferFunction& b)
{
  return SameCurve(a.stretch, b.stretch) && SameCurve(a.compression, b.compression) &&
         SameCurve(a.shear, b.shear) && a.exact_rigid_at_zero == b.exact_rigid_at_zero;
}

inline geoshaping::EditRecipe Recipe(vtkChainMailDeformationFilter* self, vtkIdType grasp)
{
  geoshaping::EditRecipe r;
  r.grasp = geoshaping::index_t(grasp);
  r.displacement = Eigen::Vector3d(self->GetDisplacement());
  r.queue = self->GetCandidateQueue();
  self->GetStretchRange(r.stretch);
  self->GetCompressionRange(r.compression);
  self->GetShearRange(r.shear);
  r.curve_shape = self->GetTransferCurveShape();
  r.step_threshold = self->GetStepThreshold();
  r.refinement_iterations = self->GetRefinementIterations();
  return r;
}

inline geoshaping::Curve MakeCurve(
  const double range[2], int shape, double threshold, const geoshaping::Curve& userPoints)
{
  geoshaping::Curve c;
  c.at_rigid = range[0];
  c.at_soft = range[1];
  c.threshold = threshold;
  c.shape = shape == vtkChainMailDeformationFilter::SMOOTH ? geoshaping::CurveShape::smooth
            : shape == vtkChainMailDeformationFilter::STEP ? geoshaping::CurveShape::step
                                                           : geoshaping::CurveShape::linear;
  if (!userPoints.points.empty())
  {
    c.shape = geoshaping::CurveShape::piecewise;
    c.points = userPoints.points;
  }
  return c;
}

// The transfer function of the filter's properties and the user's curve points.
inline geoshaping::TransferFunction Transfer(vtkChainMailDeformationFilter* self,
  const geoshaping::Curve& stretch, const geoshaping::Curve& compression,
  const geoshaping::Curve& shear)
{
  const int shape = self->GetTransferCurveShape();
  const double threshold = self->GetStepThreshold();
  geoshaping::TransferFunction tf;
  tf.stretch = MakeCurve(self->GetStretchRange(), shape, threshold, stretch);
  tf.compression = MakeCurve(self->GetCompressionRange(), shape, threshold, compression);
  tf.shear = MakeCurve(self->GetShearRange(), shape, threshold, shear);
  tf.exact_rigid_at_zero = self->GetExactRigidAtZero();
  return tf;
}
} // namespace vtkChainMailDeformationFilterDetail

inline void vtkChainMailDeformationFilter::vtkInternals::Invalidate(Stale level)
{
  this->Projector.reset();
  if (level == Stale::Links)
    return;
  this->GeometryValid = false;
  this->MalleabilitySource = nullptr;
  this->PinSource = nullptr;
  this->MalleabilityDefault = -1.0;
  this->Locator = nullptr;
  this->Refined.clear();
  this->Relaxed.clear();
  this->Refining = false;
  this->Relaxing = false;
  this->History.clear();
  this->EditsDirty = true;
  this->Warned.clear();
}

inline void vtkChainMailDeformationFilter::vtkInternals::EnsureLinks()
{
  const geoshaping::TransferFunction& tf = this->Deformer.transfer_function();
  if (!this->Projector ||
      !vtkChainMailDeformationFilterDetail::SameTransfer(tf, this->LinksTransfer))
  {
    this->Links = geoshaping::link_mesh(this->Deformer);
    this->LinksTransfer = tf;
    this->Projector = std::make_unique<geoshaping::LinkProjector>(this->Links);
    this->Relaxer = std::make_unique<geoshaping::Relaxer>(this->Links);
  }
  this->Links.frame = this->Deformer.valid_region_frame(); // the relaxation keeps these regions
}

#endif
