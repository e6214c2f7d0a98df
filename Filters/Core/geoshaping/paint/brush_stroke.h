#pragma once
// A brush stroke: where its dabs go along the stylus's path.
#include <Eigen/Core>

#include <vector>

namespace geoshaping
{

// The dab centres of one stroke, spaced evenly along the path of the stylus, whatever
// the rate at which the path is sampled (an interactive frame sees one position; a fast
// hand moves many radii between two frames).
//
// The path is the polyline through the positions given to begin() and move_to(). The
// first dab sits at the first position; each next one where the arc length since the
// previous dab reaches
//
//   spacing = spacing_fraction * radius        (radius: the brush's, at that move)
//
// on the straight segment between two positions, so a move of length L after a
// remainder a (the arc length since the last dab, a < spacing) gives
// floor((a + L) / spacing) dabs at arc lengths spacing - a, 2 spacing - a, ... along it,
// and the remainder carries over to the next move. No dab is placed at the end of the
// path (the last one is within one spacing of it). With spacing_fraction s <= 1 every
// point of the path is within s/2 radius of a dab: a brush of any falloff leaves no gap
// along the stroke (with a Constant falloff, every point within
// radius * sqrt(1 - s^2 / 4) of the path is under a dab).
//
// A non-finite position, a non-positive or non-finite radius or a stroke not begun
// places no dab (a non-finite position is skipped: the path continues from the last
// finite one). At most max_dabs_per_move dabs per move (a position 10^9 radii away would
// otherwise ask for billions); the rest of that segment is skipped.
class BrushStroke
{
public:
  static constexpr double default_spacing_fraction = 0.25;
  static constexpr std::size_t max_dabs_per_move = 10000;

  explicit BrushStroke(double spacing_fraction = default_spacing_fraction);

  // Starts a stroke at `p`: appends its first dab (p) to `centres`.
  void begin(const Eigen::Vector3d& p, std::vector<Eigen::Vector3d>& centres);
  // The stylus is now at `p`: appends the dabs on the segment from the last position.
  void move_to(const Eigen::Vector3d& p, double radius, std::vector<Eigen::Vector3d>& centres);
  void end() { active_ = false; }
  bool active() const { return active_; }
  double spacing_fraction() const { return spacing_fraction_; }

private:
  double spacing_fraction_;
  bool active_ = false;
  Eigen::Vector3d last_ = Eigen::Vector3d::Zero();
  double since_dab_ = 0.0; // arc length from the last dab to last_
};

} // namespace geoshaping
