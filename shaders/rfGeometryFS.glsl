// The glass's geometry stage, drawn by VTK's own mappers: the glass G-buffer. Injected into
// VTK's polydata fragment shader through its tags by vtkRefractionGeometryStage: the part
// before the RF::Impl marker after VTK's Output::Dec tag, the part after it after VTK's
// Coincident::Impl tag (the end of main). Nothing else runs per fragment: VTK's lighting is
// left out (the refraction replaces the colour) and the refraction itself runs once per pixel
// in the shading stage (rfShadeFS.glsl). One program serves every stage (rfGeometryStage
// selects), so switching stages costs no shader rebuild; only the composite (stage 5) is
// compiled in just for frames that draw it (RF_SAMPLE_COMPOSITE): llvmpipe runs both sides of
// a branch under a mask, and the composite's fetches took half or more of each G-buffer draw.
// Where the composite has a program of its own (RF_COMPOSITE_ONLY) the G-buffer's code is left
// out of it, for the same reason.
//  1 front: octahedral view-space normal facing the viewer, -z_view, material index + 1 (a
//    cleared texel, 0, is no glass); with RF_GBUFFER_COLOUR (output 1) the data's
//    colour VTK computed (the actor's, or the scalars through the lookup table; alpha: how much
//    of an edge VTK draws there, with EdgeVisibility), with
//    RF_GBUFFER_NORMAL_DISTANCE (its output index) ISR's d_N, with RF_GBUFFER_SH (its output
//    index) the SH method's exit direction and length. With RF_SIGNED_FRONT (PEEL composited
//    across ranks) the material is signed as a peeled layer's.
//  2 back: DIR pass 1 (Oliveira & Brauwers 2007, section 3.1): outward normal and (in alpha)
//    -z_view of the back surface. Drawn with GL_GREATER and depth cleared to 0, so the furthest surface
//    wins whatever the mesh's winding; empty texels keep 0, which is what the search tests
//    against. With RF_BACK_NEAREST (beyond the paper) the nearest back-facing surface is kept
//    (GL_LESS, front faces discarded by winding, flipped for meshes wound inward): on shapes
//    of several parts it is the surface the refracted ray leaves through far more often.
//  4 peel (with RF_PEEL_CAPTURE): one depth-peeled layer of the PEEL method (Chi, Wang & Hu,
//    seed 004; Everitt's depth peeling): the nearest surface behind the previous layer
//    (rfPeelPrevious; layer 0 is the front G-buffer), both faces drawn: the normal turned
//    toward the viewer (octahedral), -z_view, and +-(material index + 1), positive where the
//    outward side faces the viewer (rfOutwardFront: whether that is the GL front face).
//  3 mask: SSP's refraction mask (Sousa, GPU Gems 2 ch. 19, listing 19-2), blended into the
//    framebuffer's alpha.
//  5 composite at the window's samples (vtkRefractionSampleComposite): the front surface
//    drawn again into a multisampled framebuffer, with the colour the shading stage gave the
//    fragment's pixel, so that the window's samples cover the glass's silhouette as they
//    cover an opaque actor's (the full-screen composite, rfCompositeFS.glsl, covers whole
//    pixels). Nothing of the G-buffer is computed.
// Defined by the stage: RF_POSITION_VC and RF_NORMAL_VC (the mapper's view-space position and
// normal, or what stands in for them).
uniform int rfGeometryStage;
#ifdef RF_SURFACES_ONLY
// 1 where the actor draws its surfaces (VTK_SURFACE): its vertex and line cells are left out.
uniform int rfSurfacesOnly;
#endif
uniform int rfWindingSign;
uniform float rfMaterial;
uniform int rfParallel;
uniform mat4 rfDCVC;
uniform vec4 rfViewport;
#ifdef RF_GBUFFER_SH
in vec4 rfSHExitVSOut; // the SH method's exit direction (view) and length (rfSHTransferVS.glsl)
#endif
#ifdef RF_PEEL_CAPTURE
uniform sampler2D rfPeelPrevious;
uniform int rfOutwardFront;
#endif
#ifdef RF_PEEL_KBUFFER
//  6 peel depths, 7 peel layers (RF_PEEL_KBUFFER, vtkRefractionGeometryStage::DrawPeelLayers):
//    the same layers as stage 4 in two draws instead of K - 1. Stage 6 inserts every
//    fragment's -z behind the front (rfPeelPrevious) into the pixel's K - 1 slots, which keep
//    the nearest distinct depths sorted: a chain of atomic minimums, correct in any order of
//    the fragments (the k-buffer's insertion, Bavoil et al. 2007, with image atomics). Stage 7
//    writes each fragment whose depth a slot holds into that slot's layer, as stage 4 would.
//    The depths are compared as the bits of positive floats, which order as the floats do.
layout(r32ui) uniform uimage2D rfPeelSlots; // slot i of pixel p at p + (0, i * rfPeelSlotRows)
uniform int rfPeelSlotRows;
layout(rgba32f) writeonly uniform image2D rfPeelLayer1;
#if RF_PEEL_KBUFFER_LAYERS > 2
layout(rgba32f) writeonly uniform image2D rfPeelLayer2;
#endif
#if RF_PEEL_KBUFFER_LAYERS > 3
layout(rgba32f) writeonly uniform image2D rfPeelLayer3;
#endif
#if RF_PEEL_KBUFFER_LAYERS > 4
layout(rgba32f) writeonly uniform image2D rfPeelLayer4;
#endif
#if RF_PEEL_KBUFFER_LAYERS > 5
layout(rgba32f) writeonly uniform image2D rfPeelLayer5;
#endif
#if RF_PEEL_KBUFFER_LAYERS > 6
layout(rgba32f) writeonly uniform image2D rfPeelLayer6;
#endif
#if RF_PEEL_KBUFFER_LAYERS > 7
layout(rgba32f) writeonly uniform image2D rfPeelLayer7;
#endif
#endif
#ifdef RF_PIECE_SHEETS
// A mesh whose connected pieces disagree (vtkRefractionSurfaceModel): 1 on its thin-sheet
// pieces, which take the material rfSheetMaterial (its solid pieces keep rfMaterial).
in float rfPieceSheetVSOut;
uniform float rfSheetMaterial;
#define RF_FRAGMENT_MATERIAL (rfPieceSheetVSOut > 0.5 ? rfSheetMaterial : rfMaterial)
#else
#define RF_FRAGMENT_MATERIAL rfMaterial
#endif
#ifdef RF_GBUFFER_NORMAL_DISTANCE
in float rfNormalDistanceVSOut;
uniform int rfHaveNormalDistance;
uniform float rfModelScale;
#endif

