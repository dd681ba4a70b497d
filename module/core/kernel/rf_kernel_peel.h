/* rf_kernel_peel.h (kernel dialect, C and GLSL): a ray followed through K depth-peeled layers
 * of the glass, Chi, Wang & Hu (seed 004): the transmitted ray is marched with a linear search
 * against the layers, each change of side is refined by bisection and a secant step, and the
 * result is told apart from a fault zone (section 3.1: a discontinuity of the peeled layers)
 * by the paper's test on the final bracket (the depth difference X of the crossed layer across
 * it must shrink below the linear step). Beyond the paper, all K layers are searched at once:
 * a ray point's side is how many layers at its texel lie in front of it, which changes exactly
 * where the ray crosses a layer, so the layers need no pairing (the paper's combination of
 * layers 2-4 and 1-3, section 3.1.2, is what this count does implicitly). Several glass actors,
 * nested or overlapping, share the layers: each texel carries its material, and the medium the
 * ray is in is kept on a small stack (entering a surface pushes its material, leaving pops), so
 * nested glass refracts by the ratio of its index to the enclosing one. Total internal
 * reflection is followed up to a number of bounces (section 3.2), then the TIR policy decides.
 *
 * A layer texel (what shaders/rfGeometryFS.glsl writes): x, y the octahedral view-space normal
 * turned toward the viewer, z the depth -z_view (0: empty), w = +-(material + 1), positive
 * where the surface's outward side faces the viewer. Layers are sorted by depth at each texel
 * (peeling makes them so) and the empty ones come last.
 *
 * Two resources GLSL cannot pass as arguments (an array of samplers, an array of indices) are
 * reached through macros the including side defines: rf_layer_texel(layers, tc, size, i),
 * rf_layer_depth(layers, tc, size, i) (its z alone: the GLSL side reads it from the depths
 * packed four to a texel, one fetch where a whole texel runs through every layer's sampler),
 * rf_layer_side(layers, count, tc, size, depth) and rf_material_ior(materials, m) /
 * rf_material_is_sheet(materials, m); in C rf_layer_stack and
 * rf_material_table are structs of callbacks and arrays (rf_kernel_prelude.h), in GLSL plain
 * handles the stage resolves (shaders/rfMethodPEEL.glsl). */
#ifndef RF_KERNEL_PEEL_H
#define RF_KERNEL_PEEL_H

#ifndef RF_GLSL
#include "rf_kernel_dir.h"
#include "rf_kernel_octahedral.h"
#include "rf_kernel_optics.h"
#include "rf_kernel_prelude.h"
#endif

#if !defined(RF_GLSL) || defined(RF_PEEL_LAYERS)

#define RF_PEEL_MAX_LAYERS 8
/* Most linear search steps per segment (the paper settles on 50 over the depth range, section
 * 4.4; here the segment is at most the glass's diagonal and within its depth range, and the
 * steps follow its length on screen) and bisections of a crossing. On the bunny at 512 px
 * (llvmpipe) 16 steps took 213 ms a frame against 299 ms for 32, and the layers tests read
 * within 0.2 dB of 32 steps. Four bisections and a secant step place a crossing as
 * closely as six bisections did (every benchmark mesh within 0.15 dB; three lost 0.24-0.51 dB
 * on the nested contours, whose layers change surface from texel to texel) for two fetches
 * fewer per crossing (docs/benchmark.md). */
#define RF_PEEL_MARCH_STEPS 16
#define RF_PEEL_MARCH_STEPS_REAL 16.0
#define RF_PEEL_MIN_STEPS_REAL 4.0
#define RF_PEEL_BISECTIONS 4
/* Glass a ray can be inside at once: materials + 1 in 7-bit fields of an int, innermost low. */
#define RF_PEEL_STACK_DEPTH 4

