#pragma once
// @brief The contact proxy (god-object, Zilles & Salisbury 1995; the finger proxy of
// Ruspini et al. 1997 with a zero radius; CHAI3D's cAlgorithmFingerProxy): a point that
// follows the stylus but never crosses a triangle of the contact patch. The contact force
// is a spring from the stylus to it (force_model.h), so a hand that pushes harder than the
// device can resist feels a saturated force and is never popped through; and the spring
// changes by no more than the stylus moves in a tick, convex crests included (update()).
//
// Contract: no allocation, no lock, O(passes x triangles) per call; the patch is a
// triangle soup (3 vertices a triangle), two-sided: a triangle holds the proxy on the side
// the proxy is on, whatever its winding. Degenerate and non-finite triangles are ignored.
#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace geoshaping::haptics
{

// First crossing of the segment o -> o + d with a triangle of the soup (Moller-Trumbore,
// both windings, edges included with a relative slack of 1e-9 so a segment through a
// shared edge hits one of its two triangles): the smallest t in [0, 1] with
// o + t d = a + u (b - a) + v (c - a), u, v >= 0, u + v <= 1. `normal` is the unit normal
// of that triangle turned against d (toward the side o is on).
struct SegmentHit
{
  bool hit = false;
  double t = 1.0;
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
};
SegmentHit first_hit(
  const Eigen::Vector3d& o, const Eigen::Vector3d& d, const std::vector<Eigen::Vector3d>& soup);

class ContactProxy
{
public:
  static constexpr int max_planes = 3;
  static constexpr int max_passes = 12;

  // Forgets everything: the next update() starts the proxy at the stylus (a stale or new
  // scene: nothing is known of the side the stylus was on).
  void reset();
  // Starts the proxy at `p` (its side of every triangle is the side p is on).
  void place(const Eigen::Vector3d& p);
  bool placed() const { return this->placed_; }

  // A new patch (another `sequence`): the proxy moves with the surface it was nearest to,
  // within `reach`, so it stays on its side when the surface moves or is re-triangulated.
  // With f the proxy's foot on the previous patch (nearest point, remembered by update())
  // and n that triangle's normal toward the proxy, f' the nearest point of the new patch
  // to f and n' its triangle's normal turned toward n (n'.n >= 0):
  //
  //   p <- p + (f' - f),  then, if h = (p - f').n' < c / 1000,  p <- p + (c - h) n'
  //
  // (c: clearance; the surface came through or onto p) if |f' - f| <= reach; else p
  // stays. The same surface re-sent gives f' = f: the proxy does not move, so replacing
  // the patch adds no force step.
  void carry_over(std::uint64_t sequence, const std::vector<Eigen::Vector3d>& soup, double reach,
    double clearance);

  // One servo tick: the proxy moves from where it is toward the goal x (the stylus) along
  // straight sweeps that stop `clearance` before the first triangle they cross; each
  // triangle so met adds its plane (normal n_i turned toward the proxy) to the active
  // set, and the next sweep aims at x projected onto what the active planes allow:
  //
  //   0 planes: x          1 plane: x - ((x - p).n1) n1
  //   2 planes: p + ((x - p).u) u,  u = n1 x n2 / |n1 x n2|       3 planes: p (a corner)
  //
  // A sweep that meets nothing ends at its target; if planes were active, the set is
  // cleared and one more sweep aims at x itself (a plane the stylus has left, or a convex
  // edge the proxy has slid past, stops constraining; one still pushed against is met
  // again at once). Planes parallel to an active one replace it. At most max_passes
  // sweeps. Their end is the local minimum of |p - x| on the proxy's side (the
  // god-object): on one plane the projection of x, in a concave fold or corner the
  // projection onto the wedge, i.e. onto a convex set, so |d(p - x)| <= |dx| there.
  //
  // Past a convex crest (a ridge, the top of a fault step) that end jumps: the stylus,
  // pressed d deep and slid past the crest line, is nearer the next face, so the spring
  // e = p - x would turn from d n1 to about d cos(theta) n2 in one tick. The sweeps are
  // therefore followed only while the spring stays within one tick of motion of the last
  // one: with x', e' the stylus and spring of the previous update and s the distance
  // carry_over() moved the proxy since,
  //
  //   |(p - x) - e'| <= |x - x'| + s,
  //
  // i.e. p stays in the ball of that radius around x + e'. The first sweep point out of the
  // ball is cut at the ball's boundary and the proxy is held there, off its god-object
  // position and still in contact (in_contact()); it catches up as the stylus moves on, so a
  // crest is felt rounded over about the depth d, and a proxy held still stays put (a
  // still stylus feels a constant force). The start p' + s is in the ball, every sweep
  // point is on the proxy's side and each sweep only shortens |p - x|, so the hold
  // neither crosses a triangle nor adds spring energy. The first update after reset() or
  // place() is not bounded.
  void update(const Eigen::Vector3d& x, const std::vector<Eigen::Vector3d>& soup, double clearance,
    double reach);

  const Eigen::Vector3d& position() const { return this->p_; }
  // On a surface, or held off its god-object position by the bound above (or, out of
  // passes in a shallow crease, off the stylus with no plane active).
  bool in_contact() const { return this->planes_ > 0 || this->held_; }
  // The active (or, held off every plane, the last) constraint's normal toward the proxy;
  // zero out of contact.
  Eigen::Vector3d normal() const
  {
    return this->in_contact() ? this->normal_ : Eigen::Vector3d::Zero();
  }

private:
  Eigen::Vector3d target(const Eigen::Vector3d& x) const;
  void add_plane(const Eigen::Vector3d& n);
  void remember_foot(const std::vector<Eigen::Vector3d>& soup, double reach);

  Eigen::Vector3d p_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d normals_[max_planes];
  int planes_ = 0;
  bool placed_ = false;
  // The step bound: the stylus and the spring p - x of the last update, the distance
  // carry_over() moved the proxy since, whether the proxy is held off its god-object
  // position, and the normal in_contact() reports.
  Eigen::Vector3d last_x_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d spring_ = Eigen::Vector3d::Zero();
  double carried_ = 0.0;
  bool bounded_ = false;
  bool held_ = false;
  Eigen::Vector3d normal_ = Eigen::Vector3d::Zero();
  // The proxy's nearest point on the patch and that triangle's normal toward the proxy.
  Eigen::Vector3d foot_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d foot_normal_ = Eigen::Vector3d::Zero();
  bool has_foot_ = false;
  std::uint64_t sequence_ = 0;
};

} // namespace geoshaping::haptics
