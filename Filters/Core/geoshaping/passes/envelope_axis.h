#pragma once
// One axis of the envelope refinement (link_projection.h, ProjectionSolver::envelope),
// written once for the whole mesh (LinkProjector) and for a piece of it
// (PartitionedEnvelope, partitioned_envelope.h): the two give the same bits because they
// run this same step and differ only in what a Net supplies, how a vertex's links are read
// and how a label-correcting run reaches the other pieces.
//
// Per axis, with y = sign u (D: sign +1, the greatest feasible configuration below the
// start; U: sign -1, the least above):
//   1. scan: each link violated by the start, lo <= u_v - u_m <= hi broken, seeds D's run
//      at its low end and U's at its high end (an end whose other end is fixed is left);
//   2. each run: the fixed vertices' cones on -y raise the labels above them (free
//      vertices only), the links those raised labels break seed the run too, then the
//      min-plus run lowers labels from the seeds: y_a <= y_b + ub(a, b), ub(v, m) = hi
//      (sign +1) or -lo (sign -1);
//   3. each vertex either run labelled takes (D + U) / 2 (D itself when D == U); fixed
//      vertices and non-finite results keep their start;
//   4. the check: the largest distance of a link's difference to its slab on this axis
//      (links between two fixed vertices left out).
//
// A Net supplies (v, m vertices; f a callable):
//   bool is_fixed(v); double u(v, axis): u_v on the axis, read by steps 1 and 4 (between
//     begin_axis and the first begin_run, and after end_runs); start_u(v, axis): u_v on the
//     axis before step 3, read by step 3;
//   begin_axis(axis), end_runs(axis): called before step 1 and after step 3;
//   for_each_scanned(f(v)), for_each_checked(f(v)): the vertices whose links steps 1 and 4
//     read; scanned_from(m, v), checked_from(m, v): the link (v, m) is read from m's side
//     there instead;
//   for_each_link(v, axis, f(m, lo, hi, m_fixed)): v's links, lo <= u_v - u_m <= hi;
//   begin_run(axis, sign): new labels (every label the start, y = sign u);
//   label(v, axis, sign), set_label(v, axis, sign, y), touched(): the run's labels;
//   raised_to_check(): after cone(), the raised vertices whose links step 2 checks for
//     breaks: touched(), or any subset holding every raised vertex with a broken link;
//   cone(axis, sign, f(a, c)): the fixed vertices' cone labels c on y' = sign u, each
//     vertex a with one;
//   min_pass(axis, sign, seeds): the min-plus run;
//   change(v, axis, value): u_v[axis] = value, v recorded as changed (mark_changed).
#include "geoshaping/mesh/adjacency.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace geoshaping
{

// Records v as changed: a mark of 0 (outside the region) adds v to `region`, a mark other
// than 2 adds it to `changed`; the mark becomes 2.
inline void mark_changed(
  std::uint8_t& mark, index_t v, std::vector<index_t>& region, std::vector<index_t>& changed)
{
  if (!mark)
    region.push_back(v);
  if (mark != 2)
    changed.push_back(v);
  mark = 2;
}

class EnvelopeAxis
{
public:
  // Dense scratch for n vertices (allocated once; reset sparsely after each axis).
  void resize(std::size_t n)
  {
    if (down_.size() != n)
      down_.assign(n, std::numeric_limits<double>::quiet_NaN());
  }

  // Steps 1-4 on `axis`; returns the check's largest slab distance.
  template<class Net>
  double run(Net& net, int axis);

private:
  template<class Net>
  void scan(Net& net, int axis);
  template<class Net>
  void direction(Net& net, int axis, double sign, std::vector<index_t>& from);
  template<class Net>
  double check(Net& net, int axis);

  std::vector<double> down_; // D per vertex (NaN: not labelled)
  std::vector<index_t> seeds_, seeds_up_, down_list_;
};

template<class Net>
double EnvelopeAxis::run(Net& net, int axis)
{
  net.begin_axis(axis);
  scan(net, axis);
  direction(net, axis, 1.0, seeds_);
  down_list_ = net.touched();
  for (index_t v : down_list_)
    down_[std::size_t(v)] = net.label(v, axis, 1.0);
  direction(net, axis, -1.0, seeds_up_);
  const auto combine = [&](index_t v)
  {
    const double old = net.start_u(v, axis);
    const double d = std::isnan(down_[std::size_t(v)]) ? old : down_[std::size_t(v)];
    const double u = -net.label(v, axis, -1.0);
    const double mid = d == u ? d : 0.5 * (d + u);
    if (net.is_fixed(v) || mid == old || !std::isfinite(mid))
      return;
    net.change(v, axis, mid);
  };
  for (index_t v : down_list_)
    combine(v);
  // A vertex both runs labelled was combined above: a second combine would change nothing.
  for (index_t v : net.touched())
    if (std::isnan(down_[std::size_t(v)]))
      combine(v);
  net.end_runs(axis);
  for (index_t v : down_list_)
    down_[std::size_t(v)] = std::numeric_limits<double>::quiet_NaN();
  return check(net, axis);
}

template<class Net>
void EnvelopeAxis::scan(Net& net, int axis)
{
  seeds_.clear();
  seeds_up_.clear();
  net.for_each_scanned(
    [&](index_t v)
    {
      const double uv = net.u(v, axis);
      net.for_each_link(v, axis,
        [&](index_t m, double lo, double hi, bool m_fixed)
        {
          if (net.scanned_from(m, v))
            return;
          const double w = uv - net.u(m, axis);
          const index_t high = w > hi ? v : (w < lo ? m : -1);
          if (high < 0)
            return;
          const index_t low = high == v ? m : v;
          if (!(high == v ? net.is_fixed(v) : m_fixed))
            seeds_.push_back(low);
          if (!(low == v ? net.is_fixed(v) : m_fixed))
            seeds_up_.push_back(high);
        });
    });
}

template<class Net>
void EnvelopeAxis::direction(Net& net, int axis, double sign, std::vector<index_t>& from)
{
  net.begin_run(axis, sign);
  net.cone(axis, -sign,
    [&](index_t a, double c)
    {
      if (!net.is_fixed(a) && c < -net.label(a, axis, sign))
        net.set_label(a, axis, sign, -c);
    });
  // Links the raised labels break seed the run too.
  const std::vector<index_t>& raised = net.raised_to_check();
  for (std::size_t i = 0; i < raised.size(); ++i)
  {
    const index_t v = raised[i];
    const double yv = net.label(v, axis, sign);
    const bool v_fixed = net.is_fixed(v);
    net.for_each_link(v, axis,
      [&](index_t m, double lo, double hi, bool m_fixed)
      {
        const double ym = net.label(m, axis, sign);
        const double ub_vm = sign > 0.0 ? hi : -lo;
        const double ub_mv = sign > 0.0 ? -lo : hi;
        if (yv > ym + ub_vm && !v_fixed)
          from.push_back(m);
        if (ym > yv + ub_mv && !m_fixed)
          from.push_back(v);
      });
  }
  net.min_pass(axis, sign, from);
}

// In the Axes frame a direction's distance is the Euclidean norm of its per-axis
// distances, each at most the slab's (the slab is inside both directions' boxes), and an
// axis left out is 0 everywhere (0 is in every slab): the root of the sum of the squared
// per-axis results bounds E_link from above.
template<class Net>
double EnvelopeAxis::check(Net& net, int axis)
{
  double worst = 0.0;
  net.for_each_checked(
    [&](index_t v)
    {
      const double uv = net.u(v, axis);
      const bool v_fixed = net.is_fixed(v);
      net.for_each_link(v, axis,
        [&](index_t m, double lo, double hi, bool m_fixed)
        {
          if (net.checked_from(m, v) || (v_fixed && m_fixed))
            return;
          const double w = uv - net.u(m, axis);
          worst = std::max(worst, std::max(lo - w, w - hi));
        });
    });
  return worst;
}

} // namespace geoshaping