/* rfk_peel_next_crossing's results. */
#define RF_PEEL_NONE 0    /* no crossing before the segment's end (or the image's edge) */
#define RF_PEEL_SURFACE 1 /* a crossing of a layer */
#define RF_PEEL_EDGE 2    /* inside the glass, the ray left its footprint on screen */

/* The texture coordinates of a point given in clip coordinates, inside the image and in
 * front of the camera; false outside. */
RF_KERNEL rf_bool rfk_peel_clip_on_image(rf_float4 clip, RF_OUT(rf_float2) tc)
{
  RF_DEREF(tc) = rf_make2(0.0, 0.0);
  if (!(clip.w > 0.0))
  {
    return RF_FALSE;
  }
  rf_float2 t = rfk_texture_of_clip(clip);
  RF_DEREF(tc) = t;
  return t.x >= 0.0 && t.y >= 0.0 && t.x <= 1.0 && t.y <= 1.0;
}

/* The texture coordinates of P inside the image and in front of the camera; false outside. */
RF_KERNEL rf_bool rfk_peel_on_image(rfk_camera camera, rf_float3 P, RF_OUT(rf_float2) tc)
{
  return rfk_peel_clip_on_image(rfk_clip_of(camera, P), tc);
}

/* A ray P + t T in clip coordinates, which are linear in t (the projection is linear in
 * homogeneous coordinates): clip(t) = clipP + t clipT. With the view-space depth, also
 * linear, a march step costs a multiply-add per component instead of a matrix product. */
RF_STRUCT_BEGIN(rfk_peel_clip_ray)
  rf_float4 clipP;
  rf_float4 clipT;
  rf_float depthP; /* -P.z */
  rf_float depthT; /* -T.z */
};

RF_KERNEL rfk_peel_clip_ray rfk_peel_clip_ray_of(rfk_camera camera, rf_float3 P, rf_float3 T)
{
  rfk_peel_clip_ray ray;
  ray.clipP = rfk_clip_of(camera, P);
  ray.clipT = rf_mul_mat4(camera.projection, rf_make4(T.x, T.y, T.z, 0.0));
  ray.depthP = -P.z;
  ray.depthT = -T.z;
  return ray;
}

/* The side of the ray point at t (-1 off the image or behind the camera): how many layers at
 * its texel lie in front of it, by rf_layer_side, which the including side provides (the GLSL
 * stage reads the depths packed four to a texel instead of each layer through
 * rf_layer_texel). */
RF_KERNEL int rfk_peel_side_at(rf_layer_stack layers, int count, rf_float2 viewportSize,
  rfk_peel_clip_ray ray, rf_float t)
{
  rf_float4 clip = rf_make4(ray.clipP.x + t * ray.clipT.x, ray.clipP.y + t * ray.clipT.y,
    ray.clipP.z + t * ray.clipT.z, ray.clipP.w + t * ray.clipT.w);
  rf_float2 tc;
  if (!rfk_peel_clip_on_image(clip, RF_ADDR(tc)))
  {
    return -1;
  }
  return rf_layer_side(layers, count, tc, viewportSize, ray.depthP + t * ray.depthT);
}

/* The depths of layer `layer` at two points a fraction of a texel apart (aTC, bTC, the ends
 * of a crossing's final bracket), filtered: the bilinear weights of the four texels around
 * their midpoint, over those holding a surface within `tolerance` of `centre` (the depth the
 * crossing was found on), so that the layer reads as the surface it samples, not as flat steps
 * a texel wide, without blending across its faults (as rfk_peel_normal filters the normals);
 * `centre` where none does. Four fetches for both ends. */
