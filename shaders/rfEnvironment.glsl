// The environment along a view-space direction: the renderer's cube map (RF_ENV_CUBEMAP), else
// the built-in one (rfk_builtin_environment of the kernel, the formula rf_builtin_environment
// runs in C). Inserted after rfKernelSource; needs the uniforms rfViewToWorld and, with
// RF_ENV_CUBEMAP, rfEnvironmentCube and rfEnvMatrix.
vec3 rfEnvironment(vec3 directionVC)
{
  vec3 w = rfViewToWorld * directionVC;
#ifdef RF_ENV_CUBEMAP
  return texture(rfEnvironmentCube, rfEnvMatrix * w).rgb;
#else
  return rfk_builtin_environment(w);
#endif
}
