// What the geometry and the shading stages share. Expects uniform int rfParallel.

vec3 rfViewDirection(vec3 p)
{
  return rfParallel == 1 ? vec3(0.0, 0.0, -1.0) : normalize(p);
}

// Octahedral encoding of a unit vector into [-1, 1]^2 (Meyer et al. 2010): the G-buffer keeps
// the front normal in two floats beside the depth and the material, one RGBA32F texel.
vec2 rf_oct_encode(vec3 n)
{
  vec3 a = n / max(abs(n.x) + abs(n.y) + abs(n.z), 1e-30);
  vec2 e = a.xy;
  if (a.z < 0.0)
  {
    e = (1.0 - abs(a.yx)) * vec2(a.x >= 0.0 ? 1.0 : -1.0, a.y >= 0.0 ? 1.0 : -1.0);
  }
  return e;
}

vec3 rf_oct_decode(vec2 e)
{
  vec3 n = vec3(e, 1.0 - abs(e.x) - abs(e.y));
  if (n.z < 0.0)
  {
    n.xy = (1.0 - abs(n.yx)) * vec2(n.x >= 0.0 ? 1.0 : -1.0, n.y >= 0.0 ? 1.0 : -1.0);
  }
  return normalize(n);
}
