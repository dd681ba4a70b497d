// vtkMetaballsSource through the pipeline: advertised time, per-time output,
// determinism, and the shape promises of the documentation (closed blobs
// inside [-0.8,0.8]^3 that merge and split over a period).

#include "vtkMetaballsSource.h"

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkFeatureEdges.h"
#include "vtkFlyingEdges3D.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataConnectivityFilter.h"
#include "vtkSmartPointer.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

namespace
{
int Failures = 0;

void Check(bool condition, const std::string& what)
{
  if (!condition)
  {
    std::cerr << "FAIL: " << what << "\n";
    ++Failures;
  }
}

bool SamePoints(vtkPolyData* a, vtkPolyData* b)
{
  if (a->GetNumberOfPoints() != b->GetNumberOfPoints())
  {
    return false;
  }
  for (vtkIdType i = 0; i < a->GetNumberOfPoints(); ++i)
  {
    double p[3], q[3];
    a->GetPoint(i, p);
    b->GetPoint(i, q);
    if (p[0] != q[0] || p[1] != q[1] || p[2] != q[2])
    {
      return false;
    }
  }
  return true;
}

vtkSmartPointer<vtkPolyData> Snapshot(vtkFlyingEdges3D* contour)
{
  auto copy = vtkSmartPointer<vtkPolyData>::New();
  copy->DeepCopy(contour->GetOutput());
  return copy;
}

void TestTimeInformation()
{
  vtkNew<vtkMetaballsSource> source;
  source->UpdateInformation();
  vtkInformation* info = source->GetOutputInformation(0);
  Check(info->Has(vtkStreamingDemandDrivenPipeline::TIME_STEPS()), "TIME_STEPS not advertised");
  Check(info->Has(vtkStreamingDemandDrivenPipeline::TIME_RANGE()), "TIME_RANGE not advertised");
  if (!info->Has(vtkStreamingDemandDrivenPipeline::TIME_STEPS()) ||
    !info->Has(vtkStreamingDemandDrivenPipeline::TIME_RANGE()))
  {
    return;
  }
  const int count = info->Length(vtkStreamingDemandDrivenPipeline::TIME_STEPS());
  const double* steps = info->Get(vtkStreamingDemandDrivenPipeline::TIME_STEPS());
  const double* range = info->Get(vtkStreamingDemandDrivenPipeline::TIME_RANGE());
  Check(count == 60, "default number of time steps is " + std::to_string(count));
  Check(steps[0] == 0.0, "first time step is not 0");
  bool even = true;
  for (int k = 1; k < count; ++k)
  {
    even = even && std::abs((steps[k] - steps[k - 1]) - 1.0 / 60.0) < 1.0e-12;
  }
  Check(even, "time steps are not evenly spaced by period/60");
  Check(steps[count - 1] < 1.0, "last time step should stop short of the period");
  Check(range[0] == 0.0 && range[1] == 1.0,
    "TIME_RANGE is [" + std::to_string(range[0]) + ", " + std::to_string(range[1]) + "]");

  int extent[6];
  info->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent);
  Check(extent[0] == 0 && extent[1] == 47 && extent[3] == 47 && extent[5] == 47,
    "whole extent is not 48^3");
  const double* spacing = info->Get(vtkDataObject::SPACING());
  const double* origin = info->Get(vtkDataObject::ORIGIN());
  Check(std::abs(spacing[0] - 2.0 / 47.0) < 1.0e-12 && origin[0] == -1.0 && origin[2] == -1.0,
    "spacing/origin do not cover [-1,1]");

  // Changing the parameters must be reflected on the next pass.
  source->SetNumberOfTimeSteps(12);
  source->SetTimePeriod(3.0);
  source->UpdateInformation();
  Check(info->Length(vtkStreamingDemandDrivenPipeline::TIME_STEPS()) == 12,
    "NumberOfTimeSteps change not advertised");
  range = info->Get(vtkStreamingDemandDrivenPipeline::TIME_RANGE());
  Check(range[1] == 3.0, "TimePeriod change not advertised");

