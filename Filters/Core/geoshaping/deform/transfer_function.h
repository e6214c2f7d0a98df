#pragma once
// Malleability (0 rigid ... 1 soft) -> ChainMail parameters (stretch, compression, shear).
#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace geoshaping
{

// How every reader of a stored malleability value takes it (the deformation contract,
// docs/design.md): NaN counts as rigid (0) and anything else is clamped to [0, 1] (+inf is soft,
// -inf rigid). The one copy of the rule: the deformer, the error metrics, the paint filter and the
// interactor's brush value all call it; callers that warn count the values it changed.
inline double clean_malleability(double m)
{
  return std::isnan(m) ? 0.0 : std::clamp(m, 0.0, 1.0);
}

// The three Generalized ChainMail parameters of one vertex:
// stretch t >= 1, compression k in [0, 1], shear h >= 0.
struct ChainMailParams
{
  double stretch = 1.0;
  double compression = 1.0;
  double shear = 0.0;
};

// Shape of the curve between the value at m = 0 and the value at m = 1.
enum class CurveShape
{
  linear,   // v0 + (v1 - v0) m
  smooth,   // v0 + (v1 - v0) s(m), s = 3m^2 - 2m^3 (smoothstep)
  step,     // v0 below the threshold, v1 at or above it
  piecewise // linear through user points (m_i, v_i), sorted by m, clamped at the ends
};

struct Curve
{
  double at_rigid = 0.0; // value at m = 0
  double at_soft = 1.0;  // value at m = 1
  CurveShape shape = CurveShape::linear;
  double threshold = 0.5;                        // for step
  std::vector<std::pair<double, double>> points; // for piecewise

  double operator()(double m) const;
};

// Equal definitions (so equal values at every m): what a cache built from a curve checks.
inline bool operator==(const Curve& a, const Curve& b)
{
  return a.at_rigid == b.at_rigid && a.at_soft == b.at_soft && a.shape == b.shape &&
         a.threshold == b.threshold && a.points == b.points;
}

// Defaults (the deformation contract, docs/design.md): stretch 1 -> 2, compression 1 -> 0.5, shear
// 0 -> 0.5. Malleability 0 yields exactly (1, 1, 0) whatever the curves: m == 0 means rigid, the
// paper's black "frozen" paint.
class TransferFunction
{
public:
  TransferFunction();

  Curve stretch{ 1.0, 2.0 };
  Curve compression{ 1.0, 0.5 };
  Curve shear{ 0.0, 0.5 };

  // `m` is clamped to [0, 1]. Results are clamped to the valid parameter domain
  // (stretch >= 1, compression in [0, 1], shear >= 0) so no curve can produce an
  // inverted valid region.
  ChainMailParams operator()(double m) const;

  // A short reason when a curve is unusable (non-finite values, unsorted points), else "".
  const char* validate() const;
};

inline bool operator==(const TransferFunction& a, const TransferFunction& b)
{
  return a.stretch == b.stretch && a.compression == b.compression && a.shear == b.shear;
}

} // namespace geoshaping
