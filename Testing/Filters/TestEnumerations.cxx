// The enumerations are one list each: the VTK filters' enums are the core's, value for
// value (static_assert), and the server-manager XML's EnumerationDomain entries, which
// ParaView sends to the filters by value, name what the core calls them
// (queue_name, falloff_name, distance_mode_name) or the filters' enum (grasp modes,
// curve shapes, mesh types).
#include "vtkChainMailDeformationFilter.h"
#include "vtkFaultStepHorizonSource.h"
#include "vtkMalleabilityPaintFilter.h"

#include "geoshaping/deform/candidate_queue.h"
#include "geoshaping/deform/transfer_function.h"
#include "geoshaping/paint/brush.h"
#include "geoshaping/passes/link_projection.h"

#include <vtkNew.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLDataParser.h>

#include <gtest/gtest.h>

#include <map>
#include <string>

namespace gs = geoshaping;
using Chain = vtkChainMailDeformationFilter;
using Paint = vtkMalleabilityPaintFilter;

static_assert(Chain::FIFO == int(gs::QueueKind::fifo));
static_assert(Chain::PRIORITY == int(gs::QueueKind::priority));
static_assert(Chain::FIFO_PRIORITY == int(gs::QueueKind::fifo_priority));
static_assert(Chain::MAX_VIOLATION == int(gs::QueueKind::max_violation));
static_assert(Chain::REFINEMENT_ADMM == int(gs::ProjectionSolver::admm));
static_assert(Chain::REFINEMENT_DYKSTRA == int(gs::ProjectionSolver::dykstra));
static_assert(Chain::REFINEMENT_ENVELOPE == int(gs::ProjectionSolver::envelope));
static_assert(Chain::LINEAR == int(gs::CurveShape::linear));
static_assert(Chain::SMOOTH == int(gs::CurveShape::smooth));
static_assert(Chain::STEP == int(gs::CurveShape::step));
static_assert(Paint::CONSTANT == int(gs::Falloff::constant));
static_assert(Paint::LINEAR == int(gs::Falloff::linear));
static_assert(Paint::SMOOTH == int(gs::Falloff::smooth));
static_assert(Paint::GAUSSIAN == int(gs::Falloff::gaussian));
static_assert(Paint::EUCLIDEAN == int(gs::DistanceMode::euclidean));
static_assert(Paint::GEODESIC == int(gs::DistanceMode::geodesic));

namespace
{
// value -> text of the EnumerationDomain of property `name` in the proxy XML `file`.
std::map<int, std::string> entries(const char* file, const char* name)
{
  vtkNew<vtkXMLDataParser> parser;
  parser->SetFileName((std::string(GEOSHAPING_SERVER_MANAGER_DIR "/") + file).c_str());
  EXPECT_EQ(parser->Parse(), 1) << file;
  vtkXMLDataElement* root = parser->GetRootElement();
  vtkXMLDataElement* property = root ? root->LookupElementWithName("ProxyGroup") : nullptr;
  std::map<int, std::string> out;
  vtkXMLDataElement* proxy = property ? property->GetNestedElement(0) : nullptr;
  for (int i = 0; proxy && i < proxy->GetNumberOfNestedElements(); ++i)
  {
    vtkXMLDataElement* p = proxy->GetNestedElement(i);
    const char* pname = p->GetAttribute("name");
    if (!pname || name != std::string(pname))
      continue;
    vtkXMLDataElement* domain = p->FindNestedElementWithName("EnumerationDomain");
    for (int k = 0; domain && k < domain->GetNumberOfNestedElements(); ++k)
    {
      vtkXMLDataElement* entry = domain->GetNestedElement(k);
      int value = -1;
      entry->GetScalarAttribute("value", value);
      out[value] = entry->GetAttribute("text");
    }
  }
  EXPECT_FALSE(out.empty()) << name << " in " << file;
  return out;
}
}

TEST(Enumerations, XmlEntriesMatchTheCore)
{
  const std::map<int, std::string> queues = entries("ChainMailDeformation.xml", "CandidateQueue");
  ASSERT_EQ(queues.size(), 4u);
  for (const auto& [value, text] : queues)
    EXPECT_EQ(text, gs::queue_name(gs::QueueKind(value))) << value;
  const std::map<int, std::string> solvers =
    entries("ChainMailDeformation.xml", "RefinementSolver");
  ASSERT_EQ(solvers.size(), 3u);
  for (const auto& [value, text] : solvers)
    EXPECT_EQ(text, gs::solver_name(gs::ProjectionSolver(value))) << value;

  const std::map<int, std::string> falloffs = entries("MalleabilityPaint.xml", "Falloff");
  ASSERT_EQ(falloffs.size(), 4u);
  for (const auto& [value, text] : falloffs)
    EXPECT_EQ(text, gs::falloff_name(gs::Falloff(value))) << value;

  const std::map<int, std::string> modes = entries("MalleabilityPaint.xml", "DistanceMode");
  ASSERT_EQ(modes.size(), 2u);
  for (const auto& [value, text] : modes)
    EXPECT_EQ(text, gs::distance_mode_name(gs::DistanceMode(value))) << value;
}

TEST(Enumerations, XmlEntriesMatchTheFilters)
{
  EXPECT_EQ(entries("ChainMailDeformation.xml", "TransferCurveShape"),
    (std::map<int, std::string>{
      { Chain::LINEAR, "Linear" }, { Chain::SMOOTH, "Smooth" }, { Chain::STEP, "Step" } }));
  EXPECT_EQ(entries("ChainMailDeformation.xml", "GraspMode"),
    (std::map<int, std::string>{ { Chain::GRASP_POINT_ID, "Point Id" },
      { Chain::GRASP_NEAREST_TO_POSITION, "Nearest To Position" } }));
  EXPECT_EQ(entries("FaultStepHorizon.xml", "OutputMeshType"),
    (std::map<int, std::string>{ { vtkFaultStepHorizonSource::SURFACE, "Surface" },
      { vtkFaultStepHorizonSource::SLAB, "Slab" } }));
}