  // Clamped setters.
  source->SetSampleDimensions(1);
  source->SetNumberOfBalls(40);
  source->SetTimePeriod(-1.0);
  Check(source->GetSampleDimensions() == 2, "SampleDimensions not clamped to >= 2");
  Check(source->GetNumberOfBalls() == 16, "NumberOfBalls not clamped to <= 16");
  Check(source->GetTimePeriod() > 0.0, "TimePeriod not kept positive");
}

void TestContourOverTime()
{
  vtkNew<vtkMetaballsSource> source;
  vtkNew<vtkFlyingEdges3D> contour;
  contour->SetInputConnection(source->GetOutputPort());
  contour->SetValue(0, source->GetIsoValue());
  contour->ComputeNormalsOn();

  const double t1 = 0.0;
  const double t2 = 0.3;
  contour->UpdateTimeStep(t1);
  auto first = Snapshot(contour);
  Check(first->GetNumberOfPolys() > 0, "no polygons at t1");
  Check(first->GetPointData()->GetNormals() != nullptr, "no normals");
  auto field = vtkSmartPointer<vtkImageData>::New();
  field->DeepCopy(source->GetOutput());
  vtkDataArray* scalars = field->GetPointData()->GetScalars();
  Check(scalars && std::string(scalars->GetName() ? scalars->GetName() : "") == "field" &&
      scalars->GetDataType() == VTK_FLOAT,
    "output scalars are not a float array named 'field'");

  contour->UpdateTimeStep(t2);
  auto second = Snapshot(contour);
  Check(second->GetNumberOfPolys() > 0, "no polygons at t2");
  Check(!SamePoints(first, second), "the surfaces at t1 and t2 are identical");
  vtkDataObject* sourceOutput = source->GetOutputDataObject(0);
  Check(sourceOutput->GetInformation()->Has(vtkDataObject::DATA_TIME_STEP()) &&
      sourceOutput->GetInformation()->Get(vtkDataObject::DATA_TIME_STEP()) == t2,
    "source output DATA_TIME_STEP is not the requested time");
  Check(contour->GetOutput()->GetInformation()->Get(vtkDataObject::DATA_TIME_STEP()) == t2,
    "contour output DATA_TIME_STEP is not the requested time");

  // Back to t1: the source must re-execute and give the very same surface.
  contour->UpdateTimeStep(t1);
  Check(SamePoints(first, contour->GetOutput()), "the same time twice gives different surfaces");

  // A separate instance at the same time computes the same field.
  vtkNew<vtkMetaballsSource> other;
  other->UpdateTimeStep(t1);
  vtkDataArray* otherScalars = other->GetOutput()->GetPointData()->GetScalars();
  bool sameField = scalars && otherScalars &&
    otherScalars->GetNumberOfTuples() == scalars->GetNumberOfTuples();
  for (vtkIdType i = 0; sameField && i < scalars->GetNumberOfTuples(); ++i)
  {
    sameField = scalars->GetTuple1(i) == otherScalars->GetTuple1(i);
  }
  Check(sameField, "two sources at the same time give different fields");

  // Periodicity: one period later is the same state (up to float rounding).
  other->UpdateTimeStep(t1 + other->GetTimePeriod());
  otherScalars = other->GetOutput()->GetPointData()->GetScalars();
  double worst = 0.0;
  for (vtkIdType i = 0; scalars && i < scalars->GetNumberOfTuples(); ++i)
  {
    const double a = scalars->GetTuple1(i);
    worst = std::max(worst, std::abs(a - otherScalars->GetTuple1(i)) / std::max(1.0, a));
  }
  Check(worst < 1.0e-4, "field at t + period differs (" + std::to_string(worst) + ")");

  // The way a mapper asks: the time is set on the request downstream, then
  // the pipeline is updated.
  contour->GetOutputInformation(0)->Set(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP(), t2);
  contour->Update();
  Check(SamePoints(second, contour->GetOutput()),
    "a time set on the downstream request is not honoured");
}