RF_KERNEL rf_float2 rfk_peel_depths_filtered(rf_layer_stack layers, rf_float2 aTC,
  rf_float2 bTC, rf_float2 size, int layer, rf_float centre, rf_float tolerance)
{
  rf_float2 mid = rf_scale2(rf_add2(aTC, bTC), 0.5);
  rf_float fx = rf_floor(mid.x * size.x - 0.5);
  rf_float fy = rf_floor(mid.y * size.y - 0.5);
  rf_float ax = aTC.x * size.x - 0.5 - fx;
  rf_float ay = aTC.y * size.y - 0.5 - fy;
  rf_float bx = bTC.x * size.x - 0.5 - fx;
  rf_float by = bTC.y * size.y - 0.5 - fy;
  rf_float aSum = 0.0;
  rf_float aWeights = 0.0;
  rf_float bSum = 0.0;
  rf_float bWeights = 0.0;
  for (int j = 0; j < 4; ++j)
  {
    rf_float ox = (j == 1 || j == 3) ? 1.0 : 0.0;
    rf_float oy = j >= 2 ? 1.0 : 0.0;
    rf_float2 at = rf_make2(rf_clamp((fx + ox + 0.5) / size.x, 0.0, 1.0),
      rf_clamp((fy + oy + 0.5) / size.y, 0.0, 1.0));
    rf_float d = rf_layer_depth(layers, at, size, layer);
    /* Bilinear weights, clamped: an end a hair past the four texels keeps their patch. */
    rf_float aw = rf_clamp(ox > 0.0 ? ax : 1.0 - ax, 0.0, 1.0) *
      rf_clamp(oy > 0.0 ? ay : 1.0 - ay, 0.0, 1.0);
    rf_float bw = rf_clamp(ox > 0.0 ? bx : 1.0 - bx, 0.0, 1.0) *
      rf_clamp(oy > 0.0 ? by : 1.0 - by, 0.0, 1.0);
    if (d > 0.0 && rf_abs(d - centre) <= tolerance)
    {
      aSum = aSum + aw * d;
      aWeights = aWeights + aw;
      bSum = bSum + bw * d;
      bWeights = bWeights + bw;
    }
  }
  return rf_make2(aWeights > 0.0 ? aSum / aWeights : centre,
    bWeights > 0.0 ? bSum / bWeights : centre);
}

/* The next crossing of the ray P + t T, 0 < t <= tEnd, with the layers, starting on side
 * `side` (how many layers lie in front of the ray just after P). faultSize is the paper's SIZE,
 * the depth change across a final bracket below which a crossing is a surface (the fault
 * test), and the largest mismatch between the ray and the crossed layer. A crossing of
 * leftLayer (the layer P lies on) within a texel of P is the layer's texel-wise depth seen
 * from beside it, not a surface: the ray goes on. Writes the crossing point,
 * its texture coordinates and the crossed layer's index there; returns RF_PEEL_SURFACE, or
 * RF_PEEL_EDGE where a ray `inside` the glass passes onto texels with no glass at all (the
 * surface it left through is too steep for the layers to hold: the layer at the last texel
 * on the glass nearest the ray stands in), or RF_PEEL_NONE. */