#ifdef RF_SAMPLE_COMPOSITE
// STAGE 5: FRONT_SURFACE (for the material at each pixel) and GLASS_COLOR (the shaded glass,
// at the pixels or, with RF_COMPOSITE_CORNERS, at their lower-left corners as rfShadeFS.glsl
// writes it with RF_CORNER_SAMPLES).
uniform sampler2D rfCompositeSurface;
uniform sampler2D rfCompositeColour;
#endif

//RF::Common

#ifdef RF_SAMPLE_COMPOSITE
#ifdef RF_COMPOSITE_CORNERS
//RF::GlassAround

// The shaded glass at pixel p: the mean of those of its four corners that lie on the glass;
// alpha 0 where it has none.
vec4 rfCompositeAt(ivec2 p, ivec2 last)
{
  vec4 sum = texelFetch(rfCompositeColour, p, 0) +
    texelFetch(rfCompositeColour, min(p + ivec2(1, 0), last), 0) +
    texelFetch(rfCompositeColour, min(p + ivec2(0, 1), last), 0) +
    texelFetch(rfCompositeColour, min(p + ivec2(1, 1), last), 0);
  return sum.a > 0.5 ? vec4(sum.rgb / sum.a, 1.0) : vec4(0.0);
}
#endif

// The colour of a fragment of the glass of this material: its pixel's where the pixel was
// shaded as this material (every pixel inside the silhouette: exactly the full-screen
// composite's colour); at the silhouette, where the fragment covers samples of a pixel whose
// centre lies off this glass, the glass colour around the pixel: levels 1 and 2 of the glass
// colour's mipmaps (vtkRefractionSampleComposite makes them) at the pixel's centre
// (rfGlassAround), whatever glass it is; for the pixels (no corners) filled into the glass colour's texels off the glass
// before the draw, so that the fragments inside the silhouette do not pay for the lookups.
// Alpha 0: none near (a sliver between pixel centres), the fragment is dropped.
vec4 rfSampleComposite(float material)
{
  ivec2 last = ivec2(rfViewport.zw) - 1;
  ivec2 pixel = clamp(ivec2(gl_FragCoord.xy - rfViewport.xy), ivec2(0), last);
#ifdef RF_COMPOSITE_CORNERS
  if (abs(texelFetch(rfCompositeSurface, pixel, 0).w - material) < 0.5)
  {
    vec4 colour = rfCompositeAt(pixel, last);
    if (colour.a > 0.5)
    {
      return colour;
    }
  }
  // Texel (i, j) is the lower-left corner of pixel (i, j): the pixel's centre lies on texel
  // boundaries one further on. Two filtered fetches instead of a search of the 3x3
  // neighbours, which llvmpipe ran for every fragment of the draw (up to 45 fetches).
  return rfGlassAround(rfCompositeColour, (vec2(pixel) + 1.0) / rfViewport.zw, 1.0);
#else
  // The pixels: the texels off the glass already hold the glass colour around them
  // (rfSilhouetteFillFS.glsl, the same two levels), so one fetch serves every fragment.
  vec4 colour = texelFetch(rfCompositeColour, pixel, 0);
#ifdef RF_COMPOSITE_MATERIALS
  // Several glass materials: a fragment over a pixel of another glass (its silhouette over
  // that glass) takes the glass colour around the pixel, level 1 (which holds that pixel's
  // glass, so never none; made before the fill, so glass only).
  float centreMaterial = texelFetch(rfCompositeSurface, pixel, 0).w;
  vec2 centre = (vec2(pixel) + 0.5) / rfViewport.zw;
  vec4 around = textureLod(rfCompositeColour, centre, 1.0);
  if (centreMaterial > 0.5 && abs(centreMaterial - material) > 0.5)
  {
    colour = around.a > 1e-3 ? vec4(around.rgb / around.a, 1.0) : vec4(0.0);
  }
#endif
  return colour.a > 0.5 ? vec4(colour.rgb, 1.0) : vec4(0.0);
#endif
}
#endif

