// geoshaping_hand_sim driven as a user would: scene and hand files written here, the
// trajectory read back and checked against the scene's geometry computed here.
#include <Eigen/Core>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include <sys/wait.h>

namespace
{
const std::string dir = GEOSHAPING_HAND_SIM_DIR;
constexpr double k = 800.0;       // contact stiffness, N/m (ForceParams)
constexpr double quantum = 55e-6; // m, the Touch model's resolution
constexpr double max_force = 3.3; // N
// N: how far a tick's step may exceed k |dx|, the passivity controller's damper changing
// by at most the fade's step (max force x 1 ms / 0.1 s; passivity.h).
constexpr double damper_step = max_force * 0.001 / 0.1 + 1e-9;

struct Row
{
  double t;
  Eigen::Vector3d x, f, p;
  bool contact;
};

std::string path(const std::string& name)
{
  std::filesystem::create_directories(dir);
  return dir + "/" + name;
}

// A grid surface z = height(x, y) over [-0.05, 0.05]^2 (metres) in nx x ny quads, written
// in millimetres as an ASCII .vtp (the runs use --scale 1000).
template<class Height>
std::string write_vtp(const std::string& name, int nx, int ny, Height height)
{
  std::ofstream out(path(name));
  out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"0.1\">\n<PolyData>\n"
      << "<Piece NumberOfPoints=\"" << (nx + 1) * (ny + 1) << "\" NumberOfPolys=\"" << 2 * nx * ny
      << "\">\n<Points><DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  out.precision(17);
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i)
    {
      const double x = -0.05 + 0.1 * i / nx, y = -0.05 + 0.1 * j / ny;
      out << 1000 * x << " " << 1000 * y << " " << 1000 * height(x, y) << "\n";
    }
  out << "</DataArray></Points>\n<Polys><DataArray type=\"Int64\" Name=\"connectivity\" "
         "format=\"ascii\">\n";
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
    {
      const int a = j * (nx + 1) + i;
      out << a << " " << a + 1 << " " << a + nx + 2 << " " << a << " " << a + nx + 2 << " "
          << a + nx + 1 << "\n";
    }
  out << "</DataArray><DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
  for (int c = 1; c <= 2 * nx * ny; ++c)
    out << 3 * c << "\n";
  out << "</DataArray></Polys>\n</Piece>\n</PolyData>\n</VTKFile>\n";
  return path(name);
}

// The fault step as a Gocad TSurf (metres): an upper plateau z = 0 for y < -5 mm, a 45
// degree ramp down to z = -1 cm at y = +5 mm, a lower plateau; 41 columns along x.
double step_height(double y)
{
  return y < -0.005 ? 0.0 : y > 0.005 ? -0.01 : -(y + 0.005);
}
std::string write_step_ts(const std::string& name)
{
  const std::vector<double> ys = { -0.05, -0.03, -0.01, -0.005, 0.005, 0.01, 0.03, 0.05 };
  const int nx = 41;
  std::ofstream out(path(name));
  out.precision(17);
  out << "GOCAD TSurf 1\nHEADER {\nname:fault_step\n}\nTFACE\n";
  int id = 1;
  for (const double y : ys)
    for (int i = 0; i < nx; ++i)
      out << "VRTX " << id++ << " " << -0.05 + 0.1 * i / (nx - 1) << " " << y << " "
          << step_height(y) << "\n";
  for (std::size_t j = 0; j + 1 < ys.size(); ++j)
    for (int i = 0; i + 1 < nx; ++i)
    {
      const int a = int(j) * nx + i + 1;
      out << "TRGL " << a << " " << a + 1 << " " << a + nx + 1 << "\n";
      out << "TRGL " << a << " " << a + nx + 1 << " " << a + nx << "\n";
    }
  out << "END\n";
  return path(name);
}

std::string write_text(const std::string& name, const std::string& text)
{
  std::ofstream(path(name)) << text;
  return path(name);
}

