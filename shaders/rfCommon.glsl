// What the geometry and the shading stages share, after rfKernelSource (rf_oct_encode and
// rf_oct_decode come from there). Expects uniform int rfParallel.

vec3 rfViewDirection(vec3 p)
{
  return rfParallel == 1 ? vec3(0.0, 0.0, -1.0) : normalize(p);
}
