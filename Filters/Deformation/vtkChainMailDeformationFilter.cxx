#include "vtkChainMailDeformationFilterInternals.h"
#include "vtkFieldData.h"

using namespace vtkChainMailDeformationFilterDetail;

vtkStandardNewMacro(vtkChainMailDeformationFilter);

vtkChainMailDeformationFilter::vtkChainMailDeformationFilter()
  : Internals(new vtkInternals)
{
  this->ThreadedSuperstepThreshold = vtkIdType(this->Internals->Deformer.threaded_threshold());
  this->SetNumberOfInputPorts(3);
  this->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "Malleability");
}

vtkChainMailDeformationFilter::~vtkChainMailDeformationFilter() = default;

void vtkChainMailDeformationFilter::AddStretchCurvePoint(double m, double v)
{
  this->Internals->StretchCurve.points.emplace_back(m, v);
  this->Modified();
}

void vtkChainMailDeformationFilter::AddCompressionCurvePoint(double m, double v)
{
  this->Internals->CompressionCurve.points.emplace_back(m, v);
  this->Modified();
}

void vtkChainMailDeformationFilter::AddShearCurvePoint(double m, double v)
{
  this->Internals->ShearCurve.points.emplace_back(m, v);
  this->Modified();
}

void vtkChainMailDeformationFilter::RemoveAllStretchCurvePoints()
{
  this->Internals->StretchCurve.points.clear();
  this->Modified();
}

void vtkChainMailDeformationFilter::RemoveAllCompressionCurvePoints()
{
  this->Internals->CompressionCurve.points.clear();
  this->Modified();
}

void vtkChainMailDeformationFilter::RemoveAllShearCurvePoints()
{
  this->Internals->ShearCurve.points.clear();
  this->Modified();
}

void vtkChainMailDeformationFilter::SetStretchFunction(vtkPiecewiseFunction* f)
{
  SetCurvePoints(this->Internals->StretchCurve, f);
  this->Modified();
}

void vtkChainMailDeformationFilter::SetCompressionFunction(vtkPiecewiseFunction* f)
{
  SetCurvePoints(this->Internals->CompressionCurve, f);
  this->Modified();
}

void vtkChainMailDeformationFilter::SetShearFunction(vtkPiecewiseFunction* f)
{
  SetCurvePoints(this->Internals->ShearCurve, f);
  this->Modified();
}

int vtkChainMailDeformationFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPointSet* input = vtkPointSet::GetData(inputVector[0]);
  vtkPointSet* output = vtkPointSet::GetData(outputVector);
  if (!input || !output)
  {
    vtkErrorMacro("Input and output must be vtkPointSet.");
    return 0;
  }
  output->ShallowCopy(input);
  this->Statistics = FrameStatistics();
  if (this->RefuseHeldObstacles())
  {
    return 1;
  }
  vtkInternals& state = *this->Internals;
  state.Passes.begin_frame();
  // The same stages on one process and on several (docs/mpi.md): on several each is
  // collective, and the data worked on may be the input with the ghost ring.
  state.Processes = ProcessExchange();
  if (!this->SelectInput(input, output) || !this->UpdateGeometry(input))
  {
    return 1;
  }
  const vtkIdType n = input->GetNumberOfPoints();
  this->UpdateMarkers(input, false); // before the pins, which it joins
  // The obstacles are collective on several processes (every piece to every process).
  if (!state.AllAgree(n == 0 || this->UpdateMalleabilityAndPins(input)) ||
      !(state.Processes ? this->UpdateObstaclesParallel(input, *state.Processes)
                        : this->UpdateObstacles(inputVector) && this->UpdateSliding(input)))
  {
    return 1;
  }
  std::vector<int> stale; // the last frame, shown until rewritten
  const std::vector<int> touched = this->UpdateEdits(stale);
  // The committed shape changed (a commit, undo, redo, replay): the markers' triangles
  // are found again in it, and the pins follow.
  if (!touched.empty() && this->UpdateMarkers(input, true))
  {
    this->UpdateMalleabilityAndPins(input);
  }
  this->Deform(input, stale);
  if (n > 0)
  {
    this->WriteOutput(input, output, stale, touched);
    this->UpdateMarkerMisfit(output);
  }
  const bool obstacles = this->GetNumberOfInputConnections(1) > 0;
  const bool markers = this->GetNumberOfInputConnections(2) > 0 && !state.Processes;
  if (obstacles || markers)
  {
    // What the obstacles held back and how far the markers are, for the Information
    // panel (a copy of the input's field data with more arrays; the input's is left as it
    // is).
    vtkNew<vtkFieldData> fields;
    fields->ShallowCopy(input->GetFieldData());
    if (obstacles)
    {
      vtkNew<vtkIdTypeArray> blocked;
      blocked->SetName("ObstacleBlockedPoints");
      blocked->InsertNextValue(this->Statistics.NumberOfObstacleBlockedPoints);
      fields->AddArray(blocked);
    }
    if (markers)
    {
      for (const auto& figure :
        { std::make_pair("MarkerVerticalMisfitRMS", this->Statistics.MarkerVerticalMisfitRMS),
          std::make_pair("MarkerVerticalMisfitMax", this->Statistics.MarkerVerticalMisfitMax) })
      {
        vtkNew<vtkDoubleArray> value;
        value->SetName(figure.first);
        value->InsertNextValue(figure.second);
        fields->AddArray(value);
      }
      vtkNew<vtkIdTypeArray> inside;
      inside->SetName("MarkersInside");
      inside->InsertNextValue(this->Statistics.NumberOfMarkersInside);
      fields->AddArray(inside);
    }
    output->SetFieldData(fields);
  }
  return 1;
}

void vtkChainMailDeformationFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "GraspPointId: " << this->GraspPointId << "\n";
  os << indent << "GraspMode: " << this->GraspMode << "\n";
  os << indent << "GraspPosition: " << this->GraspPosition[0] << " " << this->GraspPosition[1]
     << " " << this->GraspPosition[2] << "\n";
  os << indent << "Displacement: " << this->Displacement[0] << " " << this->Displacement[1] << " "
     << this->Displacement[2] << "\n";
  os << indent << "DefaultMalleability: " << this->DefaultMalleability << "\n";
  os << indent << "CandidateQueue: "
     << geoshaping::queue_name(static_cast<geoshaping::QueueKind>(this->CandidateQueue)) << "\n";
  os << indent << "NumberOfThreads: " << this->NumberOfThreads << "\n";
  os << indent << "ThreadsEvenWhenBusy: " << (this->ThreadsEvenWhenBusy ? "On" : "Off") << "\n";
  os << indent << "ThreadedSuperstepThreshold: " << this->ThreadedSuperstepThreshold << "\n";
  os << indent << "ValidRegionFrame: "
     << geoshaping::frame_name(static_cast<geoshaping::ValidRegionFrame>(this->ValidRegionFrame))
     << "\n";
  os << indent << "StretchRange: " << this->StretchRange[0] << " " << this->StretchRange[1] << "\n";
  os << indent << "CompressionRange: " << this->CompressionRange[0] << " "
     << this->CompressionRange[1] << "\n";
  os << indent << "ShearRange: " << this->ShearRange[0] << " " << this->ShearRange[1] << "\n";
  os << indent << "TransferCurveShape: " << this->TransferCurveShape << "\n";
  os << indent << "StepThreshold: " << this->StepThreshold << "\n";
  os << indent << "OutputPointsPrecision: " << this->OutputPointsPrecision << "\n";
  os << indent << "GenerateDiagnostics: " << this->GenerateDiagnostics << "\n";
  os << indent << "RefinementIterations: " << this->RefinementIterations << "\n";
  os << indent << "RefinementTolerance: " << this->RefinementTolerance << "\n";
  os << indent << "RefinementSolver: " << this->RefinementSolver << "\n";
  os << indent << "RelaxationIterations: " << this->RelaxationIterations << "\n";
  os << indent << "ObstacleClearance: " << this->ObstacleClearance << "\n";
  os << indent << "NumberOfObstacleConnections: " << this->GetNumberOfInputConnections(1) << "\n";
  os << indent << "HonourMarkers: " << this->HonourMarkers << "\n";
  os << indent << "NumberOfMarkersConnections: " << this->GetNumberOfInputConnections(2) << "\n";
  os << indent << "NumberOfEdits: " << this->Internals->Edits.records().size() << "\n";
  os << indent << "NumberOfRebuilds: " << this->NumberOfRebuilds << "\n";
}
