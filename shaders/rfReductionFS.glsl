//VTK::System::Dec
// DIR pass 2 (section 3.2): min/max of the valid back-surface depths by halving passes.
// R = nearest valid depth, G = furthest; the first level reads the back capture's depth (its
// alpha channel), where 0 marks an empty texel, the later levels read the RG32F output of the previous level.
// An all-empty block gives R = 3e38, G = 0, so a range with R > G means "no back surface".
in vec2 texCoord;
uniform sampler2D rfSource;
uniform ivec2 rfSourceSize;
uniform int rfFirstLevel;
uniform ivec2 rfTargetSize;
//VTK::Output::Dec
void main()
{
  ivec2 base = ivec2(floor(texCoord * vec2(rfTargetSize))) * 2;
  float nearest = 3.0e38;
  float furthest = 0.0;
  for (int j = 0; j < 2; ++j)
  {
    for (int i = 0; i < 2; ++i)
    {
      vec4 v = texelFetch(rfSource, min(base + ivec2(i, j), rfSourceSize - 1), 0);
      if (rfFirstLevel == 1)
      {
        if (v.a > 0.0)
        {
          nearest = min(nearest, v.a);
          furthest = max(furthest, v.a);
        }
      }
      else
      {
        nearest = min(nearest, v.r);
        furthest = max(furthest, v.g);
      }
    }
  }
  gl_FragData[0] = vec4(nearest, furthest, 0.0, 1.0);
}
