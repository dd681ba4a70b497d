//VTK::System::Dec
// Coarse shading (vtkRefractionPass::SetCoarseShading): the depth buffer that culls the rays of
// the 2x2 blocks. Texel k stands for the block whose lower-left pixel 2k is traced; it gets
// that pixel's front depth (1 where it holds no glass), so that the blocks' shading test,
// GL_GREATER at the far plane, passes at the blocks that trace glass and nowhere else
// (rfShadeFS.glsl, RF_COARSE_SAMPLES; vtkRefractionShadeStage::DrawCoarseSamples).
in vec2 texCoord;
uniform sampler2D rfFrontDepth;
uniform vec2 rfSize; // the coarse targets' size in texels
//VTK::Output::Dec
void main()
{
  gl_FragDepth = texelFetch(rfFrontDepth, 2 * ivec2(texCoord * rfSize), 0).r;
}
