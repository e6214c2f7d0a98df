#include "geoshaping/haptics/hand_sim.h"

#include "geoshaping/mesh/nearest_triangles.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <istream>
#include <ostream>
#include <sstream>

namespace geoshaping::haptics
{

namespace
{
// Splits a CSV line into exactly `n` finite numbers.
bool parse_numbers(const std::string& line, int n, double* out)
{
  std::stringstream ss(line);
  std::string field;
  int i = 0;
  while (std::getline(ss, field, ','))
  {
    if (i == n)
      return false;
    std::size_t used = 0;
    try
    {
      out[i] = std::stod(field, &used);
    }
    catch (const std::exception&)
    {
      return false;
    }
    while (used < field.size() && std::isspace((unsigned char)field[used]))
      ++used;
    if (used != field.size() || !std::isfinite(out[i]))
      return false;
    ++i;
  }
  return i == n && (line.empty() || line.back() != ',');
}

std::string trimmed(std::string s)
{
  while (!s.empty() && std::isspace((unsigned char)s.back()))
    s.pop_back();
  return s;
}

Eigen::Vector3d quantised(const Eigen::Vector3d& x, double q)
{
  return q > 0.0 ? Eigen::Vector3d((x / q).array().round() * q) : x;
}
} // namespace

bool read_hand_csv(std::istream& in, std::vector<HandKey>& keys, std::string& error)
{
  keys.clear();
  std::string line;
  if (!std::getline(in, line) || trimmed(line) != "t,fx,fy,fz")
  {
    error = "line 1: expected the header t,fx,fy,fz";
    return false;
  }
  for (int number = 2; std::getline(in, line); ++number)
  {
    line = trimmed(line);
    if (line.empty())
      continue;
    double v[4];
    if (!parse_numbers(line, 4, v))
    {
      error = "line " + std::to_string(number) + ": expected 4 finite numbers t,fx,fy,fz";
      return false;
    }
    if (v[0] < 0.0 || (!keys.empty() && !(v[0] > keys.back().t)))
    {
      error = "line " + std::to_string(number) + ": t must be >= 0 and increasing";
      return false;
    }
    keys.push_back({ v[0], Eigen::Vector3d(v[1], v[2], v[3]) });
  }
  if (keys.empty())
  {
    error = "no rows after the header";
    return false;
  }
  return true;
}

Eigen::Vector3d hand_force_at(const std::vector<HandKey>& keys, double t)
{
  if (keys.empty())
    return Eigen::Vector3d::Zero();
  if (t <= keys.front().t)
    return keys.front().force;
  if (t >= keys.back().t)
    return keys.back().force;
  const auto next = std::upper_bound(
    keys.begin(), keys.end(), t, [](double v, const HandKey& k) { return v < k.t; });
  const HandKey& a = *(next - 1);
  const HandKey& b = *next;
  const double s = (t - a.t) / (b.t - a.t);
  return (1.0 - s) * a.force + s * b.force;
}

bool DeviceModel::named(const std::string& name, DeviceModel& model)
{
  if (name != "touch")
    return false;
  model = DeviceModel();
  return true;
}

std::vector<TrajectoryRow> simulate_hand(const SceneAt& scene, const std::vector<HandKey>& hand,
  const Eigen::Vector3d& start, const DeviceModel& model, const HandSimOptions& options,
  double* injected, double* rendered_work)
{
  std::vector<TrajectoryRow> rows;
  const double T = model.period;
  const double end = hand.empty() ? 0.0 : hand.back().t;
  const auto ticks = std::size_t(std::floor(end / T + 1e-9)) + 1;
  rows.reserve(ticks);
  // The servo's clock: tick k at k T after an arbitrary epoch (stamps must be non-zero).
  const Clock::time_point epoch = Clock::time_point(std::chrono::hours(1));
  auto at = [&](double t)
  { return epoch + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(t)); };

