// PEEL, Chi, Wang & Hu (seed 004): the ray followed through K depth-peeled layers of all the
// glass (layer 0 is the front G-buffer, layers 1 .. K-1 the peeled ones), across every
// interface they hold, nested and overlapping glass included: rfk_peel_trace of the kernel
// (module/core/kernel/rf_kernel_peel.h, the same source the C core and its tests run). This
// file provides the two lookups the kernel leaves to the stage (rfKernelPrelude.glsl).
// Defines: RF_PEEL_LAYERS (K), RF_PEEL_BOUNCES (B, total internal reflections followed).
#if RF_PEEL_LAYERS > 1
uniform sampler2D rfPeel1;
#endif
#if RF_PEEL_LAYERS > 2
uniform sampler2D rfPeel2;
#endif
#if RF_PEEL_LAYERS > 3
uniform sampler2D rfPeel3;
#endif
#if RF_PEEL_LAYERS > 4
uniform sampler2D rfPeel4;
#endif
#if RF_PEEL_LAYERS > 5
uniform sampler2D rfPeel5;
#endif
#if RF_PEEL_LAYERS > 6
uniform sampler2D rfPeel6;
#endif
#if RF_PEEL_LAYERS > 7
uniform sampler2D rfPeel7;
#endif
// The longest segment a ray is searched along: the diagonal of all the glass's bounds.
uniform float rfGlassExtent;

vec4 rfPeelLayerTexel(ivec2 texel, int layer)
{
  // The front G-buffer's material (w) is positive: the nearest surface faces the viewer.
  if (layer == 0)
  {
    return texelFetch(rfFrontSurface, texel, 0);
  }
#if RF_PEEL_LAYERS > 1
  if (layer == 1)
  {
    return texelFetch(rfPeel1, texel, 0);
  }
#endif
#if RF_PEEL_LAYERS > 2
  if (layer == 2)
  {
    return texelFetch(rfPeel2, texel, 0);
  }
#endif
#if RF_PEEL_LAYERS > 3
  if (layer == 3)
  {
    return texelFetch(rfPeel3, texel, 0);
  }
#endif
#if RF_PEEL_LAYERS > 4
  if (layer == 4)
  {
    return texelFetch(rfPeel4, texel, 0);
  }
#endif
#if RF_PEEL_LAYERS > 5
  if (layer == 5)
  {
    return texelFetch(rfPeel5, texel, 0);
  }
#endif
#if RF_PEEL_LAYERS > 6
  if (layer == 6)
  {
    return texelFetch(rfPeel6, texel, 0);
  }
#endif
#if RF_PEEL_LAYERS > 7
  if (layer == 7)
  {
    return texelFetch(rfPeel7, texel, 0);
  }
#endif
  return vec4(0.0);
}

float rfPeelMaterialIOR(int material, int channel)
{
  return rfMaterialIndexOfRefraction(clamp(material, 0, RF_MAX_MATERIALS - 1), channel);
}

bool rfPeelMaterialSheet(int material)
{
  return rfMaterialSheet[clamp(material, 0, RF_MAX_MATERIALS - 1)] > 0.0;
}

// The trace from the front surface; returns the bounces (+ 16 when TIR ended it).
int rfPeelTrace(vec3 P1, vec3 T1, int material, int channel, out vec3 P2, out vec3 T2,
  out float insideLength)
{
  return rfk_peel_trace(0, RF_PEEL_LAYERS, channel, rfCamera(), P1, T1, material,
    RF_PEEL_LAYERS - 1 + RF_PEEL_BOUNCES, RF_PEEL_BOUNCES, RF_TIR_POLICY, rfGlassExtent, P2, T2,
    insideLength);
}

float rfFresnelWeight(float cosIncident, float etaIn)
{
  return rfk_fresnel_dielectric(cosIncident, etaIn);
}

vec3 rfTransmittedColour(vec2 own, vec3 N1, vec3 T1, vec3 P2, vec3 T2)
{
  return rfBehind(P2, T2);
}
