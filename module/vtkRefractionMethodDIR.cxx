#include "vtkRefractionMethodDIR.h"

#include "vtkObjectFactory.h"
#include "vtkRefractionPass.h"
#include "vtkShaderProgram.h"

#include "rfShaders.h"

vtkStandardNewMacro(vtkRefractionMethodDIR);

//------------------------------------------------------------------------------
void vtkRefractionMethodDIR::AppendDefines(std::ostream& defines, vtkRefractionPass* settings) const
{
  this->Superclass::AppendDefines(defines, settings);
  if (settings->GetAdaptiveSearch())
  {
    defines << "#define RF_ADAPTIVE_SEARCH\n";
  }
  else
  {
    // One count for every pixel: the search's loop gets a constant bound (rf_kernel_dir.h,
    // RF_KERNEL_SEARCH_LOOP_STEPS), and a change of SearchSteps builds the program again.
    defines << "#define RF_FIXED_SEARCH_STEPS " << settings->GetSearchSteps() << "\n";
  }
  if (settings->GetSecantRefinement())
  {
    defines << "#define RF_SECANT_REFINE\n";
  }
  if (settings->GetDepthRangeMode() == vtkRefractionPass::DEPTH_RANGE_BOUNDS)
  {
    defines << "#define RF_DEPTH_RANGE_BOUNDS\n";
  }
  if (settings->GetTIRBounces() > 0)
  {
    defines << "#define RF_TIR_BOUNCES " << settings->GetTIRBounces() << "\n";
  }
  if (settings->GetExitReflection() && settings->GetFresnel())
  {
    defines << "#define RF_EXIT_REFLECTION\n";
  }
}

//------------------------------------------------------------------------------
std::string vtkRefractionMethodDIR::GetShaderSource() const
{
  return std::string(rfBackSurfaceSource) + rfMethodDIRSource;
}

//------------------------------------------------------------------------------
void vtkRefractionMethodDIR::SetUniforms(
  vtkShaderProgram* program, vtkRefractionPass* settings, const double boundsDepthRange[2]) const
{
  if (program->IsUniformUsed("rfSearchSteps"))
  {
    program->SetUniformi("rfSearchSteps", settings->GetSearchSteps());
  }
  if (program->IsUniformUsed("rfDepthRangeBounds"))
  {
    const float range[2] = { static_cast<float>(boundsDepthRange[0]),
      static_cast<float>(boundsDepthRange[1]) };
    program->SetUniform2f("rfDepthRangeBounds", range);
  }
}
