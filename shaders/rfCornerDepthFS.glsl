//VTK::System::Dec
// Anti-aliasing: the depth buffer that culls the shading of the pixels' corners. Texel (i, j)
// stands for the lower-left corner of pixel (i, j), where pixels (i - 1 .. i, j - 1 .. j)
// meet; it gets the nearest front depth of those four (1 where none holds glass), so that the
// shading stage's GL_GREATER test at the far plane passes at every corner of every glass pixel
// and nowhere else (rfShadeFS.glsl, RF_CORNER_SAMPLES; vtkRefractionShadeStage::Render).
in vec2 texCoord;
uniform sampler2D rfFrontDepth;
uniform vec2 rfSize;
//VTK::Output::Dec
void main()
{
  ivec2 corner = ivec2(texCoord * rfSize);
  float depth = 1.0;
  for (int k = 0; k < 4; ++k)
  {
    ivec2 texel = max(corner + ivec2(k % 2, k / 2) - 1, ivec2(0));
    depth = min(depth, texelFetch(rfFrontDepth, texel, 0).r);
  }
  gl_FragDepth = depth;
}
