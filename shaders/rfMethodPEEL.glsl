// PEEL, Chi, Wang & Hu (seed 004): the ray followed through K depth-peeled layers of all the
// glass (layer 0 is the front G-buffer, layers 1 .. K-1 the peeled ones), across every
// interface they hold, nested and overlapping glass included: rfk_peel_trace of the kernel
// (module/core/kernel/rf_kernel_peel.h, the same source the C core and its tests run). This
// file provides the lookups the kernel leaves to the stage (rfKernelPrelude.glsl).
// Defines: RF_PEEL_LAYERS (K), RF_PEEL_BOUNCES (B, total internal reflections followed).
// The K layers' texels side by side (vtkRefractionTargets::PEEL_STACK): layer k at column
// k % columns, row k / columns of layers, each the size of the front G-buffer.
uniform sampler2D rfPeelStack;
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
  // One fetch whatever the layer: read through a sampler per layer, llvmpipe ran every
  // layer's branch, K fetches at each of the five texels a crossing reads (its own and the
  // normal filter's four).
  ivec2 size = textureSize(rfFrontSurface, 0);
  int columns = textureSize(rfPeelStack, 0).x / size.x;
  int place = clamp(layer, 0, RF_PEEL_LAYERS - 1);
  vec4 stored =
    texelFetch(rfPeelStack, texel + size * ivec2(place % columns, place / columns), 0);
  return layer >= 0 && layer < rfPeelLayersFound ? stored : vec4(0.0);
}

// The depth of one layer at a texel, from the depths packed four to a texel: one fetch, where
// rfPeelLayerTexel reads the whole texel. The packing wrote the layers not drawn this frame as
// empty, as rfPeelLayerTexel reads them.
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

