//VTK::System::Dec
// DIR pass 2 (section 3.2): min/max of the valid back-surface depths, each pass reducing
// blocks of RF_REDUCTION_BLOCK x RF_REDUCTION_BLOCK texels (4 x 4: half the passes of the
// paper's halving, the same texel reads; on llvmpipe each pass has a fixed cost).
// R = nearest valid depth, G = furthest. With RF_REDUCTION_FIRST the pass reads the back
// capture's depth (its alpha channel), where 0 marks an empty texel; without it the RG32F
// output of the previous pass. Two programs rather than a uniform branch: llvmpipe runs both
// sides of a branch. An all-empty block gives R = 3e38, G = 0, so a range with R > G means
// "no back surface".
in vec2 texCoord;
uniform sampler2D rfSource;
// The source's texels that hold data, [first, end): reads are clamped into them (a repeated
// texel leaves a min or a max as it is); outside, a level holds what an earlier frame left.
uniform ivec2 rfSourceValidFirst;
uniform ivec2 rfSourceValidEnd;
uniform ivec2 rfTargetSize;
//VTK::Output::Dec
void main()
{
  ivec2 base = ivec2(floor(texCoord * vec2(rfTargetSize))) * RF_REDUCTION_BLOCK;
  float nearest = 3.0e38;
  float furthest = 0.0;
  for (int j = 0; j < RF_REDUCTION_BLOCK; ++j)
  {
    for (int i = 0; i < RF_REDUCTION_BLOCK; ++i)
    {
      vec4 v = texelFetch(rfSource, clamp(base + ivec2(i, j), rfSourceValidFirst,
        rfSourceValidEnd - 1), 0);
#ifdef RF_REDUCTION_FIRST
      if (v.a > 0.0)
      {
        nearest = min(nearest, v.a);
        furthest = max(furthest, v.a);
      }
#else
      nearest = min(nearest, v.r);
      furthest = max(furthest, v.g);
#endif
    }
  }
  gl_FragData[0] = vec4(nearest, furthest, 0.0, 1.0);
}
