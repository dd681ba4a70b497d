//VTK::System::Dec
// PEEL: the depths (-z_view, 0 where empty) of the K layers, four to a texel, so that the ray
// march reads one texel (two for K > 4) per step instead of one per layer (rfMethodPEEL.glsl).
// Layer 0 is the front G-buffer, layers 1 .. K-1 the peeled ones (rfGeometryFS.glsl, stage 4);
// each keeps its depth in z. Defines: RF_PEEL_LAYERS (K). Layers from rfLayersFound on were
// not drawn this frame (peeling stopped at an empty one): written empty.
in vec2 texCoord;
uniform sampler2D rfLayer0;
uniform sampler2D rfLayer1;
uniform int rfLayersFound;
#if RF_PEEL_LAYERS > 2
uniform sampler2D rfLayer2;
#endif
#if RF_PEEL_LAYERS > 3
uniform sampler2D rfLayer3;
#endif
#if RF_PEEL_LAYERS > 4
uniform sampler2D rfLayer4;
#endif
#if RF_PEEL_LAYERS > 5
uniform sampler2D rfLayer5;
#endif
#if RF_PEEL_LAYERS > 6
uniform sampler2D rfLayer6;
#endif
#if RF_PEEL_LAYERS > 7
uniform sampler2D rfLayer7;
#endif
//VTK::Output::Dec
void main()
{
  ivec2 texel = ivec2(texCoord * vec2(textureSize(rfLayer0, 0)));
  vec4 first = vec4(0.0);
  first.x = texelFetch(rfLayer0, texel, 0).z;
  first.y = 1 < rfLayersFound ? texelFetch(rfLayer1, texel, 0).z : 0.0;
#if RF_PEEL_LAYERS > 2
  first.z = 2 < rfLayersFound ? texelFetch(rfLayer2, texel, 0).z : 0.0;
#endif
#if RF_PEEL_LAYERS > 3
  first.w = 3 < rfLayersFound ? texelFetch(rfLayer3, texel, 0).z : 0.0;
#endif
  gl_FragData[0] = first;
#if RF_PEEL_LAYERS > 4
  vec4 second = vec4(0.0);
  second.x = 4 < rfLayersFound ? texelFetch(rfLayer4, texel, 0).z : 0.0;
#if RF_PEEL_LAYERS > 5
  second.y = 5 < rfLayersFound ? texelFetch(rfLayer5, texel, 0).z : 0.0;
#endif
#if RF_PEEL_LAYERS > 6
  second.z = 6 < rfLayersFound ? texelFetch(rfLayer6, texel, 0).z : 0.0;
#endif
#if RF_PEEL_LAYERS > 7
  second.w = 7 < rfLayersFound ? texelFetch(rfLayer7, texel, 0).z : 0.0;
#endif
  gl_FragData[1] = second;
#endif
}
