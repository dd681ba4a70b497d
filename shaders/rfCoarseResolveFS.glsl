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
// ... and where their colours differ by at most this (any channel, display units): across an
// edge of what the glass shows (a tile's border seen through it) their mean steps along the
// blocks, and the pixel traces its own ray instead. On the benchmark's sphere, torus and bunny
// at 512 px (single-sampled) this brought coarse shading from 0.2-3.2 dB to 0.1-0.3 dB below
// the full shading's PSNR against the truth, tracing 10 % of the glass pixels on the sphere at
// 512 px and 2.6 % at 2048.
#define RF_COARSE_MAX_CONTRAST 0.1

void main()
{
  ivec2 pixel = ivec2(texCoord * rfSize);
  vec4 front = texelFetch(rfFrontSurface, pixel, 0);
  // The traced pixels sit at the blocks' lower-left pixels: a pixel lies on one of them, or
  // halfway between two or four, and the linear filter averages exactly those.
  vec2 coarse = (0.5 * vec2(pixel) + 0.5) / vec2(textureSize(rfCoarseColour, 0));
  vec4 ray = textureLod(rfCoarseRay, coarse, 0.0);
  vec4 traced = textureLod(rfCoarseColour, coarse, 0.0);
  // The (up to) four blocks the pixel lies between, repeated where it lies on a block's row or
  // column.
  ivec2 block = pixel / 2;
  ivec2 next = min(block + (pixel - 2 * block), textureSize(rfCoarseColour, 0) - 1);
  vec3 c00 = texelFetch(rfCoarseColour, block, 0).rgb;
  vec3 c10 = texelFetch(rfCoarseColour, ivec2(next.x, block.y), 0).rgb;
  vec3 c01 = texelFetch(rfCoarseColour, ivec2(block.x, next.y), 0).rgb;
  vec3 c11 = texelFetch(rfCoarseColour, next, 0).rgb;
  vec3 spread = max(max(c00, c10), max(c01, c11)) - min(min(c00, c10), min(c01, c11));
  bool even = max(spread.r, max(spread.g, spread.b)) <= RF_COARSE_MAX_CONTRAST;
  // The mean of the materials is the pixel's own only where all are (a block without glass,
  // or reflected inside, counts 0).
  bool stands = abs(ray.w - floor(front.w + 0.5)) < 0.01 &&
    dot(ray.xyz, ray.xyz) >= RF_COARSE_MIN_EXIT_AGREEMENT * RF_COARSE_MIN_EXIT_AGREEMENT &&
    abs(traced.a - front.z) <= RF_COARSE_MAX_DEPTH_SHARE * front.z && even;
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