RF_KERNEL int rfk_peel_next_crossing(rf_layer_stack layers, int count, rfk_camera camera,
  rf_float3 P, rf_float3 T, int side, int leftLayer, rf_float tEnd, rf_float faultSize,
  rf_bool inside, RF_OUT(rf_float3) hit,
  RF_OUT(rf_float2) hitTC, RF_OUT(int) hitLayer)
{
  RF_DEREF(hit) = P;
  RF_DEREF(hitTC) = rf_make2(0.0, 0.0);
  RF_DEREF(hitLayer) = 0;
  if (!(tEnd > 0.0))
  {
    return RF_PEEL_NONE;
  }
  /* About one step per texel the segment crosses on screen (the layers hold one value per
   * texel; a ray along the line of sight crosses its layers within one texel, which the count
   * of layers in front tells at once), at least RF_PEEL_MIN_STEPS, at most
   * RF_PEEL_MARCH_STEPS. */
  rf_float2 start = rfk_project_to_texture(camera, P);
  rf_float2 end = rfk_project_to_texture(camera, rf_add3(P, rf_scale3(T, tEnd)));
  rf_float texels = rf_length2(rf_mul2(rf_sub2(end, start), camera.viewportSize));
  int steps = rf_int_of(
    rf_clamp(rf_ceil(texels), RF_PEEL_MIN_STEPS_REAL, RF_PEEL_MARCH_STEPS_REAL));
  rf_float dt = tEnd / rf_float_of(steps);
  rfk_peel_clip_ray clipRay = rfk_peel_clip_ray_of(camera, P, T);
  int before = side;
  int i = 1;
  /* The march's own loop holds one fetch a step and nothing else: the bracket's refinement
   * below runs once per change of side found. Inside the loop it ran at every step, since
   * llvmpipe (like a GPU's warp where any lane needs it) runs an if's body for the whole
   * block of pixels under a mask; only a loop ends once all of its pixels are done. The same
   * steps and crossings as before. */
  while (i <= steps)
  {
    rf_float t = dt * rf_float_of(i);
    int now = rfk_peel_side_at(layers, count, camera.viewportSize, clipRay, t);
    while (now == before && i < steps)
    {
      i = i + 1;
      t = dt * rf_float_of(i);
      now = rfk_peel_side_at(layers, count, camera.viewportSize, clipRay, t);
    }
    if (now < 0)
    {
      return RF_PEEL_NONE; /* the layers hold nothing beyond the image */
    }
    if (now == before)
    {
      return RF_PEEL_NONE; /* the segment's end, no change of side */
    }
    rf_float lo = t - dt;
    rf_float hi = t;
    for (int j = 0; j < RF_PEEL_BISECTIONS; ++j)
    {
      rf_float mid = 0.5 * (lo + hi);
      if (rfk_peel_side_at(layers, count, camera.viewportSize, clipRay, mid) == before)
      {
        lo = mid;
      }
      else
      {
        hi = mid;
      }
    }
    rf_float3 nearQ = rf_add3(P, rf_scale3(T, lo));
    rf_float3 farQ = rf_add3(P, rf_scale3(T, hi));
    rf_float2 nearTC;
    rf_float2 farTC;
    rfk_peel_on_image(camera, nearQ, RF_ADDR(nearTC));
    rfk_peel_on_image(camera, farQ, RF_ADDR(farTC));
    rf_float2 pixels = camera.viewportSize;
    int farSide = rf_layer_side(layers, count, farTC, pixels, -farQ.z);
    /* Going deeper the ray passed behind layer farSide - 1; coming forward it passed in
     * front of layer farSide. */
    int crossedLayer = farSide > before ? farSide - 1 : farSide;
    rf_float farDepth = rf_layer_depth(layers, farTC, pixels, crossedLayer);
    rf_float nearDepth = rf_layer_depth(layers, nearTC, pixels, crossedLayer);
    /* The paper's fault test: across the final bracket the crossed layer's depth changes by
     * X; on a surface X shrinks with the bracket, at a fault it stays the jump. */
    rf_float X = rf_abs(farDepth - nearDepth);
    rf_float2 moved = rf_mul2(rf_sub2(farTC, start), camera.viewportSize);
    rf_bool beside =
      crossedLayer == leftLayer && rf_abs(moved.x) <= 1.0 && rf_abs(moved.y) <= 1.0;
    if (farDepth > 0.0 && nearDepth > 0.0 && X <= faultSize &&
      rf_abs(-farQ.z - farDepth) <= faultSize && !beside)
    {
      /* Beyond the paper: the crossing placed by one secant step on the bracket (the ray's
       * depth less the crossed layer's, linear in t), in place of further halvings, which
       * cost a fetch each. The layer's depth filtered (rfk_peel_depths_filtered): read a
       * texel at a time it is flat steps, and where a ray grazes the surface the step it
       * meets moves its crossing along the ray by far more than a texel (stair-stepped
       * streaks inside the balls of the layers tests); the filtered crossing can lie outside
       * the bracket, so the secant line may reach past it, up to the march's step it was
       * found in. */
      rf_float2 filtered = rfk_peel_depths_filtered(
        layers, nearTC, farTC, pixels, crossedLayer, farDepth, faultSize);
      rf_float nearGap = -nearQ.z - filtered.x;
      rf_float farGap = -farQ.z - filtered.y;
      rf_float tCross = nearGap != farGap ? lo + nearGap / (nearGap - farGap) * (hi - lo) : hi;
      tCross = tCross >= t - dt && tCross <= t ? tCross : hi;
      rf_float3 Q = rf_add3(P, rf_scale3(T, tCross));
      rf_float2 qTC;
      rf_bool onImage = rfk_peel_on_image(camera, Q, RF_ADDR(qTC));
      RF_DEREF(hit) = onImage ? Q : farQ;
      RF_DEREF(hitTC) = onImage ? qTC : farTC;
      RF_DEREF(hitLayer) = crossedLayer;
      return RF_PEEL_SURFACE;
    }
    if (inside && !(rf_layer_depth(layers, farTC, pixels, 0) > 0.0))
    {
      /* Off the glass's footprint from inside: through the layer nearest the ray at the
       * last texel on the glass (before - 1 in front of it, before behind it). */
      rf_float depth = -nearQ.z;
      int front = before > 0 ? before - 1 : 0;
      rf_float frontDepth = rf_layer_depth(layers, nearTC, pixels, front);
      rf_float backDepth = before < count ? rf_layer_depth(layers, nearTC, pixels, before) : 0.0;
      rf_bool useBack = backDepth > 0.0 && (before == 0 || backDepth - depth < depth - frontDepth);
      RF_DEREF(hit) = rf_scale3(rf_add3(nearQ, farQ), 0.5);
      RF_DEREF(hitTC) = nearTC;
      RF_DEREF(hitLayer) = useBack ? before : front;
      return RF_PEEL_EDGE;
    }
    /* A fault zone (the paper's case 2): go on from the side found beyond it. */
    before = farSide;
    i = i + 1;
  }
  return RF_PEEL_NONE;
}