int run(const std::string& scene, const std::string& hand, const std::string& start,
  const std::string& out, const std::string& extra = "")
{
  const std::string command = std::string(GEOSHAPING_HAND_SIM) + " --scene '" + scene +
                              "' --hand '" + hand + "' --start " + start + " --out '" + out + "'" +
                              extra + " 2> '" + out + ".err'";
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::vector<Row> read_trajectory(const std::string& file)
{
  std::ifstream in(file);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "t,x,y,z,fx,fy,fz,px,py,pz,contact");
  std::vector<Row> rows;
  while (std::getline(in, line))
  {
    std::replace(line.begin(), line.end(), ',', ' ');
    std::istringstream ss(line);
    Row r;
    int c = 0;
    ss >> r.t >> r.x.x() >> r.x.y() >> r.x.z() >> r.f.x() >> r.f.y() >> r.f.z() >> r.p.x() >>
      r.p.y() >> r.p.z() >> c;
    r.contact = c != 0;
    rows.push_back(r);
  }
  return rows;
}

// Largest |dF| - k |dx| over the run, x quantised as the device reads it.
double step_excess(const std::vector<Row>& rows)
{
  auto q = [](const Eigen::Vector3d& x)
  { return Eigen::Vector3d((x / quantum).array().round() * quantum); };
  double worst = -1.0;
  for (std::size_t i = 1; i < rows.size(); ++i)
    worst = std::max(
      worst, (rows[i].f - rows[i - 1].f).norm() - k * (q(rows[i].x) - q(rows[i - 1].x)).norm());
  return worst;
}

// The energy the rendering injected (hand_sim.h): its work on the stylus (F held over
// each tick) plus the spring energy left stored, less the device model's damping
// (0.6 N s/m) over the ticks in contact, velocities from the trajectory.
double injected(const std::vector<Row>& rows)
{
  auto stored = [](const Row& r) { return r.contact ? r.f.squaredNorm() / (2 * k) : 0.0; };
  double w = 0.0;
  for (std::size_t i = 1; i < rows.size(); ++i)
  {
    const Eigen::Vector3d dx = rows[i].x - rows[i - 1].x;
    w += rows[i - 1].f.dot(dx);
    if (rows[i - 1].contact)
      w -= 0.6 * dx.squaredNorm() / 0.001;
  }
  return w + stored(rows.back()) - stored(rows.front());
}

std::string sheet()
{
  return write_vtp("sheet.vtp", 20, 20, [](double, double) { return 0.0; });
}
} // namespace

namespace
{
// The hand of the table's cases: a push along z ramped up over 0.2 s and held to 2 s,
// from 1 cm on the `side` of the sheet (written in mm, --scale 1000).
std::vector<Row> press(const std::string& name, double fz, double side, const std::string& extra)
{
  const std::string out = path(name + ".csv");
  const std::string hand =
    "t,fx,fy,fz\n0,0,0,0\n0.2,0,0," + std::to_string(fz) + "\n2,0,0," + std::to_string(fz) + "\n";
  EXPECT_EQ(run(sheet(), write_text(name + ".hand", hand), side > 0 ? "0,0,0.01" : "0,0,-0.01", out,
              " --scale 1000" + extra),
    0);
  return read_trajectory(out);
}

// What every run must show: the proxy on its side (`side` of z = 0), no force step beyond
// k times the motion, no energy injected.
void expect_sound(const std::vector<Row>& rows, double side)
{
  ASSERT_EQ(rows.size(), 2001u);
  for (const Row& r : rows)
  {
    ASSERT_GT(side * r.p.z(), 0.0) << r.t;
    ASSERT_LE(r.f.norm(), max_force + 1e-9) << r.t;
    ASSERT_GE(side * r.f.z(), -1e-12) << r.t;
  }
  EXPECT_LE(step_excess(rows), damper_step);
  EXPECT_LE(injected(rows), 0.0);
}
} // namespace

TEST(HandSimCli, PressingTwoNewtonsFromTheFreeSideRestsOnTheSheet)
{
  const auto rows = press("press2", -2.0, 1.0, " --device touch");
  expect_sound(rows, 1.0);
  EXPECT_NEAR(rows.back().x.z(), -2.0 / k, 2 * quantum);
  EXPECT_NEAR(rows.back().f.z(), 2.0, 0.1);
}

TEST(HandSimCli, PressingFiveNewtonsIsHeldAtTheDevicesMaximum)
{
  const auto rows = press("press5", -5.0, 1.0, "");
  expect_sound(rows, 1.0);
  EXPECT_NEAR(rows.back().f.z(), max_force, 1e-9);
}