// The share the first refracting interface reflects (Fresnel), from where it turns back to
// where it leaves, estimated without a search as DIR's exit reflection does (rfReflectedExit):
// one chord on (inside a sphere every chord of a reflected ray is as long as the one before),
// moved onto the depth of the layer nearest there, refracted out through that layer's normal
// (turned as rfk_chord_symmetric_normal says where that layer is the glass the split left).
// Marched through the layers like the main ray, it took about 40 % of PEEL's shading on
// llvmpipe. False where the estimate leaves the image or finds no layer.
bool rfPeelReflectedExit(rfk_peel_ray branch, int channel, out vec3 exitP, out vec3 exitT)
{
  exitP = branch.P;
  exitT = branch.T;
  if (rfk_peel_stack_top(branch.stack) < 0)
  {
    return true; // reflected off glass from outside: it leaves from there
  }
  exitP += branch.chord * branch.T;
  vec2 tc;
  if (!rfk_peel_on_image(rfCamera(), exitP, tc))
  {
    return false;
  }
  float depth = -exitP.z;
  // The texel under the estimate, else the nearest other of the 2 x 2 around it that holds a
  // layer: a chord's end near the silhouette can project just past the mesh's rasterized
  // coverage (the polygons lie inside the surface they sample), and reading that one texel
  // alone lost the branch in a dotted ring of pixels.
  ivec2 own = rfTexelOf(tc);
  vec2 within = tc * rfViewport.zw - vec2(own) - 0.5;
  ivec2 toward = ivec2(within.x < 0.0 ? -1 : 1, within.y < 0.0 ? -1 : 1);
  bool acrossFirst = abs(within.x) >= abs(within.y);
  ivec2 texel = own;
  int nearest = -1;
  for (int candidate = 0; candidate < 4 && nearest < 0; ++candidate)
  {
    ivec2 offset = candidate == 0 ? ivec2(0)
      : candidate == 1 ? (acrossFirst ? ivec2(toward.x, 0) : ivec2(0, toward.y))
      : candidate == 2 ? (acrossFirst ? ivec2(0, toward.y) : ivec2(toward.x, 0))
                       : toward;
    texel = clamp(own + offset, ivec2(0), ivec2(rfViewport.zw) - 1);
    float nearestGap = 0.0;
    // The packed depths read once for all the layers (unused channels hold 0).
    vec4 depthsA = texelFetch(rfPeelDepthsA, texel, 0);
#if RF_PEEL_LAYERS > 4
    vec4 depthsB = texelFetch(rfPeelDepthsB, texel, 0);
#endif
    for (int layer = 0; layer < RF_PEEL_LAYERS; ++layer)
    {
#if RF_PEEL_LAYERS > 4
      float layerDepth = layer < 4 ? depthsA[layer & 3] : depthsB[layer & 3];
#else
      float layerDepth = depthsA[layer & 3];
#endif
      if (layerDepth > 0.0 && (nearest < 0 || abs(layerDepth - depth) < nearestGap))
      {
        nearest = layer;
        nearestGap = abs(layerDepth - depth);
      }
    }
  }
  if (nearest < 0)
  {
    return false;
  }
  vec4 surface = rfPeelLayerTexel(texel, nearest);
  exitP = rfStepOntoSurface(exitP, branch.T, depth - surface.z, branch.chord);
  vec3 towardViewer = rf_oct_decode(surface.xy);
  vec3 outward = surface.w < 0.0 ? -towardViewer : towardViewer;
  // The branch is inside its glass: it leaves through whatever surface it meets.
  outward = dot(outward, branch.T) < 0.0 ? -outward : outward;
  int crossed = int(abs(surface.w) + 0.5) - 1;
  if (rfPeelMaterialSheet(crossed))
  {
    return true;
  }
  int inside = rfk_peel_stack_top(branch.stack);
  if (branch.splitCos > 0.0 && crossed == inside)
  {
    // Back to the glass it turned from: a layer's normal one chord on, near the rim, reflected
    // totally and speckled as DIR's did; the chord meets it at the angle it met the exit.
    outward = rfk_chord_symmetric_normal(branch.T, outward, branch.splitCos);
  }
  int beyond = rfk_peel_stack_pop(branch.stack);
  float eta = rfk_peel_medium_ior(channel, branch.stack) / rfk_peel_medium_ior(channel, beyond);
  rfRefractWithPolicy(branch.T, outward, eta, exitT);
  return true;
}

// The trace from the front surface: the ray's exit (P2, T2), the length it travelled inside,
// and, with `split`, the ray the first refracting interface reflects (Fresnel) and its share,
// to where it leaves (branchP, branchT; branchWeight 0 when nothing split). Returns the
// bounces (+ 16 when TIR ended the trace).
int rfPeelTrace(vec3 P1, vec3 T1, int material, int channel, bool split, out vec3 P2,
  out vec3 T2, out float insideLength, out vec3 branchP, out vec3 branchT, out float branchWeight)
{
  int interfaces = rfk_peel_interfaces(RF_PEEL_LAYERS, RF_PEEL_BOUNCES);
  rfk_peel_ray ray = rfk_peel_entered(P1, T1, material);
  rfk_peel_ray branch;
  // The layers that hold glass this frame (rfk_peel_may_meet_more); the others read as empty.
  // Peeling that found all K may have left more behind them.
  int count = min(RF_PEEL_LAYERS, rfPeelLayersFound);
  bool capped = rfPeelLayersFound >= RF_PEEL_LAYERS;
  rfk_peel_follow(0, count, capped, channel, rfCamera(), ray, interfaces, RF_PEEL_BOUNCES,
    RF_TIR_POLICY, rfGlassExtent, rfGlassDepthRange, split, branch, branchWeight);
  P2 = ray.P;
  T2 = ray.T;
  insideLength = ray.travelled;
  branchP = P2;
  branchT = T2;
  if (branchWeight > 0.0 && !rfPeelReflectedExit(branch, channel, branchP, branchT))
  {
    branchWeight = 0.0;
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
