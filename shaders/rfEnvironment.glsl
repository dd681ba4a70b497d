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

vec3 rfEnvironment(vec3 directionVC)
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
  return rfk_builtin_environment_filtered(rfViewToWorld * directionVC, rfEnvironmentWidth);
#endif
}
