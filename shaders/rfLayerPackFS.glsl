//VTK::System::Dec
// PEEL: the depths (-z_view, 0 where empty) of the K layers, four to a texel, so that the ray
// march reads one texel (two for K > 4) per step instead of one per layer (rfMethodPEEL.glsl).
// Read from the stack of the layers found this frame (vtkRefractionTargets::PEEL_STACK: layer k
// at rfLayerOrigins[2k], [2k + 1], each rfLayerSize), where each layer texel keeps its depth in
// z (rfGeometryFS.glsl): one fetch per layer found. The layers from RF_PEEL_LAYERS_FOUND on
// were not drawn this frame (peeling stopped at an empty one): written empty.
// Defines: RF_PEEL_LAYERS (K), RF_PEEL_LAYERS_FOUND (1..K). The count found is a constant so
// that the loop is unrolled to exactly the layers found: bounded by min(a uniform count, K),
// it was unrolled K times under a mask and llvmpipe fetched all K layers (vtkRefractionLayerPack).
in vec2 texCoord;
uniform sampler2D rfStack;
uniform ivec2 rfLayerSize;
uniform int rfLayerOrigins[2 * RF_PEEL_LAYERS_FOUND];
//VTK::Output::Dec
void main()
{
  ivec2 texel = ivec2(texCoord * vec2(rfLayerSize));
  vec4 first = vec4(0.0);
  vec4 second = vec4(0.0);
  for (int layer = 0; layer < RF_PEEL_LAYERS_FOUND; ++layer)
  {
    ivec2 origin = ivec2(rfLayerOrigins[2 * layer], rfLayerOrigins[2 * layer + 1]);
    float depth = texelFetch(rfStack, texel + origin, 0).z;
    if (layer < 4)
    {
      first[layer] = depth;
    }
    else
    {
      second[layer - 4] = depth;
    }
  }
  gl_FragData[0] = first;
#if RF_PEEL_LAYERS > 4
  gl_FragData[1] = second;
#endif
}
