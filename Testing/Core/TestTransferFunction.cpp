#include "geoshaping/deform/transfer_function.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace geoshaping;

TEST(TransferFunction, DefaultsAreLinearBetweenDesignValues)
{
  const TransferFunction tf;
  const ChainMailParams soft = tf(1.0);
  EXPECT_DOUBLE_EQ(soft.stretch, 2.0);
  EXPECT_DOUBLE_EQ(soft.compression, 0.5);
  EXPECT_DOUBLE_EQ(soft.shear, 0.5);
  const ChainMailParams half = tf(0.5);
  EXPECT_DOUBLE_EQ(half.stretch, 1.5);
  EXPECT_DOUBLE_EQ(half.compression, 0.75);
  EXPECT_DOUBLE_EQ(half.shear, 0.25);
}

TEST(TransferFunction, ZeroMalleabilityIsExactlyRigidWhateverTheCurve)
{
  TransferFunction tf;
  tf.stretch = { 3.0, 5.0 };
  tf.shear.shape = CurveShape::piecewise;
  tf.shear.points = { { 0.0, 0.7 }, { 1.0, 0.9 } };
  const ChainMailParams p = tf(0.0);
  EXPECT_EQ(p.stretch, 1.0);
  EXPECT_EQ(p.compression, 1.0);
  EXPECT_EQ(p.shear, 0.0);
  // Just above 0 the curves apply.
  EXPECT_NEAR(tf(1e-12).stretch, 3.0, 1e-9);
  EXPECT_NEAR(tf(1e-12).shear, 0.7, 1e-9);
}

TEST(TransferFunction, CurvesHitTheirEndsAndShapes)
{
  Curve c{ 1.0, 3.0, CurveShape::smooth };
  EXPECT_DOUBLE_EQ(c(0.0), 1.0);
  EXPECT_DOUBLE_EQ(c(1.0), 3.0);
  EXPECT_DOUBLE_EQ(c(0.5), 2.0);
  EXPECT_DOUBLE_EQ(c(0.25), 1.0 + 2.0 * 0.15625);
  c.shape = CurveShape::step;
  c.threshold = 0.4;
  EXPECT_EQ(c(0.39), 1.0);
  EXPECT_EQ(c(0.4), 3.0);
  c.shape = CurveShape::piecewise;
  c.points = { { 0.2, 1.0 }, { 0.6, 2.0 }, { 1.0, 10.0 } };
  EXPECT_DOUBLE_EQ(c(0.0), 1.0);
  EXPECT_DOUBLE_EQ(c(0.4), 1.5);
  EXPECT_DOUBLE_EQ(c(0.8), 6.0);
  EXPECT_DOUBLE_EQ(c(1.0), 10.0);
}

TEST(TransferFunction, ParametersAreClampedToTheirDomains)
{
  TransferFunction tf;
  tf.stretch = { 0.5, 0.5 };
  tf.compression = { 2.0, -1.0 };
  tf.shear = { -1.0, -1.0 };
  const ChainMailParams p = tf(0.7);
  EXPECT_EQ(p.stretch, 1.0);
  EXPECT_EQ(p.compression, 0.0);
  EXPECT_EQ(p.shear, 0.0);
  EXPECT_EQ(tf(7.0).stretch, tf(1.0).stretch); // malleability clamped to [0, 1]
}

TEST(TransferFunction, ValidateRejectsNonFiniteAndUnsortedCurves)
{
  TransferFunction tf;
  EXPECT_STREQ(tf.validate(), "");
  tf.shear.at_soft = std::nan("");
  EXPECT_STRNE(tf.validate(), "");
  tf.shear.at_soft = 0.5;
  tf.stretch.points = { { 0.5, 1.0 }, { 0.2, 2.0 } };
  EXPECT_STRNE(tf.validate(), "");
}

TEST(TransferFunction, AStoredMalleabilityIsReadOneWayNaNRigidTheRestClamped)
{
  using geoshaping::clean_malleability;
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(clean_malleability(std::numeric_limits<double>::quiet_NaN()), 0.0);
  EXPECT_EQ(clean_malleability(-inf), 0.0);
  EXPECT_EQ(clean_malleability(inf), 1.0);
  EXPECT_EQ(clean_malleability(-0.2), 0.0);
  EXPECT_EQ(clean_malleability(1.5), 1.0);
  EXPECT_EQ(clean_malleability(0.3), 0.3);
  EXPECT_EQ(clean_malleability(0.0), 0.0);
  EXPECT_EQ(clean_malleability(1.0), 1.0);
}
