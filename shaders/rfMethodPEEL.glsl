// PEEL, Chi, Wang & Hu (seed 004): the ray followed through K depth-peeled layers of all the
// glass (layer 0 is the front G-buffer, layers 1 .. K-1 the peeled ones), across every
// interface they hold, nested and overlapping glass included: rfk_peel_trace of the kernel
// (module/core/kernel/rf_kernel_peel.h, the same source the C core and its tests run). This
// file provides the lookups the kernel leaves to the stage (rfKernelPrelude.glsl).
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
uniform sampler2D rfPeelDepthsA;
#if RF_PEEL_LAYERS > 4
uniform sampler2D rfPeelDepthsB;
#endif
// The longest segment a ray is searched along: the diagonal of all the glass's bounds; and the
// depths (positive, near to far) of those bounds: no layer lies outside them.
uniform float rfGlassExtent;
uniform vec2 rfGlassDepthRange;
// Layers from rfPeelLayersFound on were not drawn this frame (peeling stopped at an empty
// one, vtkRefractionPass::GetPeelLayersFound): read as empty, whatever their targets hold.
uniform int rfPeelLayersFound;

vec4 rfPeelLayerTexel(ivec2 texel, int layer)
{
  if (layer >= rfPeelLayersFound)
  {
    return vec4(0.0);
  }
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

// The depth of one layer at a texel, from the depths packed four to a texel: one fetch, where
// rfPeelLayerTexel goes through every layer's sampler (llvmpipe runs every branch). The packing
// wrote the layers not drawn this frame as empty, as rfPeelLayerTexel reads them.
float rfPeelLayerDepth(ivec2 texel, int layer)
{
#if RF_PEEL_LAYERS > 4
  vec4 d = layer < 4 ? texelFetch(rfPeelDepthsA, texel, 0) : texelFetch(rfPeelDepthsB, texel, 0);
#else
  vec4 d = texelFetch(rfPeelDepthsA, texel, 0);
#endif
  return layer >= 0 && layer < RF_PEEL_LAYERS ? d[layer & 3] : 0.0;
}

// How many layers at a texel hold a surface nearer than depth, from the depths packed four to
// a texel (rfLayerPackFS.glsl; unused channels hold 0, which never counts).
int rfPeelLayerSide(ivec2 texel, float depth)
{
  vec4 d = texelFetch(rfPeelDepthsA, texel, 0);
  vec4 inFront = vec4(greaterThan(d, vec4(0.0))) * vec4(lessThan(d, vec4(depth)));
#if RF_PEEL_LAYERS > 4
  vec4 e = texelFetch(rfPeelDepthsB, texel, 0);
  inFront += vec4(greaterThan(e, vec4(0.0))) * vec4(lessThan(e, vec4(depth)));
#endif
  return int(dot(inFront, vec4(1.0)) + 0.5);
}

float rfPeelMaterialIOR(int material, int channel)
{
  return rfMaterialIndexOfRefraction(clamp(material, 0, RF_MAX_MATERIALS - 1), channel);
}

bool rfPeelMaterialSheet(int material)
{
  return rfMaterialSheet[clamp(material, 0, RF_MAX_MATERIALS - 1)] > 0.0;
}

// The trace from the front surface: the ray's exit (P2, T2), the length it travelled inside,
// and, with `split`, the ray the first refracting interface reflects (Fresnel) and its share,
// followed to its own exit (branchP, branchT; branchWeight 0 when nothing split). Returns the
// bounces (+ 16 when TIR ended the trace).
int rfPeelTrace(vec3 P1, vec3 T1, int material, int channel, bool split, out vec3 P2,
  out vec3 T2, out float insideLength, out vec3 branchP, out vec3 branchT, out float branchWeight)
{
  int interfaces = RF_PEEL_LAYERS - 1 + RF_PEEL_BOUNCES;
  rfk_peel_ray ray = rfk_peel_entered(P1, T1, material);
  rfk_peel_ray branch;
  rfk_peel_follow(0, RF_PEEL_LAYERS, channel, rfCamera(), ray, interfaces, RF_PEEL_BOUNCES,
    RF_TIR_POLICY, rfGlassExtent, rfGlassDepthRange, split, branch, branchWeight);
  P2 = ray.P;
  T2 = ray.T;
  insideLength = ray.travelled;
  branchP = P2;
  branchT = T2;
  if (branchWeight > 0.0)
  {
    rfk_peel_ray unused;
    float unusedWeight;
    // The reflected share is small but where TIR is near: its path is followed to the next
    // interface, and one more only where that one reflected it back inside (not beyond its
    // exit: marching on outside the glass, where the share rarely meets glass again, took a
    // fifth of a full-screen sphere's frame on llvmpipe).
    for (int followed = 0; followed < min(interfaces, 2); ++followed)
    {
      if (followed > 0 && (branch.ended || rfk_peel_stack_top(branch.stack) < 0))
      {
        break;
      }
      rfk_peel_follow(0, RF_PEEL_LAYERS, channel, rfCamera(), branch, 1, RF_PEEL_BOUNCES,
        RF_TIR_POLICY, rfGlassExtent, rfGlassDepthRange, false, unused, unusedWeight);
    }
    branchP = branch.P;
    branchT = branch.T;
  }
  return ray.reflected + (ray.ended ? 16 : 0);
}

float rfFresnelWeight(float cosIncident, float etaIn)
{
  return rfk_fresnel_dielectric(cosIncident, etaIn);
}

vec3 rfTransmittedColour(vec2 own, vec3 N1, vec3 T1, vec3 P2, vec3 T2)
{
  return rfBehind(P2, T2);
}
