// Beyond the papers (vtkRefractionPass::SetSmoothInternalReflections): where a pixel's ray was
// totally reflected inside the glass, the rays through the rest of that pixel leave along
// paths of their own (another wall, another bounce, out or not), so the one ray the pixel
// traced is a poor estimate of the light the pixel averages, and no lookup width mends it (the
// neighbours' directions jump, they do not spread). There the pixel shows its 3 x 3
// neighbourhood's glass, tent-weighted: the one-ray-per-pixel samples reconstructed over a
// wider support. On the benchmark's bunny at 512 px against the supersampled full reference,
// DIR 5 TIR 2 exit 19.6 -> 21.2 dB (docs/benchmark.md).
//
// The shading stage (rfShadeFS.glsl) marks such a pixel in the glass colour's alpha: 1 +
// 1/1024 (the next half float after 1) instead of 1; the smoothing (rfSmoothReflectedFS.glsl)
// writes every glass pixel back with alpha 1.
#define RF_REFLECTED_INSIDE_ALPHA (1.0 + 1.0 / 1024.0)

// The glass colour at pixel p of a target whose texels without glass hold 0: the tent mean of
// the glass in its 3 x 3 neighbourhood where any of those texels is marked, else its own.
vec3 rfReflectedFilterColour(sampler2D glassColour, ivec2 p, ivec2 last)
{
  vec4 own = texelFetch(glassColour, p, 0);
  vec3 sum = vec3(0.0);
  float weight = 0.0;
  bool marked = false;
  for (int j = -1; j <= 1; ++j)
  {
    for (int i = -1; i <= 1; ++i)
    {
      ivec2 q = p + ivec2(i, j);
      bool inside = all(greaterThanEqual(q, ivec2(0))) && all(lessThanEqual(q, last));
      vec4 texel = inside ? texelFetch(glassColour, q, 0) : vec4(0.0);
      float w = texel.a > 0.5 ? (2.0 - abs(float(i))) * (2.0 - abs(float(j))) : 0.0;
      sum += w * texel.rgb;
      weight += w;
      marked = marked || texel.a > 1.0 + 0.5 / 1024.0;
    }
  }
  return marked && weight > 0.0 ? sum / weight : own.rgb;
}