// The unit shading normal; where it is unusable the face normal from the position's
// derivatives, else the direction toward the eye. Unusable: zero, tiny or not finite (VTK has
// normalized it already, so a zero normal arrives as NaN), or turning by more than 1.5 rad
// across the pixel's 2x2 quad. The last catches vertex normals that cancel inside a triangle
// (zero-length normals in the data): there the interpolated vector is rounding noise (the
// attribute planes round each component on their own) and its direction is arbitrary (a turn
// of ~2.8 on average), while a genuine shading normal turns by a few degrees per pixel (the
// metaball isosurface, the steepest of the regression scenes, stays below the threshold).
// One NaN normal would also spread through the filtered back-normal texture to neighbours.
// Call in uniform control flow (derivatives).
vec3 rfSafeNormal(vec3 n, vec3 p)
{
  vec3 face = cross(dFdx(p), dFdy(p));
  float n2 = dot(n, n);
  float turn = length(dFdx(n)) + length(dFdy(n));
  if (n2 > 1e-24 && n2 < 1e30 && turn < 1.5)
  {
    return n * inversesqrt(n2);
  }
  float f2 = dot(face, face);
  if (f2 > 1e-36 && f2 < 1e30)
  {
    return face * inversesqrt(f2);
  }
  vec3 v = rfViewDirection(p);
  return dot(v, v) > 0.0 ? -v : vec3(0.0, 0.0, 1.0);
}

#ifdef RF_PEEL_KBUFFER
const uint rfPeelEmptySlot = 0xFFFFFFFFu;

