#include "vtkMetaballsSource.h"

#include "vtkDataObject.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkSMPTools.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <cmath>
#include <vector>

vtkStandardNewMacro(vtkMetaballsSource);

namespace
{
// Keeps the field finite when a grid point coincides with a ball centre; far
// below the grid spacing squared, so it does not change the surface.
constexpr double FieldEpsilon = 1.0e-6;

// Tuned together with the default radius: fully extended, the four default
// balls are 1.22 apart, enough to be separate blobs (with the inverse-square
// tails of all four adding up they separate only beyond about 1.0), while the
// surface reaches 0.77 at most, inside [-0.8,0.8]^3.
constexpr double ExtendedDistance = 0.75;
constexpr double SwirlRadius = 0.15;
}

//------------------------------------------------------------------------------
vtkMetaballsSource::vtkMetaballsSource()
  : SampleDimensions(48)
  , NumberOfBalls(4)
  , NumberOfTimeSteps(60)
  , TimePeriod(1.0)
  , BallRadius(0.30)
  , IsoValue(1.0)
{
  this->SetNumberOfInputPorts(0);
}

//------------------------------------------------------------------------------
void vtkMetaballsSource::ComputeBallCenter(int ball, double time, double center[3]) const
{
  // One period of the motion is one turn of the phase angle; every term below
  // uses an integer multiple of it, which makes the motion periodic.
  const double tau = 2.0 * vtkMath::Pi() * time / this->TimePeriod;

  // The box is tightest along the axes, so balls leave the group along the
  // cube diagonals, where there is most room; the first four take alternate
  // corners (a tetrahedron) so that they are as far apart as possible when
  // they split.
  static const double corners[8][3] = { { 1, 1, 1 }, { 1, -1, -1 }, { -1, 1, -1 },
    { -1, -1, 1 }, { -1, -1, -1 }, { -1, 1, 1 }, { 1, -1, 1 }, { 1, 1, -1 } };
  const double* corner = corners[ball % 8];
  const double s3 = 1.0 / std::sqrt(3.0);
  const double dir[3] = { corner[0] * s3, corner[1] * s3, corner[2] * s3 };
  // An orbit plane perpendicular to the diagonal (no corner is parallel to z).
  double u[3] = { dir[1], -dir[0], 0.0 };
  vtkMath::Normalize(u);
  double v[3];
  vtkMath::Cross(dir, u, v);

  // Extension goes 0 -> 1 -> 0 once a period: at 0 the balls swirl around
  // each other as one blob, at 1 they sit out towards the corners as separate
  // blobs. A small stagger makes them leave and rejoin one after another
  // rather than in lockstep; balls beyond the eighth move in counter-phase.
  const double stagger = 2.0 * vtkMath::Pi() * (0.07 * ball + (ball >= 8 ? 0.5 : 0.0));
  const double extension = 0.5 - 0.5 * std::cos(tau + stagger);
  // Opposite spins and different speeds keep the merged blob churning.
  const double spin = (ball % 2 == 0 ? 1.0 : -1.0) * (2 + ball % 3);
  const double angle = spin * tau + 2.0 * vtkMath::Pi() * ball / 8.0;
  const double reach = ExtendedDistance * extension;
  const double swirl = SwirlRadius * (1.0 - extension);
  for (int c = 0; c < 3; ++c)
  {
    center[c] = reach * dir[c] + swirl * (std::cos(angle) * u[c] + std::sin(angle) * v[c]);
  }
}

//------------------------------------------------------------------------------
int vtkMetaballsSource::RequestInformation(vtkInformation* vtkNotUsed(request),
  vtkInformationVector** vtkNotUsed(inputVector), vtkInformationVector* outputVector)
{
  vtkInformation* outInfo = outputVector->GetInformationObject(0);

  const int n = this->SampleDimensions;
  int wholeExtent[6] = { 0, n - 1, 0, n - 1, 0, n - 1 };
  const double spacing = 2.0 / (n - 1);
  outInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), wholeExtent, 6);
  outInfo->Set(vtkDataObject::SPACING(), spacing, spacing, spacing);
  outInfo->Set(vtkDataObject::ORIGIN(), -1.0, -1.0, -1.0);
  vtkDataObject::SetPointDataActiveScalarInfo(outInfo, VTK_FLOAT, 1);
  // Each sample depends on its position only, so pieces can be computed
  // exactly on their own; without this the executive gives every piece but
  // the first an empty extent.
  outInfo->Set(CAN_PRODUCE_SUB_EXTENT(), 1);

  // The period end is left out of the steps: it is the same state as t = 0.
  std::vector<double> steps(static_cast<size_t>(this->NumberOfTimeSteps));
  for (int k = 0; k < this->NumberOfTimeSteps; ++k)
  {
    steps[k] = this->TimePeriod * k / this->NumberOfTimeSteps;
  }
  outInfo->Set(
    vtkStreamingDemandDrivenPipeline::TIME_STEPS(), steps.data(), this->NumberOfTimeSteps);
  // The field is defined at any time, so the range is the whole period.
  double range[2] = { 0.0, this->TimePeriod };
  outInfo->Set(vtkStreamingDemandDrivenPipeline::TIME_RANGE(), range, 2);
  return 1;
}

