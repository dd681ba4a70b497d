// The SH method (Genevaux et al., seed 003), per vertex of the glass: the direction in which
// the light seen along the view direction leaves the glass, and the length it travels inside,
// evaluated from the vertex's spherical-harmonic coefficients (vtkSHTransferFilter's
// "SHTransfer": rfk_sh_evaluate of the kernel, module/core/kernel/rf_kernel_sh.h) for the
// current view direction, in model coordinates, and handed to the fragment stage in view
// coordinates. Injected into VTK's polydata vertex shader by vtkRefractionGeometryStage: the
// part before the RF::Impl marker after VTK's Normal Dec tag, the rest after its Normal Impl
// tag (the tags' own text must not appear here: VTK replaces it wherever it is). The
// coefficients are a texture of RGBA texels (x, y, z, length), one
// per coefficient, point-major; rfSHVertex is the point's index.
in float rfSHVertex;
out vec4 rfSHExitVSOut;
uniform sampler2D rfSHCoefficients;
uniform int rfSHCount;
uniform int rfSHOrder;
uniform vec3 rfSHEyeMC;
uniform vec3 rfSHDirectionMC;
uniform int rfSHParallel;
uniform mat3 rfSHModelToView;
uniform float rfSHLengthScale;

vec4 rfSHCoefficient(int i)
{
  int width = textureSize(rfSHCoefficients, 0).x;
  return texelFetch(rfSHCoefficients, ivec2(i % width, i / width), 0);
}

#define RF_SH_TABLE
#define rf_sh_coefficient(table, i) rfSHCoefficient(i)[table]
//RF::Kernel

//RF::Impl
  {
    vec3 rfView = rfSHParallel == 1 ? rfSHDirectionMC : normalize(vertexMC.xyz / vertexMC.w - rfSHEyeMC);
    int rfBase = int(rfSHVertex + 0.5) * rfSHCount;
    vec3 rfExit = vec3(rfk_sh_evaluate(0, rfBase, rfSHOrder, rfView),
      rfk_sh_evaluate(1, rfBase, rfSHOrder, rfView), rfk_sh_evaluate(2, rfBase, rfSHOrder, rfView));
    float rfLength = rfk_sh_evaluate(3, rfBase, rfSHOrder, rfView);
    vec3 rfExitVC = rfSHModelToView * rfExit;
    rfSHExitVSOut = vec4(dot(rfExitVC, rfExitVC) > 0.0 ? normalize(rfExitVC) : vec3(0.0),
      max(rfLength, 0.0) * rfSHLengthScale);
  }