// Stage 6: `depth` into the pixel's slots. Each atomic minimum leaves the smaller of the two
// depths in the slot and carries the larger on; a depth the slot already holds (two fragments
// of one surface at the same depth) goes no further, as peeling takes it once.
// Where a depth fills an empty slot, the texel past the last slot (its first column) takes
// the minimum of ~(slots filled): how many layers lie behind the front somewhere, for
// vtkRefractionPass::GetPeelLayersFound and the shading, without a count per layer.
void rfPeelInsertDepth(ivec2 pixel, uint depth)
{
  for (int slot = 0; slot < RF_PEEL_KBUFFER_LAYERS - 1; ++slot)
  {
    uint held = imageAtomicMin(rfPeelSlots, pixel + ivec2(0, slot * rfPeelSlotRows), depth);
    if (held == rfPeelEmptySlot)
    {
      imageAtomicMin(rfPeelSlots, ivec2(0, (RF_PEEL_KBUFFER_LAYERS - 1) * rfPeelSlotRows),
        ~uint(slot + 1));
      return;
    }
    if (held == depth)
    {
      return;
    }
    depth = max(held, depth);
  }
}

// Stage 7: the slot that holds `depth`, or -1 (the pixel's K - 1 nearest are in front of it).
int rfPeelFindSlot(ivec2 pixel, uint depth)
{
  for (int slot = 0; slot < RF_PEEL_KBUFFER_LAYERS - 1; ++slot)
  {
    uint held = imageLoad(rfPeelSlots, pixel + ivec2(0, slot * rfPeelSlotRows)).x;
    if (held >= depth)
    {
      return held == depth ? slot : -1;
    }
  }
  return -1;
}

void rfPeelStoreLayer(int slot, ivec2 pixel, vec4 texel)
{
  if (slot == 0)
  {
    imageStore(rfPeelLayer1, pixel, texel);
  }
#if RF_PEEL_KBUFFER_LAYERS > 2
  else if (slot == 1)
  {
    imageStore(rfPeelLayer2, pixel, texel);
  }
#endif
#if RF_PEEL_KBUFFER_LAYERS > 3
  else if (slot == 2)
  {
    imageStore(rfPeelLayer3, pixel, texel);
  }
#endif
#if RF_PEEL_KBUFFER_LAYERS > 4
  else if (slot == 3)
  {
    imageStore(rfPeelLayer4, pixel, texel);
  }
#endif
#if RF_PEEL_KBUFFER_LAYERS > 5
  else if (slot == 4)
  {
    imageStore(rfPeelLayer5, pixel, texel);
  }
#endif
#if RF_PEEL_KBUFFER_LAYERS > 6
  else if (slot == 5)
  {
    imageStore(rfPeelLayer6, pixel, texel);
  }
#endif
#if RF_PEEL_KBUFFER_LAYERS > 7
  else if (slot == 6)
  {
    imageStore(rfPeelLayer7, pixel, texel);
  }
#endif
}
#endif

// The fragment's view-space position from gl_FragCoord, for mappers that declare no vertexVC.
vec3 rfReconstructPositionVC()
{
  vec2 ndc = (gl_FragCoord.xy - rfViewport.xy) / rfViewport.zw * 2.0 - 1.0;
  vec4 p = rfDCVC * vec4(ndc, gl_FragCoord.z * 2.0 - 1.0, 1.0);
  return p.xyz / p.w;
}

//RF::Impl
#ifdef RF_SURFACES_ONLY
  // VTK's mapper draws a polydata's vertex and line cells with its polygons, through this
  // program. Glass is its surfaces: a line drawn into it left a one-pixel copy of the surface
  // it lies on (or a sliver of glass inside), which PEEL took for two more interfaces (the
  // benchmark's torus: docs/benchmark.md, *The torus's seam*). A point's or a line's fragments
  // move along one direction at most (the rasterizer interpolates along the line), a polygon's
  // span two; 1e-3 of the sine between them leaves out polygons seen within 0.03 degrees of
  // edge-on only. Outside any branch: derivatives.
  {
    vec3 rfAcross = dFdx(RF_POSITION_VC);
    vec3 rfDown = dFdy(RF_POSITION_VC);
    if (rfSurfacesOnly == 1 &&
      length(cross(rfAcross, rfDown)) <= 1e-3 * length(rfAcross) * length(rfDown))
    {
      discard;
    }
  }
#endif
#ifdef RF_SAMPLE_COMPOSITE
  if (rfGeometryStage == 5)
  {
    vec4 rfComposite = rfSampleComposite(RF_FRAGMENT_MATERIAL);
    if (!(rfComposite.a > 0.5))
    {
      discard;
    }
    gl_FragData[0] = rfComposite;
  }
#ifndef RF_COMPOSITE_ONLY
  else