//------------------------------------------------------------------------------
int vtkMetaballsSource::RequestData(vtkInformation* vtkNotUsed(request),
  vtkInformationVector** vtkNotUsed(inputVector), vtkInformationVector* outputVector)
{
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  vtkImageData* output = vtkImageData::GetData(outInfo);
  if (!output)
  {
    vtkErrorMacro("Output is not a vtkImageData.");
    return 0;
  }

  const double time = outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP())
    ? outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP())
    : 0.0;

  // Honour a downstream request for a sub-extent (streaming, pieces); the
  // field at a point does not depend on its neighbours, so any extent works.
  const int n = this->SampleDimensions;
  int extent[6] = { 0, n - 1, 0, n - 1, 0, n - 1 };
  if (outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT()))
  {
    outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT(), extent);
  }
  const double spacing = 2.0 / (n - 1);
  output->SetExtent(extent);
  output->SetSpacing(spacing, spacing, spacing);
  output->SetOrigin(-1.0, -1.0, -1.0);

  const int nx = extent[1] - extent[0] + 1;
  const int ny = extent[3] - extent[2] + 1;
  const int nz = extent[5] - extent[4] + 1;
  vtkNew<vtkFloatArray> field;
  field->SetName("field");
  field->SetNumberOfComponents(1);
  const vtkIdType numPoints = (nx > 0 && ny > 0 && nz > 0)
    ? static_cast<vtkIdType>(nx) * static_cast<vtkIdType>(ny) * static_cast<vtkIdType>(nz)
    : 0;
  field->SetNumberOfTuples(numPoints);

  std::vector<double> centers(3 * static_cast<size_t>(this->NumberOfBalls));
  for (int b = 0; b < this->NumberOfBalls; ++b)
  {
    this->ComputeBallCenter(b, time, &centers[3 * b]);
  }
  const double r2 = this->BallRadius * this->BallRadius;
  const int numBalls = this->NumberOfBalls;
  float* values = field->GetPointer(0);

  if (numPoints > 0)
  {
    // Slices are independent, and large grids are slow enough on one thread
    // to make scrubbing through time sluggish.
    vtkSMPTools::For(0, nz, [&](vtkIdType kBegin, vtkIdType kEnd) {
      for (vtkIdType k = kBegin; k < kEnd; ++k)
      {
        const double z = -1.0 + spacing * (extent[4] + k);
        float* out = values + k * nx * ny;
        for (int j = 0; j < ny; ++j)
        {
          const double y = -1.0 + spacing * (extent[2] + j);
          for (int i = 0; i < nx; ++i)
          {
            const double x = -1.0 + spacing * (extent[0] + i);
            double sum = 0.0;
            for (int b = 0; b < numBalls; ++b)
            {
              const double dx = x - centers[3 * b];
              const double dy = y - centers[3 * b + 1];
              const double dz = z - centers[3 * b + 2];
              sum += r2 / (dx * dx + dy * dy + dz * dz + FieldEpsilon);
            }
            *out++ = static_cast<float>(sum);
          }
        }
      }
    });
  }

  output->GetPointData()->SetScalars(field);
  output->GetInformation()->Set(vtkDataObject::DATA_TIME_STEP(), time);
  return 1;
}

//------------------------------------------------------------------------------
void vtkMetaballsSource::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "SampleDimensions: " << this->SampleDimensions << "\n";
  os << indent << "NumberOfBalls: " << this->NumberOfBalls << "\n";
  os << indent << "NumberOfTimeSteps: " << this->NumberOfTimeSteps << "\n";
  os << indent << "TimePeriod: " << this->TimePeriod << "\n";
  os << indent << "BallRadius: " << this->BallRadius << "\n";
  os << indent << "IsoValue: " << this->IsoValue << "\n";
}
