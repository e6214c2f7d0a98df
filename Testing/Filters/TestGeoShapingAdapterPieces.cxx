// The distributed set-up of a piece (vtkGeoShapingAdapter: PieceArraysProblem,
// AgreeOnPieces, OwnedPoints, IdentifyPiece), on pieces run by threads (InProcessExchange,
// the tests' stand-in for MPI), against the one-piece numbering by coordinates and
// ownership worked by hand.
#include "vtkGeoShapingAdapter.h"

#include "vtkDataSetAttributes.h"
#include "vtkIdTypeArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"

#include "geoshaping/parallel/coordinate_ids.h"
#include "geoshaping/parallel/in_process_exchange.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

namespace
{
// Points on the x axis at `xs`, the ones in `ghosts` marked as owned elsewhere.
vtkSmartPointer<vtkPolyData> Piece(
  const std::vector<double>& xs, const std::vector<vtkIdType>& ghosts = {})
{
  auto piece = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  for (double x : xs)
    points->InsertNextPoint(x, 0.5 * x, 0.0);
  piece->SetPoints(points);
  if (!ghosts.empty())
  {
    piece->AllocatePointGhostArray();
    for (vtkIdType g : ghosts)
      piece->GetPointGhostArray()->SetValue(g, vtkDataSetAttributes::DUPLICATEPOINT);
  }
  return piece;
}

std::vector<double> Coordinates(vtkPolyData* piece)
{
  std::vector<double> xyz;
  vtkIdType firstBad;
  vtkGeoShapingAdapter::PointsAsDouble(piece->GetPoints(), xyz, firstBad);
  return xyz;
}
} // namespace

TEST(AdapterPieces, OwnedPointsAreThoseVtkGhostTypeDoesNotMarkAsDuplicates)
{
  EXPECT_EQ(vtkGeoShapingAdapter::OwnedPoints(Piece({ 0, 1, 2, 3 }, { 2 })),
    (std::vector<std::uint8_t>{ 1, 1, 0, 1 }));
  EXPECT_EQ(
    vtkGeoShapingAdapter::OwnedPoints(Piece({ 0, 1, 2 })), (std::vector<std::uint8_t>{ 1, 1, 1 }));
}

TEST(AdapterPieces, ArraysThatAreNotOneValuePerPointAreNamed)
{
  EXPECT_EQ(vtkGeoShapingAdapter::PieceArraysProblem(Piece({ 0, 1, 2 }, { 1 })), "");
  auto ids = Piece({ 0, 1, 2 });
  vtkNew<vtkIdTypeArray> gids;
  gids->SetName("GlobalIds");
  gids->SetNumberOfTuples(2);
  ids->GetPointData()->SetGlobalIds(gids);
  EXPECT_NE(vtkGeoShapingAdapter::PieceArraysProblem(ids).find("GlobalIds"), std::string::npos);
  auto ghosts = Piece({ 0, 1, 2 }, { 1 });
  ghosts->GetPointGhostArray()->SetNumberOfTuples(2);
  EXPECT_NE(
    vtkGeoShapingAdapter::PieceArraysProblem(ghosts).find("vtkGhostType"), std::string::npos);
}

TEST(AdapterPieces, TwoPiecesAreNumberedByCoordinatesAsTheWholeMeshIs)
{
  // The whole mesh: five points; piece 1 holds a ghost copy of the seam point x = 2.
  auto whole = Piece({ 4, 0, 3, 1, 2 });
  const std::vector<double> all = Coordinates(whole);
  const std::vector<std::int64_t> wholeIds = geoshaping::coordinate_ids(all.data(), 5);
  ASSERT_EQ(wholeIds, (std::vector<std::int64_t>{ 4, 0, 3, 1, 2 }));
  std::vector<std::int64_t> ids[2];
  std::vector<std::uint8_t> owned[2];
  bool ok[2] = { false, false };
  geoshaping::run_in_pieces(2,
    [&](int p, geoshaping::Exchange& ex)
    {
      auto piece = p == 0 ? Piece({ 1, 0, 2 }) : Piece({ 2, 4, 3 }, { 0 });
      const std::vector<double> xyz = Coordinates(piece);
      std::string refusal;
      ok[p] = vtkGeoShapingAdapter::IdentifyPiece(
        piece, xyz.data(), false, ex, ids[p], owned[p], refusal);
    });
  EXPECT_TRUE(ok[0] && ok[1]);
  EXPECT_EQ(ids[0], (std::vector<std::int64_t>{ 1, 0, 2 }));
  EXPECT_EQ(ids[1], (std::vector<std::int64_t>{ 2, 4, 3 }));
  EXPECT_EQ(owned[0], (std::vector<std::uint8_t>{ 1, 1, 1 }));
  EXPECT_EQ(owned[1], (std::vector<std::uint8_t>{ 0, 1, 1 }));
}

