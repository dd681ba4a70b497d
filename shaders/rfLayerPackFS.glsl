//VTK::System::Dec
// PEEL: the depths (-z_view, 0 where empty) of the K layers, four to a texel, so that the ray
// march reads one texel (two for K > 4) per step instead of one per layer (rfMethodPEEL.glsl).
// Read from the stack of the layers found this frame (vtkRefractionTargets::PEEL_STACK: layer k
// at column k % columns, row k / columns, each rfLayerSize), where each layer texel keeps its
// depth in z (rfGeometryFS.glsl): one fetch per layer found, in a loop that ends with them
// (through a sampler per layer every layer's was fetched). The layers from rfLayersFound on
// were not drawn this frame (peeling stopped at an empty one): written empty.
// Defines: RF_PEEL_LAYERS (K).
in vec2 texCoord;
uniform sampler2D rfStack;
uniform ivec2 rfLayerSize;
uniform int rfLayersFound;
//VTK::Output::Dec
void main()
{
  ivec2 texel = ivec2(texCoord * vec2(rfLayerSize));
  int columns = max(textureSize(rfStack, 0).x / rfLayerSize.x, 1);
  vec4 first = vec4(0.0);
  vec4 second = vec4(0.0);
  int found = min(rfLayersFound, RF_PEEL_LAYERS);
  for (int layer = 0; layer < found; ++layer)
  {
    float depth =
      texelFetch(rfStack, texel + rfLayerSize * ivec2(layer % columns, layer / columns), 0).z;
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
