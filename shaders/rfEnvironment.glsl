// The environment along a view-space direction: the renderer's cube map (RF_ENV_CUBEMAP), or
// its background (RF_ENV_BACKGROUND: the colour the screen shows in that direction; VTK's
// gradient runs from Background at the bottom of the viewport to Background2 at the top),
// else the built-in sky and ground (rfk_builtin_environment_filtered of the kernel, the formula
// rf_builtin_environment runs in C). Inserted after rfKernelSource; needs the uniforms
// rfViewToWorld and rfVCDC, with RF_ENV_CUBEMAP rfEnvironmentCube and rfEnvMatrix, with
// RF_ENV_BACKGROUND rfBackground and rfBackground2.

// The angular width (radians) of the cone of directions the next lookup stands for: the
// spread of the pixel's rays, which the shading stage sets from their screen-space derivatives
// before it looks up (0: the one direction). Lookups average over it, so that the environment
// seen through glass that minifies it does not alias (moire on the tiles, broken lines).
float rfEnvironmentWidth = 0.0;
// The long axis of that footprint: how far the direction turns across the pixel along the
// axis its rays spread most (0: rfEnvironmentWidth every way). Set with rfEnvironmentWidth.
vec3 rfEnvironmentAxis = vec3(0.0);
// How far the direction turns across the pixel along the other axis (the footprint's second
// span; rfEnvironmentWidth is its length). Set with rfEnvironmentWidth.
vec3 rfEnvironmentShortAxis = vec3(0.0);

// One lookup, averaged over rfEnvironmentWidth; the built-in environment over the whole
// footprint (rfEnvironmentAxis and rfEnvironmentShortAxis), which it filters in closed form.
vec3 rfEnvironmentLookup(vec3 directionVC)
{
#if defined(RF_ENV_CUBEMAP)
  // The mip level whose texels span the width (a face's texel spans about (pi / 2) / size
  // radians); a cube map without mip levels reads its one level.
  float texel = 1.5707963 / float(textureSize(rfEnvironmentCube, 0).x);
  float level = log2(max(rfEnvironmentWidth / texel, 1.0));
  return textureLod(rfEnvironmentCube, rfEnvMatrix * (rfViewToWorld * directionVC), level).rgb;
#elif defined(RF_ENV_BACKGROUND)
  vec4 c = rfVCDC * vec4(directionVC, 0.0);
  float up = c.w > 1e-6 * length(directionVC) ? 0.5 + 0.5 * c.y / c.w
    : (directionVC.y >= 0.0 ? 1.0 : 0.0);
  return mix(rfBackground, rfBackground2, clamp(up, 0.0, 1.0));
#else
  return rfk_builtin_environment_footprint(rfViewToWorld * directionVC,
    rfViewToWorld * rfEnvironmentAxis, rfViewToWorld * rfEnvironmentShortAxis);
#endif
}

// The most lookups one footprint is averaged from along its long axis: on the torus (with the
// built-in environment, then looked up so too) 2 gained 0.4 dB of the 1.2 that 8 gain, 4
// gained 1.0 at the cost of 8 (docs/benchmark.md).
#define RF_MAX_ENVIRONMENT_TAPS 4

// The environment over the footprint of a pixel's rays around directionVC. The built-in
// environment filters the whole parallelogram in one lookup, in closed form
// (rfk_builtin_environment_footprint), its tiles strip by strip along the footprint, so that it
// does not blur across the long axis what the rays resolve there (the sharp tile edge down the
// middle of the benchmark's torus, 3-5 pixels wide with cones; docs/benchmark.md, *The
// built-in environment over the footprint*). It was looked up as a cube map is, each lookup
// evaluating the whole environment; the strips read 0.1-0.3 dB closer to the truth on the
// sphere and the torus for 1-2 ms less of DIR's shading (*The ground's strips*). A cube map:
// where the directions spread along one axis (rfEnvironmentAxis) more than 1.5 times across
// it, the mean of lookups spaced along that axis, each a cone as wide as its share of the
// axis (at least rfEnvironmentWidth), as a GPU's anisotropic filtering does; else one lookup
// over the whole footprint. Both are the one loop (one pass for the single lookup): as an
// early return before the loop, the single lookup cost llvmpipe a lookup more at every pixel
// (it runs both paths, and the loop at least once), 3-10 ms of a 1024 px full-window sphere's
// shading with the built-in environment. A single lookup as wide as the long axis would blur
// across what the rays resolve, one as wide as the short axis aliases along the long one
// (speckle in the rings inside the torus's hole and along its rims).
vec3 rfEnvironment(vec3 directionVC)
{
#if !defined(RF_ENV_CUBEMAP) && !defined(RF_ENV_BACKGROUND)
  return rfEnvironmentLookup(directionVC); // the whole footprint at once (above)
#else
  float width = rfEnvironmentWidth;
  vec3 longAxis = rfEnvironmentAxis;
  float span = length(longAxis);
  float taps = min(ceil(span / max(width, 1e-6)), float(RF_MAX_ENVIRONMENT_TAPS));
  bool spread = span > 1.5 * width && taps >= 2.0;
  taps = spread ? taps : 1.0;
  vec3 axis = spread ? longAxis : vec3(0.0);
  rfEnvironmentWidth = spread ? max(width, span / taps) : width;
  rfEnvironmentAxis = longAxis / taps;
  vec3 sum = vec3(0.0);
  for (float i = 0.5; i < taps; i += 1.0)
  {
    sum += rfEnvironmentLookup(directionVC + (i / taps - 0.5) * axis);
  }
  rfEnvironmentWidth = width;
  rfEnvironmentAxis = longAxis;
  return sum / taps;
#endif
}