  ServoTick servo(options.force, options.velocity_filter_s);
  SceneSnapshot snapshot;
  snapshot.valid_for = std::chrono::duration_cast<std::chrono::nanoseconds>(
    std::chrono::duration<double>(3.0 * options.patch_period));
  snapshot.grasping = options.grasping;
  snapshot.grasp_anchor = options.grasp_anchor;
  snapshot.grasp_stiffness = options.grasp_stiffness;
  double next_patch = 0.0;
  Eigen::Vector3d x = start, v = Eigen::Vector3d::Zero();
  const double k = std::clamp(options.force.contact_stiffness, 0.0, model.limits.max_stiffness);
  const double f_max = model.limits.max_force;
  auto stored = [&](const TrajectoryRow& r)
  {
    const double d = r.contact ? (r.proxy - quantised(r.x, model.resolution)).norm() : 0.0;
    const double grasp =
      options.grasping ? 0.5 * options.grasp_stiffness * (options.grasp_anchor - r.x).squaredNorm()
                       : 0.0;
    return grasp + (k * d <= f_max ? 0.5 * k * d * d : f_max * d - f_max * f_max / (2 * k));
  };
  double work = 0.0, damped = 0.0;
  const int n = std::max(1, options.substeps);
  const double h = T / n;
  for (std::size_t k = 0; k < ticks; ++k)
  {
    const double t = double(k) * T;
    const bool stalled = t >= options.stall_from && t < options.stall_until;
    if (!stalled && t + 1e-12 >= next_patch)
    {
      scene(t, snapshot.contact_triangles);
      keep_nearest(snapshot.contact_triangles, x, options.max_triangles);
      snapshot.stamp = at(t);
      ++snapshot.sequence;
      while (next_patch <= t + 1e-12)
        next_patch += options.patch_period;
    }
    DeviceSample sample;
    sample.t = t;
    sample.position = quantised(x, model.resolution);
    const ForceResult f = servo.tick(sample, true, at(t), snapshot, model.limits);
    rows.push_back({ t, x, f.force, f.proxy, f.in_contact });

    for (int s = 0; s < n; ++s)
    {
      const Eigen::Vector3d push = hand_force_at(hand, t + s * h) + f.force;
      const Eigen::Vector3d before = x;
      v += h * (push - model.damping * v) / model.mass;
      const double speed = v.norm();
      const double brake = model.friction * h / model.mass;
      v = speed > brake ? Eigen::Vector3d(v * (1.0 - brake / speed)) : Eigen::Vector3d::Zero();
      x += h * v;
      for (int i = 0; i < 3; ++i)
      {
        if (x[i] < model.limits.workspace_min[i] || x[i] > model.limits.workspace_max[i])
        {
          x[i] = std::clamp(x[i], model.limits.workspace_min[i], model.limits.workspace_max[i]);
          v[i] = 0.0;
        }
      }
      work += f.force.dot(x - before);
      if (f.in_contact || options.grasping)
        damped += model.damping * v.squaredNorm() * h;
    }
  }
  if (injected && !rows.empty())
    *injected = work + stored(rows.back()) - stored(rows.front()) - damped;
  if (rendered_work)
    *rendered_work = work;
  return rows;
}

void write_trajectory_csv(std::ostream& out, const std::vector<TrajectoryRow>& rows)
{
  out << "t,x,y,z,fx,fy,fz,px,py,pz,contact\n" << std::setprecision(17);
  for (const TrajectoryRow& r : rows)
  {
    out << r.t << ',' << r.x.x() << ',' << r.x.y() << ',' << r.x.z() << ',' << r.force.x() << ','
        << r.force.y() << ',' << r.force.z() << ',' << r.proxy.x() << ',' << r.proxy.y() << ','
        << r.proxy.z() << ',' << (r.contact ? 1 : 0) << '\n';
  }
}

RunFigures run_figures(
  const std::vector<TrajectoryRow>& rows, const DeviceModel& model, const HandSimOptions& options)
{
  RunFigures f;
  const double k = std::clamp(options.force.contact_stiffness, 0.0, model.limits.max_stiffness);
  for (std::size_t i = 0; i < rows.size(); ++i)
  {
    if (rows[i].contact)
      f.max_proxy_distance = std::max(f.max_proxy_distance, (rows[i].proxy - rows[i].x).norm());
    if (i == 0)
      continue;
    const double step = (rows[i].force - rows[i - 1].force).norm();
    const double motion =
      (quantised(rows[i].x, model.resolution) - quantised(rows[i - 1].x, model.resolution)).norm();
    f.max_force_step = std::max(f.max_force_step, step);
    f.max_step_excess = std::max(f.max_step_excess, step - k * motion);
  }
  return f;
}

} // namespace geoshaping::haptics