TEST(AdapterPieces, GlobalIdsNameThePiecesWhenEveryPieceHasThem)
{
  auto piece = Piece({ 5, 6, 7 }, { 2 });
  vtkNew<vtkIdTypeArray> gids;
  gids->SetName("GlobalIds");
  for (vtkIdType id : { 40, 10, 30 })
    gids->InsertNextValue(id);
  piece->GetPointData()->SetGlobalIds(gids);
  std::vector<std::int64_t> ids;
  std::vector<std::uint8_t> owned;
  std::string refusal;
  geoshaping::run_in_pieces(1,
    [&](int, geoshaping::Exchange& ex)
    {
      const std::vector<double> xyz = Coordinates(piece);
      EXPECT_TRUE(
        vtkGeoShapingAdapter::IdentifyPiece(piece, xyz.data(), true, ex, ids, owned, refusal));
    });
  EXPECT_EQ(ids, (std::vector<std::int64_t>{ 40, 10, 30 }));
  EXPECT_EQ(owned, (std::vector<std::uint8_t>{ 1, 1, 0 }));
  EXPECT_EQ(refusal, "");
}

TEST(AdapterPieces, SplitNodesOnOnePieceAreRefusedOnEveryPiece)
{
  std::string refusal[2];
  bool ok[2] = { true, true };
  geoshaping::run_in_pieces(2,
    [&](int p, geoshaping::Exchange& ex)
    {
      // Piece 0 holds two vertices at x = 1 (a fault's two sides).
      auto piece = p == 0 ? Piece({ 0, 1, 1 }) : Piece({ 2, 3 });
      const std::vector<double> xyz = Coordinates(piece);
      std::vector<std::int64_t> ids;
      std::vector<std::uint8_t> owned;
      ok[p] =
        vtkGeoShapingAdapter::IdentifyPiece(piece, xyz.data(), false, ex, ids, owned, refusal[p]);
      EXPECT_TRUE(ok[p] || ids.empty());
    });
  EXPECT_FALSE(ok[0] || ok[1]);
  EXPECT_NE(refusal[0].find("GlobalIds"), std::string::npos) << refusal[0];
  EXPECT_EQ(refusal[0], refusal[1]);
}

TEST(AdapterPieces, PiecesAgreeOnTheirChecksAndOnHavingGlobalIds)
{
  // One process: its own values.
  const auto one = vtkGeoShapingAdapter::AgreeOnPieces(nullptr, true, true, 3, false);
  EXPECT_TRUE(one.Ok && one.AnyChanged && !one.WithIds && one.Refusal.empty());
  vtkGeoShapingAdapter::PieceAgreement mixed[2], refused[2];
  geoshaping::run_in_pieces(2,
    [&](int p, geoshaping::Exchange& ex)
    {
      // Ids on piece 0 only; an empty piece's ids do not count.
      mixed[p] = vtkGeoShapingAdapter::AgreeOnPieces(&ex, true, p == 1, 3, p == 0);
      refused[p] = vtkGeoShapingAdapter::AgreeOnPieces(&ex, p == 0, false, p == 0 ? 3 : 0, true);
    });
  for (int p = 0; p < 2; ++p)
  {
    EXPECT_FALSE(mixed[p].Ok);
    EXPECT_TRUE(mixed[p].AnyChanged);
    EXPECT_EQ(mixed[p].Refusal, "Point GlobalIds on some processes and not on others");
    EXPECT_FALSE(refused[p].Ok);
    EXPECT_TRUE(refused[p].WithIds);
  }
  EXPECT_EQ(refused[0].Refusal, "Another process refused its piece");
  EXPECT_EQ(refused[1].Refusal, ""); // it reports its own problem
}