/* The viewer-facing normal of layer `layer` at tc, filtered: the bilinear weights of the four
 * texels around tc, over those holding the same surface as `centre` (the texel the crossing
 * was found on: same facing, depth within `tolerance`). As DIR filters its back normals (the
 * paper: filtering reduces noise), without blending across the layer's faults. */
RF_KERNEL rf_float3 rfk_peel_normal(rf_layer_stack layers, rf_float2 tc, rf_float2 size,
  int layer, rf_float4 centre, rf_float tolerance)
{
  rf_float px = tc.x * size.x - 0.5;
  rf_float py = tc.y * size.y - 0.5;
  rf_float fx = rf_floor(px);
  rf_float fy = rf_floor(py);
  rf_float ax = px - fx;
  rf_float ay = py - fy;
  rf_float3 sum = rf_make3(0.0, 0.0, 0.0);
  for (int j = 0; j < 4; ++j)
  {
    rf_float ox = (j == 1 || j == 3) ? 1.0 : 0.0;
    rf_float oy = j >= 2 ? 1.0 : 0.0;
    rf_float2 at = rf_make2(rf_clamp((fx + ox + 0.5) / size.x, 0.0, 1.0),
      rf_clamp((fy + oy + 0.5) / size.y, 0.0, 1.0));
    rf_float4 t = rf_layer_texel(layers, at, size, layer);
    rf_float w = (ox > 0.0 ? ax : 1.0 - ax) * (oy > 0.0 ? ay : 1.0 - ay);
    if (t.z > 0.0 && rf_abs(t.z - centre.z) <= tolerance && (t.w < 0.0) == (centre.w < 0.0))
    {
      sum = rf_add3(sum, rf_scale3(rf_oct_decode(rf_make2(t.x, t.y)), w));
    }
  }
  return rf_length3(sum) > 0.0 ? rf_normalize3(sum) : rf_oct_decode(rf_make2(centre.x, centre.y));
}