// A piece of the output (streaming, parallel) holds exactly the values of the
// whole output at the same points.
void TestPieces()
{
  const double t = 0.4;
  vtkNew<vtkMetaballsSource> whole;
  whole->UpdateTimeStep(t);
  vtkImageData* all = whole->GetOutput();
  vtkNew<vtkMetaballsSource> source;
  std::vector<char> covered(static_cast<size_t>(all->GetNumberOfPoints()), 0);
  bool same = true;
  for (int piece = 0; piece < 3; ++piece)
  {
    source->UpdateTimeStep(t, piece, 3);
    vtkImageData* part = source->GetOutput();
    vtkDataArray* values = part->GetPointData()->GetScalars();
    int extent[6];
    part->GetExtent(extent);
    // Without sub-extent support the first piece would get everything.
    Check(part->GetNumberOfPoints() > 0 && part->GetNumberOfPoints() < all->GetNumberOfPoints(),
      "piece " + std::to_string(piece) + " of 3 has " + std::to_string(part->GetNumberOfPoints()) +
        " points");
    for (int k = extent[4]; values && k <= extent[5]; ++k)
    {
      for (int j = extent[2]; j <= extent[3]; ++j)
      {
        for (int i = extent[0]; i <= extent[1]; ++i)
        {
          int ijk[3] = { i, j, k };
          const vtkIdType id = all->ComputePointId(ijk);
          covered[id] = 1;
          same = same &&
            values->GetTuple1(part->ComputePointId(ijk)) ==
              all->GetPointData()->GetScalars()->GetTuple1(id);
        }
      }
    }
  }
  Check(same, "pieces do not match the whole output");
  Check(std::count(covered.begin(), covered.end(), 1) == all->GetNumberOfPoints(),
    "the pieces do not cover the whole grid");
}

// Over the advertised steps the default blobs stay closed and inside
// [-0.8,0.8]^3, and come apart and together at least once.
void TestShapeOverPeriod()
{
  vtkNew<vtkMetaballsSource> source;
  vtkNew<vtkFlyingEdges3D> contour;
  contour->SetInputConnection(source->GetOutputPort());
  contour->SetValue(0, 1.0);
  vtkNew<vtkFeatureEdges> edges;
  edges->SetInputConnection(contour->GetOutputPort());
  edges->BoundaryEdgesOn();
  edges->NonManifoldEdgesOn();
  edges->FeatureEdgesOff();
  edges->ManifoldEdgesOff();
  vtkNew<vtkPolyDataConnectivityFilter> regions;
  regions->SetInputConnection(contour->GetOutputPort());
  regions->SetExtractionModeToAllRegions();

  source->UpdateInformation();
  vtkInformation* info = source->GetOutputInformation(0);
  const int count = info->Length(vtkStreamingDemandDrivenPipeline::TIME_STEPS());
  const double* steps = info->Get(vtkStreamingDemandDrivenPipeline::TIME_STEPS());
  int minRegions = VTK_INT_MAX;
  int maxRegions = 0;
  double extent = 0.0;
  int open = 0;
  int empty = 0;
  for (int k = 0; k < count; ++k)
  {
    const double t = steps[k];
    edges->UpdateTimeStep(t);
    regions->UpdateTimeStep(t);
    vtkPolyData* surface = contour->GetOutput();
    if (surface->GetNumberOfPolys() == 0)
    {
      ++empty;
      continue;
    }
    double bounds[6];
    surface->GetBounds(bounds);
    for (double b : bounds)
    {
      extent = std::max(extent, std::abs(b));
    }
    if (edges->GetOutput()->GetNumberOfCells() > 0)
    {
      ++open;
    }
    const int n = regions->GetNumberOfExtractedRegions();
    minRegions = std::min(minRegions, n);
    maxRegions = std::max(maxRegions, n);
  }
  std::cout << "over " << count << " steps: regions " << minRegions << ".." << maxRegions
            << ", largest |coordinate| " << extent << "\n";
  Check(empty == 0, std::to_string(empty) + " time steps have an empty surface");
  Check(open == 0, std::to_string(open) + " time steps have an open surface");
  Check(extent <= 0.8, "the surface leaves [-0.8,0.8]^3 (" + std::to_string(extent) + ")");
  Check(minRegions == 1 && maxRegions > 1, "the blobs do not both merge and split");
}
}

int main()
{
  TestTimeInformation();
  TestContourOverTime();
  TestPieces();
  TestShapeOverPeriod();
  if (Failures)
  {
    std::cerr << Failures << " check(s) failed\n";
    return EXIT_FAILURE;
  }
  std::cout << "all metaballs source checks passed\n";
  return EXIT_SUCCESS;
}
