#include "vtkWaveEquationSource.h"

#include "vtkDataObject.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkSMPTools.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <algorithm>
#include <cmath>
#include <utility>

vtkStandardNewMacro(vtkWaveEquationSource);

namespace
{
// Off the centre and off each other's symmetry planes, so that the reflected shells cross at
// different times rather than all focusing back on one point.
constexpr double PulseCenters[4][3] = { { -0.38, -0.22, 0.10 }, { 0.36, 0.18, -0.12 },
  { 0.04, 0.42, 0.30 }, { -0.05, -0.40, -0.36 } };

// Half the 3D CFL limit of the leapfrog scheme (c dt / h <= 1/sqrt(3)): well inside the
// stable range, and the dispersion error stays small at the default resolution.
constexpr double CourantSafety = 0.5;

// Report progress about this often (in steps) during long integrations.
constexpr int ProgressInterval = 16;
}

//------------------------------------------------------------------------------
vtkWaveEquationSource::vtkWaveEquationSource()
  : SampleDimensions(48)
  , WaveSpeed(1.0)
  , NumberOfPulses(3)
  , PulseWidth(0.15)
  , NumberOfTimeSteps(60)
  , EndTime(2.0)
  , IsoValue(0.08)
  , StepsFromStart(0)
{
  this->SetNumberOfInputPorts(0);
}

//------------------------------------------------------------------------------
double vtkWaveEquationSource::StepLength() const
{
  const double spacing = 2.0 / (this->SampleDimensions - 1);
  const double stable = CourantSafety * spacing / (this->WaveSpeed * std::sqrt(3.0));
  const double interval = this->EndTime / (this->NumberOfTimeSteps - 1);
  const double substeps = std::ceil(interval / stable);
  return interval / substeps;
}

//------------------------------------------------------------------------------
void vtkWaveEquationSource::Restart(double dt)
{
  const int n = this->SampleDimensions;
  const double spacing = 2.0 / (n - 1);
  const size_t count = static_cast<size_t>(n) * n * n;
  this->Current.assign(count, 0.0f);
  const double twoSigma2 = 2.0 * this->PulseWidth * this->PulseWidth;
  // Interior points only: the walls hold u = 0 from the start.
  for (int k = 1; k < n - 1; ++k)
  {
    const double z = -1.0 + spacing * k;
    for (int j = 1; j < n - 1; ++j)
    {
      const double y = -1.0 + spacing * j;
      for (int i = 1; i < n - 1; ++i)
      {
        const double x = -1.0 + spacing * i;
        double u = 0.0;
        for (int p = 0; p < this->NumberOfPulses; ++p)
        {
          const double dx = x - PulseCenters[p][0];
          const double dy = y - PulseCenters[p][1];
          const double dz = z - PulseCenters[p][2];
          u += std::exp(-(dx * dx + dy * dy + dz * dz) / twoSigma2);
        }
        this->Current[(static_cast<size_t>(k) * n + j) * n + i] = static_cast<float>(u);
      }
    }
  }
  // At rest at t = 0: the step "before" the start mirrors the first step,
  // u(-dt) = u(0) + (c dt)^2 / 2 laplace(u(0)), so the leapfrog starts with zero velocity.
  this->Previous = this->Current;
  const double courant = this->WaveSpeed * dt / spacing;
  const double halfC2 = 0.5 * courant * courant;
  const size_t sj = static_cast<size_t>(n);
  const size_t sk = static_cast<size_t>(n) * n;
  for (int k = 1; k < n - 1; ++k)
  {
    for (int j = 1; j < n - 1; ++j)
    {
      for (int i = 1; i < n - 1; ++i)
      {
        const size_t c = (static_cast<size_t>(k) * n + j) * n + i;
        const double laplacian = this->Current[c - 1] + this->Current[c + 1] +
          this->Current[c - sj] + this->Current[c + sj] + this->Current[c - sk] +
          this->Current[c + sk] - 6.0 * this->Current[c];
        this->Previous[c] = static_cast<float>(this->Current[c] + halfC2 * laplacian);
      }
    }
  }
  this->StepsFromStart = 0;
  this->StateTime = this->GetMTime();
}