/* The largest t for which the ray P + t T stays within the glass's depth range (positive
 * depths): no layer lies outside it, so no segment needs to be searched beyond. */
RF_KERNEL rf_float rfk_peel_slab_exit(rf_float3 P, rf_float3 T, rf_float2 depthRange)
{
  rf_float depth = -P.z;
  if (T.z < 0.0)
  {
    return rf_max((depthRange.y - depth) / -T.z, 0.0);
  }
  if (T.z > 0.0)
  {
    return rf_max((depth - depthRange.x) / T.z, 0.0);
  }
  return 1e30;
}

/* The crossings a trace follows after the front surface, with K layers and B total internal
 * reflections: the K - 1 one texel's stack holds behind the front, and one per bounce. A ray
 * moving across the image can meet more (leaving one glass it can cross another beside it:
 * rays through two of the nested contours' balls, each holding a ball, cross seven surfaces
 * after the front), but each crossing allowed costs the march that looks for it, also on rays
 * that find nothing: 2K - 1 read the nested contours 0.7 dB closer to the truth with K = 4
 * (17.39 -> 18.10 against the 4 x 4 truth) and lengthened their shading by half (47.8 -> 72.0
 * ms; K = 2: the isosurface +0.2 dB, the shading of every mesh 50-90 % longer), so not kept
 * (docs/benchmark.md). */
RF_KERNEL int rfk_peel_interfaces(int layers, int bounces)
{
  return layers - 1 + bounces;
}

/* The innermost glass of a medium stack, -1 when the ray is outside every glass. */
RF_KERNEL int rfk_peel_stack_top(int stack)
{
  return (stack & 127) - 1;
}

RF_KERNEL int rfk_peel_stack_push(int stack, int material)
{
  /* A ray inside more glass than the stack holds forgets the outermost. */
  return ((stack << 7) & 268435455) | (material + 1);
}

RF_KERNEL int rfk_peel_stack_pop(int stack)
{
  return stack >> 7;
}

/* The index of refraction of the medium a stack describes (1: outside every glass). */
RF_KERNEL rf_float rfk_peel_medium_ior(rf_material_table materials, int stack)
{
  int top = rfk_peel_stack_top(stack);
  return top < 0 ? 1.0 : rf_material_ior(materials, top);
}

/* A ray being followed through the layers: where it is, where it goes, the medium stack, its
 * side of the layers, the total internal reflections it took, the length it travelled inside
 * glass, the length of the segment that brought it to P, whether a reflection past the
 * bounces ended it and, for a split's reflected ray, the cosine at the exit it turned back from
 * (0 where it split entering glass). */
RF_STRUCT_BEGIN(rfk_peel_ray)
  rf_float3 P;
  rf_float3 T;
  int stack;
  int side;
  int layer; /* the layer P lies on */
  int reflected;
  rf_float travelled;
  rf_float chord;
  rf_bool ended;
  rf_float splitCos;
};

/* The ray just inside glass `material`, entered at P1 (on layer 0) with unit direction T1. */
RF_KERNEL rfk_peel_ray rfk_peel_entered(rf_float3 P1, rf_float3 T1, int material)
{
  rfk_peel_ray ray;
  ray.P = P1;
  ray.T = T1;
  ray.stack = rfk_peel_stack_push(0, material);
  ray.side = 1;
  ray.layer = 0;
  ray.reflected = 0;
  ray.travelled = 0.0;
  ray.chord = 0.0;
  ray.ended = RF_FALSE;
  ray.splitCos = 0.0;
  return ray;
}

