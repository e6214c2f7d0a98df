// geoshaping_hand_sim: the project's servo-side rendering against a simulated device and
// hand, no GUI (docs/haptics.md, "Hand simulator"). VTK only reads the scene; the physics
// is hand_sim.h. Exit codes: 0 done, 2 bad arguments or input, 1 output not written.
#include "geoshaping/haptics/hand_sim.h"

#include "vtkGocadTSurfReader.h"

#include <vtkCellArray.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkTriangleFilter.h>
#include <vtkXMLPolyDataReader.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

namespace haptics = geoshaping::haptics;

namespace
{
int usage(const std::string& why)
{
  std::cerr << "geoshaping_hand_sim: " << why << "\n"
            << "usage: geoshaping_hand_sim --scene SURFACE.vtp|.ts --hand HAND.csv"
               " --start X,Y,Z --out TRAJECTORY.csv [--device touch] [--scale S]\n";
  return 2;
}

bool ends_with(const std::string& s, const std::string& end)
{
  return s.size() >= end.size() && s.compare(s.size() - end.size(), end.size(), end) == 0;
}

bool parse_point(const std::string& text, Eigen::Vector3d& p)
{
  std::stringstream ss(text);
  std::string field;
  int i = 0;
  while (std::getline(ss, field, ','))
  {
    char* end = nullptr;
    if (i == 3 || field.empty())
      return false;
    p[i++] = std::strtod(field.c_str(), &end);
    if (*end != '\0' || !std::isfinite(p[i - 1]))
      return false;
  }
  return i == 3;
}

// The scene's triangles divided by `scale`, or an error.
bool read_scene(
  const std::string& path, double scale, std::vector<Eigen::Vector3d>& soup, std::string& error)
{
  if (!std::ifstream(path))
  {
    error = "cannot open the scene " + path;
    return false;
  }
  vtkSmartPointer<vtkAlgorithm> reader;
  if (ends_with(path, ".vtp"))
  {
    auto xml = vtkSmartPointer<vtkXMLPolyDataReader>::New();
    xml->SetFileName(path.c_str());
    reader = xml;
  }
  else if (ends_with(path, ".ts"))
  {
    auto ts = vtkSmartPointer<vtkGocadTSurfReader>::New();
    ts->SetFileName(path.c_str());
    reader = ts;
  }
  else
  {
    error = "the scene must be a .vtp or .ts file: " + path;
    return false;
  }
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(reader->GetOutputPort());
  triangles->PassLinesOff();
  triangles->PassVertsOff();
  triangles->Update();
  vtkPolyData* mesh = triangles->GetOutput();
  if (reader->GetErrorCode() != 0 || !mesh || mesh->GetNumberOfPolys() == 0)
  {
    error = "no triangles read from the scene " + path;
    return false;
  }
  vtkCellArray* polys = mesh->GetPolys();
  vtkIdType n = 0;
  const vtkIdType* ids = nullptr;
  for (polys->InitTraversal(); polys->GetNextCell(n, ids);)
  {
    for (vtkIdType i = 0; i < n; ++i)
    {
      Eigen::Vector3d p;
      mesh->GetPoint(ids[i], p.data());
      if (!p.allFinite())
      {
        error = "a scene point is not finite in " + path;
        return false;
      }
      soup.push_back(p / scale);
    }
  }
  return true;
}
} // namespace

int main(int argc, char** argv)
{
  std::string scene_path, hand_path, start_text, out_path, device = "touch";
  double scale = 1.0;
  bool have_start = false;
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    if (i + 1 >= argc)
      return usage("missing value after " + arg);
    const std::string value = argv[++i];
    if (arg == "--scene")
      scene_path = value;
    else if (arg == "--hand")
      hand_path = value;
    else if (arg == "--start")
      start_text = value, have_start = true;
    else if (arg == "--out")
      out_path = value;
    else if (arg == "--device")
      device = value;
    else if (arg == "--scale")
    {
      char* end = nullptr;
      scale = std::strtod(value.c_str(), &end);
      if (*end != '\0' || !std::isfinite(scale) || !(scale > 0.0))
        return usage("--scale must be a positive number: " + value);
    }
    else
      return usage("unknown option " + arg);
  }
  if (scene_path.empty() || hand_path.empty() || !have_start || out_path.empty())
    return usage("--scene, --hand, --start and --out are required");
  Eigen::Vector3d start;
  if (!parse_point(start_text, start))
    return usage("--start must be X,Y,Z (three finite numbers): " + start_text);
  haptics::DeviceModel model;
  if (!haptics::DeviceModel::named(device, model))
    return usage("unknown device " + device + " (known: touch)");

  std::vector<haptics::HandKey> hand;
  std::string error;
  std::ifstream hand_file(hand_path);
  if (!hand_file)
    return usage("cannot open the hand file " + hand_path);
  if (!haptics::read_hand_csv(hand_file, hand, error))
    return usage(hand_path + ": " + error);
  std::vector<Eigen::Vector3d> soup;
  if (!read_scene(scene_path, scale, soup, error))
    return usage(error);

  const auto rows =
    haptics::simulate_hand([&soup](double, std::vector<Eigen::Vector3d>& out) { out = soup; }, hand,
      start, model, haptics::HandSimOptions());
  std::ofstream out(out_path);
  haptics::write_trajectory_csv(out, rows);
  out.close();
  if (!out)
  {
    std::cerr << "geoshaping_hand_sim: cannot write " << out_path << "\n";
    return 1;
  }
  return 0;
}
