// The glass colour around a point, for the composite at the window's samples: two successive
// mip levels of the glass colour from `lod`, filtered at the point. Texels without glass hold
// 0, so rgb / a is the mean of the glass colours there. The nearer level where it holds glass,
// else the wider; alpha 0 where neither does (nothing near: the composite drops the fragment).
// The silhouette's fill (rfSilhouetteFillFS.glsl) and the corners' composite (rfGeometryFS.glsl)
// read it.
vec4 rfGlassAround(sampler2D glassColour, vec2 point, float lod)
{
  vec4 near = textureLod(glassColour, point, lod);
  vec4 wider = textureLod(glassColour, point, lod + 1.0);
  vec4 sum = near.a > 1e-3 ? near : wider;
  return sum.a > 1e-3 ? vec4(sum.rgb / sum.a, 1.0) : vec4(0.0);
}