/* Whether the ray r, just past a crossing, is searched for a next one, where `count` layers
 * hold the glass (`capped`: the count is the layers captured, K, and the glass may hold more
 * behind them): always inside glass; outside every glass only where some texel holds, or may
 * hold, more than two layers. With two, each pixel sees one glass's front and back and no
 * glass behind it, so a ray that has left the glass could meet more only beside it on
 * screen, grazing its silhouette (the paper follows a ray "until the ray leaves the object",
 * seed 004, section 3.1). That search is a whole march that finds nothing at nearly every
 * pixel, and llvmpipe leaves the loop of crossings only once all of a block's rays have
 * ended: PEEL 4's shading on the benchmark's sphere and torus read 28-35 ms with it and 21-26
 * without, the sphere's pictures the same and 64 pixels of the torus's silhouette at most 18
 * levels apart (docs/benchmark.md, *PEEL leaves glass of two layers for good*). PEEL 2
 * captures two layers whatever the glass holds: on the isosurface, whose blobs lie beside and
 * behind each other, a ray that has left one blob after a total internal reflection meets the
 * next (its rows with TIR followed read 0.17-0.32 dB less when it was not searched for). */
RF_KERNEL rf_bool rfk_peel_may_meet_more(int count, rf_bool capped, rfk_peel_ray r)
{
  return count > 2 || capped || rfk_peel_stack_top(r.stack) >= 0;
}

/* Follows the ray through at most `interfaces` crossings, of which at most `bounces` in all may
 * totally reflect (one more takes tirPolicy's direction and ends it), each segment searched up
 * to tLimit (the glass's extent), the glass's depth range and the frustum. With `split`, the first interface that
 * refracts also reflects (Fresnel): the reflected ray, ready to be followed, goes to `branch`
 * and its share (the exact dielectric Fresnel term) to `branchWeight`, 0 when nothing split. */
