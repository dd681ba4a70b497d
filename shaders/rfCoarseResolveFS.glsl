//VTK::System::Dec
// Coarse shading (vtkRefractionPass::SetCoarseShading): each glass pixel takes the colour the
// rays of the 2x2 blocks around it were shaded (rfShadeFS.glsl with RF_COARSE_SAMPLES) where
// they stand for it; where they do not, depth 0 marks it for the shading stage, which traces
// it on its own behind a GL_GREATER test at the far plane (every other pixel: depth 1,
// culled; vtkRefractionShadeStage::Render). Runs over the glass's rectangle, glass or not:
// the depth it writes keeps the GPU from culling ahead of it.
in vec2 texCoord;
uniform sampler2D rfFrontSurface; // -z_view in z, material + 1 in w
// The blocks' traced pixels: rfCoarseColour their colour and -z_view there, rfCoarseRay their
// unit exit direction and material + 1 (0: no glass, or a ray reflected inside). Both
// filtered linearly.
uniform sampler2D rfCoarseColour;
uniform sampler2D rfCoarseRay;
#ifdef RF_TINT
uniform sampler2D rfFrontColour; // EdgeVisibility: the edges over the glass
#endif
uniform vec2 rfSize; // the full targets' size in pixels
//VTK::Output::Dec

// The blocks' rays stand for a pixel only where their exit directions agree: their mean is
// nearly unit length only then (1 - |mean| is about half their spread's variance; 0.9995
// allows about 2 degrees between two of them). Beyond, the glass turns the rays too fast
// between the blocks for a mean to stand in (a crease of the exit, near the rim).
#define RF_COARSE_MIN_EXIT_AGREEMENT 0.9995
// ... and where their depth is the pixel's own within this share: no jump to another part of
// the glass between them.
#define RF_COARSE_MAX_DEPTH_SHARE 0.02

void main()
{
  ivec2 pixel = ivec2(texCoord * rfSize);
  vec4 front = texelFetch(rfFrontSurface, pixel, 0);
  // The traced pixels sit at the blocks' lower-left pixels: a pixel lies on one of them, or
  // halfway between two or four, and the linear filter averages exactly those.
  vec2 coarse = (0.5 * vec2(pixel) + 0.5) / vec2(textureSize(rfCoarseColour, 0));
  vec4 ray = textureLod(rfCoarseRay, coarse, 0.0);
  vec4 traced = textureLod(rfCoarseColour, coarse, 0.0);
  // The mean of the materials is the pixel's own only where all are (a block without glass,
  // or reflected inside, counts 0).
  bool stands = abs(ray.w - floor(front.w + 0.5)) < 0.01 &&
    dot(ray.xyz, ray.xyz) >= RF_COARSE_MIN_EXIT_AGREEMENT * RF_COARSE_MIN_EXIT_AGREEMENT &&
    abs(traced.a - front.z) <= RF_COARSE_MAX_DEPTH_SHARE * front.z;
  bool glass = front.w > 0.5;
  vec3 colour = traced.rgb;
#ifdef RF_TINT
  vec4 data = texelFetch(rfFrontColour, pixel, 0);
  colour = mix(colour, data.rgb, data.a);
#endif
  // No glass: 0, as the glass colour target holds there (the shading stage clears it where
  // its composite or smoothing reads beyond the glass); a pixel to trace: overwritten.
  gl_FragData[0] = glass && stands ? vec4(colour, 1.0) : vec4(0.0);
  gl_FragDepth = glass && !stands ? 0.0 : 1.0;
}