TEST(HandSimCli, ComingFromTheBackSideIsHeldOnTheBackSide)
{
  // The stylus may overshoot the sheet; the proxy holds it back.
  const auto rows = press("back", 0.5, -1.0, "");
  expect_sound(rows, -1.0);
  EXPECT_NEAR(rows.back().x.z(), 0.5 / k, 2 * quantum);
  EXPECT_NEAR(rows.back().f.z(), -0.5, 0.1);
}

TEST(HandSimCli, SlidingOverSliversAndAcrossManyPatchesGivesNoStep)
{
  // 10 cm x 0.4 mm strips cut in two (slivers of 250 : 1), 500 triangles: the 256
  // nearest are re-sent every 16 ms while the hand presses 1.5 N and drags about 8 cm/s
  // across them.
  const std::string scene = write_vtp("slivers.vtp", 1, 250, [](double, double) { return 0.0; });
  const std::string out = path("slivers.csv");
  ASSERT_EQ(run(scene,
              write_text("slide.hand", "t,fx,fy,fz\n0,0,0,-1.5\n0.3,0,0,-1.5\n0.5,0.08,0.06,-1.5\n"
                                       "1.2,0.08,0.06,-1.5\n"),
              "-0.03,-0.03,0.002", out, " --scale 1000"),
    0);
  const auto rows = read_trajectory(out);
  EXPECT_GT(rows.back().x.x(), 0.0);
  for (const Row& r : rows)
    ASSERT_GT(r.p.z(), 0.0);
  EXPECT_LE(step_excess(rows), damper_step);
  EXPECT_LE(injected(rows), 0.0);
}

TEST(HandSimCli, ClimbingOverAFaultStepNeverPassesThrough)
{
  const std::string out = path("step.csv");
  ASSERT_EQ(run(write_step_ts("step.ts"),
              write_text("climb.hand", "t,fx,fy,fz\n0,0,0,-0.1\n0.3,0,0,-0.1\n0.5,0,-0.25,-0.1\n"
                                       "0.8,0,-0.25,-0.1\n"),
              "0,0.02,-0.008", out),
    0);
  const auto rows = read_trajectory(out);
  EXPECT_LT(rows.back().x.y(), -0.01); // it climbed onto the upper plateau
  for (const Row& r : rows)
    ASSERT_GT(r.p.z(), step_height(r.p.y()) - 1e-9) << r.t;
  EXPECT_LE(step_excess(rows), damper_step);
  std::cout << "fault step: step excess " << step_excess(rows) << " N, injected " << injected(rows)
            << " J\n";
  EXPECT_LE(injected(rows), 0.0);
}

TEST(HandSimCli, MalformedInputIsAClearErrorWithExitCode2)
{
  const std::string good = write_text("good.hand", "t,fx,fy,fz\n0,0,0,0\n0.1,0,0,0\n");
  const std::string out = path("bad.csv");
  EXPECT_EQ(run(sheet(), write_text("bad1.hand", "t,fx,fy\n0,0,0\n"), "0,0,1", out), 2);
  EXPECT_EQ(run(sheet(), write_text("bad2.hand", "t,fx,fy,fz\n0,0,zero,0\n"), "0,0,1", out), 2);
  std::ifstream err(out + ".err");
  std::string message((std::istreambuf_iterator<char>(err)), std::istreambuf_iterator<char>());
  EXPECT_NE(message.find("line 2"), std::string::npos) << message;
  EXPECT_EQ(run(sheet(), good, "0,0", out), 2);
  EXPECT_EQ(run(sheet(), good, "0,0,1", out, " --device phantom"), 2);
  EXPECT_EQ(run(sheet(), good, "0,0,1", out, " --scale -1"), 2);
  EXPECT_EQ(run(path("missing.vtp"), good, "0,0,1", out), 2);
  EXPECT_EQ(run(write_text("junk.vtp", "not xml"), good, "0,0,1", out), 2);
  EXPECT_EQ(run(write_text("junk.ts", "GOCAD TSurf 1\nEND\n"), good, "0,0,1", out), 2);
  EXPECT_EQ(run(sheet(), good, "0,0,1", out), 0);
}