RF_KERNEL void rfk_peel_follow(rf_layer_stack layers, int count, rf_bool capped,
  rf_material_table materials,
  rfk_camera camera, RF_INOUT(rfk_peel_ray) ray, int interfaces, int bounces, int tirPolicy,
  rf_float tLimit, rf_float2 depthRange, rf_bool split, RF_OUT(rfk_peel_ray) branch,
  RF_OUT(rf_float) branchWeight)
{
  rfk_peel_ray r = RF_DEREF(ray);
  rf_bool splitting = split;
  /* SIZE: a linear step over the glass's extent. */
  rf_float faultSize = tLimit / RF_PEEL_MARCH_STEPS_REAL;
  RF_DEREF(branch) = r;
  RF_DEREF(branchWeight) = 0.0;
  for (int k = 0; k < interfaces; ++k)
  {
    rf_float tEnd = rf_min(rf_min(rfk_frustum_exit(camera, r.P, r.T), tLimit),
      rfk_peel_slab_exit(r.P, r.T, depthRange));
    rf_float3 Q;
    rf_float2 tc;
    int hitLayer;
    int found = rfk_peel_next_crossing(layers, count, camera, r.P, r.T, r.side, r.layer, tEnd,
      faultSize, rfk_peel_stack_top(r.stack) >= 0, RF_ADDR(Q), RF_ADDR(tc), RF_ADDR(hitLayer));
    if (found == RF_PEEL_NONE)
    {
      break;
    }
    rf_float4 texel = rf_layer_texel(layers, tc, camera.viewportSize, hitLayer);
    rf_float3 towardViewer =
      rfk_peel_normal(layers, tc, camera.viewportSize, hitLayer, texel, faultSize);
    rf_float3 outward = texel.w < 0.0 ? rf_neg3(towardViewer) : towardViewer;
    int crossed = rf_int_of(rf_abs(texel.w) + 0.5) - 1;
    r.chord = rf_length3(rf_sub3(Q, r.P));
    if (rfk_peel_stack_top(r.stack) >= 0)
    {
      r.travelled = r.travelled + r.chord;
    }
    r.P = Q;
    r.layer = hitLayer;
    if (found == RF_PEEL_EDGE)
    {
      /* Left through the edge: the surface there faces the ray's way out. */
      outward = rf_dot3(outward, r.T) < 0.0 ? rf_neg3(outward) : outward;
    }
    rf_bool entering = rf_dot3(r.T, outward) < 0.0;
    if (crossed >= 0 && rf_material_is_sheet(materials, crossed))
    {
      /* A thin sheet: crossed without bending (its two faces are parallel). */
      r.side = rf_dot3(r.T, towardViewer) < 0.0 ? hitLayer + 1 : hitLayer;
      continue;
    }
    int beyond = entering ? rfk_peel_stack_push(r.stack, crossed) : rfk_peel_stack_pop(r.stack);
    rf_float eta =
      rfk_peel_medium_ior(materials, r.stack) / rfk_peel_medium_ior(materials, beyond);
    rf_float3 next;
    if (rfk_refract(r.T, outward, eta, RF_TIR_POLICY_REFLECT, RF_ADDR(next)) ==
      RF_TOTAL_INTERNAL_REFLECTION)
    {
      if (r.reflected >= bounces)
      {
        rfk_refract(r.T, outward, eta, tirPolicy, RF_ADDR(next));
        r.T = next;
        r.ended = RF_TRUE;
        break;
      }
      r.reflected = r.reflected + 1;
    }
    else
    {
      if (splitting && eta != 1.0)
      {
        /* The reflected part stays in this medium and turns back from the surface. */
        rfk_peel_ray reflectedRay = r;
        reflectedRay.T = rf_normalize3(rf_reflect3(r.T, outward));
        reflectedRay.side = rf_dot3(reflectedRay.T, towardViewer) < 0.0 ? hitLayer + 1 : hitLayer;
        reflectedRay.splitCos = entering ? 0.0 : rf_dot3(r.T, outward);
        RF_DEREF(branch) = reflectedRay;
        RF_DEREF(branchWeight) = rfk_fresnel_dielectric(rf_dot3(r.T, outward), eta);
        splitting = RF_FALSE;
      }
      r.stack = beyond;
    }
    r.T = next;
    r.side = rf_dot3(r.T, towardViewer) < 0.0 ? hitLayer + 1 : hitLayer;
    if (!rfk_peel_may_meet_more(count, capped, r))
    {
      break;
    }
  }
  RF_DEREF(ray) = r;
}

/* The ray after the front surface: entered at P1 (on layer 0) into glass `material`, unit
 * direction T1 inside, followed as rfk_peel_follow without a split. Writes where and in which
 * direction the ray leaves the captured glass, and the length it travelled inside; returns the
 * bounces followed, + 16 when TIR ended the trace. */
RF_KERNEL int rfk_peel_trace(rf_layer_stack layers, int count, rf_material_table materials,
  rfk_camera camera, rf_float3 P1, rf_float3 T1, int material, int interfaces, int bounces,
  int tirPolicy, rf_float tLimit, rf_float2 depthRange, RF_OUT(rf_float3) P2,
  RF_OUT(rf_float3) T2, RF_OUT(rf_float) insideLength)
{
  rfk_peel_ray ray = rfk_peel_entered(P1, T1, material);
  rfk_peel_ray unused;
  rf_float unusedWeight;
  rfk_peel_follow(layers, count, RF_FALSE, materials, camera, RF_ADDR(ray), interfaces, bounces,
    tirPolicy, tLimit, depthRange, RF_FALSE, RF_ADDR(unused), RF_ADDR(unusedWeight));
  RF_DEREF(P2) = ray.P;
  RF_DEREF(T2) = ray.T;
  RF_DEREF(insideLength) = ray.travelled;
  return ray.reflected + (ray.ended ? 16 : 0);
}

#endif /* !RF_GLSL || RF_PEEL_LAYERS */

#endif /* RF_KERNEL_PEEL_H */
