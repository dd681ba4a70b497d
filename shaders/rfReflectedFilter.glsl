// Beyond the papers (vtkRefractionPass::SetSmoothInternalReflections): where a pixel's ray was
// totally reflected inside the glass, the rays through the rest of that pixel leave along
// paths of their own (another wall, another bounce, out or not), so the one ray the pixel
// traced is a poor estimate of the light the pixel averages, and no lookup width mends it (the
// neighbours' directions jump, they do not spread). There the pixel shows its 3 x 3
// neighbourhood's glass, tent-weighted: the one-ray-per-pixel samples reconstructed over a
// wider support. Measured offline on the bunny at 512 px against the supersampled full
// reference (docs/benchmark.md): the exact trace at one ray per pixel 18.4 -> 22.5 dB.
//
// The shading stage marks such a pixel in the glass colour target's alpha: 1 + 1/1024 (the
// next half float after 1) instead of 1, so that a mean of alphas still counts glass texels
// to within 0.1 % (the silhouette's mipmaps, vtkRefractionSampleComposite).
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
