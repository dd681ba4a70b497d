//VTK::System::Dec
// Anti-aliasing, the resolve (vtkRefractionPass::SetAntiAliasing): each pixel of the glass
// averages the colours the shading stage wrote at its four corners (rfShadeFS.glsl,
// RF_CORNER_SAMPLES: texel (i, j) of rfCorners holds the lower-left corner of pixel (i, j)),
// over the corners that lie on the glass; that share is the alpha that blends it over the
// scene. Writes the glass's depth, as the shading stage does without anti-aliasing. A pixel
// whose centre is glass but none of its corners (a sliver thinner than a pixel) shows the
// scene.
in vec2 texCoord;
uniform sampler2D rfFrontSurface;
uniform sampler2D rfFrontDepth;
uniform sampler2D rfCorners;
uniform vec2 rfSize;
//VTK::Output::Dec
void main()
{
  ivec2 pixel = ivec2(texCoord * rfSize);
  if (!(texelFetch(rfFrontSurface, pixel, 0).w > 0.5))
  {
    discard;
  }
  ivec2 last = ivec2(rfSize) - 1;
  vec4 sum = texelFetch(rfCorners, pixel, 0) +
    texelFetch(rfCorners, min(pixel + ivec2(1, 0), last), 0) +
    texelFetch(rfCorners, min(pixel + ivec2(0, 1), last), 0) +
    texelFetch(rfCorners, min(pixel + ivec2(1, 1), last), 0);
  if (!(sum.a > 0.5))
  {
    discard;
  }
  gl_FragDepth = texelFetch(rfFrontDepth, pixel, 0).r;
  gl_FragData[0] = vec4(sum.rgb / sum.a, sum.a / 4.0);
}
