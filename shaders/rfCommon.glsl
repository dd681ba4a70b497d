// What the geometry and the shading stages share, after rfKernelSource (rf_oct_encode and
// rf_oct_decode come from there). Expects uniform int rfParallel and uniform vec4 rfViewport
// (origin, size in pixels).

vec3 rfViewDirection(vec3 p)
{
  return rfParallel == 1 ? vec3(0.0, 0.0, -1.0) : normalize(p);
}

// The texel of a viewport-sized target at texture coordinates tc in [0, 1] (1 on the last).
ivec2 rfTexelOf(vec2 tc)
{
  return ivec2(min(tc * rfViewport.zw, rfViewport.zw - 1.0));
}

// A point estimated one chord along T (an exit reflection's next interface, DIR's and PEEL's)
// moved onto the surface found there: pastSurface is how much deeper (-z) than the surface it
// lies, and along T the depth changes by -T.z; at most a chord either way, and not at all
// where T runs across the line of sight.
vec3 rfStepOntoSurface(vec3 P, vec3 T, float pastSurface, float chord)
{
  return abs(T.z) > 1e-3 ? P + clamp(pastSurface / T.z, -chord, chord) * T : P;
}