//------------------------------------------------------------------------------
void vtkWaveEquationSource::Step(double courantSquared)
{
  const int n = this->SampleDimensions;
  const vtkIdType sj = n;
  const vtkIdType sk = static_cast<vtkIdType>(n) * n;
  const float* u = this->Current.data();
  float* previous = this->Previous.data();
  const float c2 = static_cast<float>(courantSquared);
  // u(t+dt) = 2 u(t) - u(t-dt) + (c dt/h)^2 laplace(u(t)), written over u(t-dt), which no
  // other point reads.
  vtkSMPTools::For(1, n - 1, [&](vtkIdType kBegin, vtkIdType kEnd) {
    for (vtkIdType k = kBegin; k < kEnd; ++k)
    {
      for (vtkIdType j = 1; j < n - 1; ++j)
      {
        vtkIdType c = (k * n + j) * n + 1;
        for (vtkIdType i = 1; i < n - 1; ++i, ++c)
        {
          const float laplacian =
            u[c - 1] + u[c + 1] + u[c - sj] + u[c + sj] + u[c - sk] + u[c + sk] - 6.0f * u[c];
          previous[c] = 2.0f * u[c] - previous[c] + c2 * laplacian;
        }
      }
    }
  });
  std::swap(this->Previous, this->Current);
  ++this->StepsFromStart;
}

//------------------------------------------------------------------------------
int vtkWaveEquationSource::RequestInformation(vtkInformation* vtkNotUsed(request),
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

  std::vector<double> steps(static_cast<size_t>(this->NumberOfTimeSteps));
  for (int k = 0; k < this->NumberOfTimeSteps; ++k)
  {
    steps[k] = this->EndTime * k / (this->NumberOfTimeSteps - 1);
  }
  outInfo->Set(
    vtkStreamingDemandDrivenPipeline::TIME_STEPS(), steps.data(), this->NumberOfTimeSteps);
  double range[2] = { 0.0, this->EndTime };
  outInfo->Set(vtkStreamingDemandDrivenPipeline::TIME_RANGE(), range, 2);
  return 1;
}

//------------------------------------------------------------------------------
int vtkWaveEquationSource::RequestData(vtkInformation* vtkNotUsed(request),
  vtkInformationVector** vtkNotUsed(inputVector), vtkInformationVector* outputVector)
{
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  vtkImageData* output = vtkImageData::GetData(outInfo);
  if (!output)
  {
    vtkErrorMacro("Output is not a vtkImageData.");
    return 0;
  }
  double time = outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP())
    ? outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP())
    : 0.0;
  if (!std::isfinite(time) || time < 0.0)
  {
    vtkWarningMacro("Time " << time << " is outside [0, EndTime]; using 0.");
    time = 0.0;
  }

  const double dt = this->StepLength();
  const double spacing = 2.0 / (this->SampleDimensions - 1);
  const double courant = this->WaveSpeed * dt / spacing;
  const long target = std::lround(time / dt);
  const size_t count = static_cast<size_t>(this->SampleDimensions) *
    this->SampleDimensions * this->SampleDimensions;
  if (this->Current.size() != count || this->GetMTime() > this->StateTime ||
    target < this->StepsFromStart)
  {
    this->Restart(dt);
  }
  const long todo = target - this->StepsFromStart;
  this->UpdateProgress(0.0);
  for (long s = 0; s < todo && !this->GetAbortExecute(); ++s)
  {
    this->Step(courant * courant);
    if (s % ProgressInterval == 0)
    {
      this->UpdateProgress(static_cast<double>(s) / todo);
    }
  }
  this->UpdateProgress(1.0);

  const int n = this->SampleDimensions;
  output->SetExtent(0, n - 1, 0, n - 1, 0, n - 1);
  output->SetSpacing(spacing, spacing, spacing);
  output->SetOrigin(-1.0, -1.0, -1.0);
  vtkNew<vtkFloatArray> field;
  field->SetName("u");
  field->SetNumberOfTuples(static_cast<vtkIdType>(count));
  std::copy(this->Current.begin(), this->Current.end(), field->GetPointer(0));
  output->GetPointData()->SetScalars(field);
  output->GetInformation()->Set(vtkDataObject::DATA_TIME_STEP(), this->StepsFromStart * dt);
  return 1;
}

//------------------------------------------------------------------------------
void vtkWaveEquationSource::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "SampleDimensions: " << this->SampleDimensions << "\n";
  os << indent << "WaveSpeed: " << this->WaveSpeed << "\n";
  os << indent << "NumberOfPulses: " << this->NumberOfPulses << "\n";
  os << indent << "PulseWidth: " << this->PulseWidth << "\n";
  os << indent << "NumberOfTimeSteps: " << this->NumberOfTimeSteps << "\n";
  os << indent << "EndTime: " << this->EndTime << "\n";
  os << indent << "IsoValue: " << this->IsoValue << "\n";
  os << indent << "StepsFromStart: " << this->StepsFromStart << "\n";
}
