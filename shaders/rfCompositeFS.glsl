//VTK::System::Dec
// The composite: puts the glass the shading stage wrote into the glass colour target
// (rfShadeFS.glsl) into the scene, with the glass's depth, so that the scene's depth test keeps
// glass behind opaque actors hidden and later passes see the glass's depth. The shading stage
// runs into a target of its own because there the front capture's depth buffer rejects every
// 4x4 block without glass before the program runs (llvmpipe skips such blocks whole; a discard
// does not spare the rest of the program), while the scene's depth test needs the glass's depth
// written per pixel, which would turn that early test off.
// With anti-aliasing (RF_CORNER_SAMPLES: texel (i, j) holds the lower-left corner of pixel
// (i, j)) each pixel of the glass averages its four corners over the corners that lie on the
// glass; that share is the alpha that blends it over the scene. A pixel whose centre is glass
// but none of its corners (a sliver thinner than a pixel) shows the scene.
in vec2 texCoord;
uniform sampler2D rfFrontDepth;
uniform sampler2D rfGlassColour;
uniform vec2 rfSize;
//VTK::Output::Dec
void main()
{
  ivec2 pixel = ivec2(texCoord * rfSize);
  // The front capture's depth buffer is cleared to 1: below it, the glass.
  float depth = texelFetch(rfFrontDepth, pixel, 0).r;
  if (!(depth < 1.0))
  {
    discard;
  }
#ifdef RF_CORNER_SAMPLES
  ivec2 last = ivec2(rfSize) - 1;
  vec4 sum = texelFetch(rfGlassColour, pixel, 0) +
    texelFetch(rfGlassColour, min(pixel + ivec2(1, 0), last), 0) +
    texelFetch(rfGlassColour, min(pixel + ivec2(0, 1), last), 0) +
    texelFetch(rfGlassColour, min(pixel + ivec2(1, 1), last), 0);
  if (!(sum.a > 0.5))
  {
    discard;
  }
  vec4 colour = vec4(sum.rgb / sum.a, sum.a / 4.0);
#else
  vec4 colour = vec4(texelFetch(rfGlassColour, pixel, 0).rgb, 1.0);
#endif
  gl_FragDepth = depth;
  gl_FragData[0] = colour;
}
