// Helpers shared by the GOCAD TSurf tests: capture errors, write and read files.
#ifndef GocadTestUtilities_h
#define GocadTestUtilities_h

#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkExecutive.h"
#include "vtkGocadTSurfReader.h"
#include "vtkGocadTSurfWriter.h"
#include "vtkIdList.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

namespace gocadtest
{
// Collects error and warning messages instead of printing them.
class MessageCapture : public vtkCommand
{
public:
  static MessageCapture* New() { return new MessageCapture; }
  void Execute(vtkObject*, unsigned long event, void* data) override
  {
    std::string& log = (event == vtkCommand::ErrorEvent) ? this->Errors : this->Warnings;
    log += static_cast<const char*>(data);
    log += "\n";
  }
  void Watch(vtkAlgorithm* algorithm)
  {
    algorithm->AddObserver(vtkCommand::ErrorEvent, this);
    algorithm->AddObserver(vtkCommand::WarningEvent, this);
    algorithm->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, this);
  }
  std::string Errors;
  std::string Warnings;
};

inline std::string WorkPath(const std::string& name)
{
  std::filesystem::create_directories(GEOSHAPING_IO_WORK_DIR);
  return std::string(GEOSHAPING_IO_WORK_DIR) + "/" + name;
}

inline std::string WriteText(const std::string& name, const std::string& content)
{
  const std::string path = WorkPath(name);
  std::ofstream(path, std::ios::binary) << content;
  return path;
}

struct ReadResult
{
  vtkSmartPointer<vtkPolyData> Output;
  std::string Errors;
  std::string Warnings;
};

inline ReadResult Read(const std::string& path)
{
  vtkNew<vtkGocadTSurfReader> reader;
  vtkNew<MessageCapture> capture;
  capture->Watch(reader);
  reader->SetFileName(path.c_str());
  reader->Update();
  return { reader->GetOutput(), capture->Errors, capture->Warnings };
}

inline std::string Write(vtkPolyData* data, const std::string& name, std::string* errors = nullptr)
{
  const std::string path = WorkPath(name);
  std::filesystem::remove(path);
  vtkNew<vtkGocadTSurfWriter> writer;
  vtkNew<MessageCapture> capture;
  capture->Watch(writer);
  writer->SetInputData(data);
  writer->SetFileName(path.c_str());
  writer->Write();
  if (errors)
    *errors = capture->Errors;
  return path;
}

// Same points (==), triangles and point arrays (== or both NaN); "what" names the case.
inline void ExpectSameSurface(vtkPolyData* a, vtkPolyData* b, const std::string& what)
{
  SCOPED_TRACE(what);
  ASSERT_EQ(a->GetNumberOfPoints(), b->GetNumberOfPoints());
  ASSERT_EQ(a->GetNumberOfPolys(), b->GetNumberOfPolys());
  vtkIdType differentPoints = 0;
  for (vtkIdType i = 0; i < a->GetNumberOfPoints(); ++i)
  {
    double p[3], q[3];
    a->GetPoint(i, p);
    b->GetPoint(i, q);
    differentPoints += !(p[0] == q[0] && p[1] == q[1] && p[2] == q[2]);
  }
  EXPECT_EQ(differentPoints, 0);
  vtkNew<vtkIdList> ca, cb;
  for (vtkIdType c = 0; c < a->GetNumberOfCells(); ++c)
  {
    a->GetCellPoints(c, ca);
    b->GetCellPoints(c, cb);
    ASSERT_EQ(ca->GetNumberOfIds(), cb->GetNumberOfIds());
    for (vtkIdType k = 0; k < ca->GetNumberOfIds(); ++k)
      ASSERT_EQ(ca->GetId(k), cb->GetId(k)) << "cell " << c;
  }
  for (int i = 0; i < a->GetPointData()->GetNumberOfArrays(); ++i)
  {
    vtkDataArray* x = a->GetPointData()->GetArray(i);
    vtkDataArray* y = b->GetPointData()->GetArray(x->GetName());
    ASSERT_TRUE(y) << "point array " << x->GetName() << " was not written";
    ASSERT_EQ(x->GetNumberOfComponents(), y->GetNumberOfComponents());
    vtkIdType different = 0;
    for (vtkIdType t = 0; t < x->GetNumberOfTuples(); ++t)
      for (int c = 0; c < x->GetNumberOfComponents(); ++c)
      {
        const double u = x->GetComponent(t, c), v = y->GetComponent(t, c);
        different += !(u == v || (std::isnan(u) && std::isnan(v)));
      }
    EXPECT_EQ(different, 0) << "point array " << x->GetName();
  }
}

inline vtkSmartPointer<vtkPolyData> WriteAndRead(vtkPolyData* data, const std::string& name)
{
  std::string errors;
  const std::string path = Write(data, name, &errors);
  EXPECT_EQ(errors, "");
  const auto r = Read(path);
  EXPECT_EQ(r.Errors, "");
  return r.Output;
}
}

#endif
