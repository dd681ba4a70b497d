// The built-in environment: the GLSL twin of rf_builtin_environment (module/core/rf_environment.c).
// World space, +y up. Keep the two formulas identical.
vec3 rfBuiltinEnvironment(vec3 directionWorld)
{
  const vec3 horizon = vec3(0.85, 0.88, 0.92);
  const vec3 zenith = vec3(0.15, 0.35, 0.75);
  const vec3 tileDark = vec3(0.70, 0.22, 0.15);
  const vec3 tileLight = vec3(0.95, 0.93, 0.85);
  const vec3 sunColour = vec3(3.0, 2.6, 1.8);
  float len = length(directionWorld);
  if (!(len > 0.0))
  {
    return horizon;
  }
  vec3 d = directionWorld / len;
  if (d.y >= 0.0)
  {
    float elevation = sqrt(d.y);
    float azimuth = atan(d.z, d.x);
    float sector = fract(azimuth * (6.0 / 3.14159265358979));
    float meridian = 1.0 - smoothstep(0.0, 0.04, min(sector, 1.0 - sector));
    float ring = 1.0 - smoothstep(0.0, 0.02, abs(d.y - 0.5));
    float sunCos = dot(d, vec3(0.48, 0.6, -0.64));
    float sun = pow(max(sunCos, 0.0), 400.0);
    float line = max(meridian, ring) * 0.6;
    return mix(horizon, zenith, elevation) * (1.0 - line) + sunColour * sun;
  }
  float down = -d.y;
  float u = d.x / max(down, 1e-4);
  float v = d.z / max(down, 1e-4);
  float checker = fract((floor(u) + floor(v)) * 0.5) * 2.0;
  float fade = smoothstep(0.0, 0.35, down);
  return mix(horizon, mix(tileLight, tileDark, checker), fade);
}