#endif
#endif
#ifndef RF_COMPOSITE_ONLY
  {
    vec4 rfDataColour = gl_FragData[0]; // RF_DATA_COLOUR, as VTK's colour code left it
    vec3 rfP = RF_POSITION_VC;
    vec3 rfN = rfSafeNormal(RF_NORMAL_VC, rfP);
    vec3 rfV = rfViewDirection(rfP);
#ifdef RF_PEEL_CAPTURE
    if (rfGeometryStage == 4 || rfGeometryStage == 6 || rfGeometryStage == 7)
    {
      // Exactly the previous layer's fragment computes the same -z again: <= peels it off.
      ivec2 rfPixel = ivec2(gl_FragCoord.xy - rfViewport.xy);
      float rfPrevious = texelFetch(rfPeelPrevious, rfPixel, 0).z;
      bool rfBehind = rfPrevious > 0.0 && -rfP.z > rfPrevious;
      bool rfOutwardToViewer = gl_FrontFacing == (rfOutwardFront == 1);
      vec4 rfLayerTexel = vec4(rf_oct_encode(dot(rfN, rfV) > 0.0 ? -rfN : rfN), -rfP.z,
        rfOutwardToViewer ? RF_FRAGMENT_MATERIAL : -RF_FRAGMENT_MATERIAL);
#ifdef RF_PEEL_KBUFFER
      if (rfGeometryStage == 6 && rfBehind)
      {
        rfPeelInsertDepth(rfPixel, floatBitsToUint(-rfP.z));
      }
      else if (rfGeometryStage == 7 && rfBehind)
      {
        int rfSlot = rfPeelFindSlot(rfPixel, floatBitsToUint(-rfP.z));
        if (rfSlot >= 0)
        {
          rfPeelStoreLayer(rfSlot, rfPixel, rfLayerTexel);
        }
      }
      else
#endif
      if (!rfBehind)
      {
        discard;
      }
      gl_FragData[0] = rfLayerTexel; // stage 4's output; stages 6 and 7 write no colour
    }
    else
#endif
    if (rfGeometryStage == 3)
    {
      gl_FragData[0] = vec4(0.0, 0.0, 0.0, 0.5); // blended to 0.25 + 0.5 alpha
    }
    else if (rfGeometryStage == 2)
    {
#ifdef RF_BACK_NEAREST
      if (gl_FrontFacing == (rfWindingSign > 0))
      {
        discard;
      }
#endif
      gl_FragData[0] = vec4(dot(rfN, rfV) < 0.0 ? -rfN : rfN, -rfP.z);
    }
    else
    {
      float rfFrontMaterial = RF_FRAGMENT_MATERIAL;
#ifdef RF_SIGNED_FRONT
      // Composited across ranks (vtkRefractionGeometryStage::SetSignedFront): signed as a
      // peeled layer's, since this surface may become a deeper layer of the whole glass.
      if (gl_FrontFacing != (rfOutwardFront == 1))
      {
        rfFrontMaterial = -rfFrontMaterial;
      }
#endif
      gl_FragData[0] =
        vec4(rf_oct_encode(dot(rfN, rfV) > 0.0 ? -rfN : rfN), -rfP.z, rfFrontMaterial);
#ifdef RF_GBUFFER_COLOUR
      // Literal indices: VTK maps gl_FragData[n] to its outputs by their text.
      gl_FragData[1] = vec4(clamp(rfDataColour.rgb, 0.0, 1.0), RF_EDGE_MIX);
#endif
#ifdef RF_GBUFFER_SH
#if RF_GBUFFER_SH == 1
      gl_FragData[1] = rfSHExitVSOut;
#else
      gl_FragData[2] = rfSHExitVSOut;
#endif
#endif
#ifdef RF_GBUFFER_NORMAL_DISTANCE
      // d_N is measured in model coordinates: scaled with the actor; -1 marks "none".
      vec4 rfNormalDistanceOut = vec4(
        rfHaveNormalDistance == 1 ? rfNormalDistanceVSOut * rfModelScale : -1.0, 0.0, 0.0, 1.0);
#if RF_GBUFFER_NORMAL_DISTANCE == 1
      gl_FragData[1] = rfNormalDistanceOut;
#else
      gl_FragData[2] = rfNormalDistanceOut;
#endif
#endif
    }
  }
#endif
