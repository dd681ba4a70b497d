//VTK::System::Dec
// Smoothing the pixels reflected inside (vtkRefractionPass::SetSmoothInternalReflections,
// rfReflectedFilter.glsl), after the shading stage and before either composite: reads a copy of
// the glass colour as the shading wrote it (marks in alpha) and writes the glass colour target
// back, glass pixels only (the front capture's depth test, as the shading stage's), with alpha
// 1. Once per glass pixel, whichever composite follows.
in vec2 texCoord;
uniform sampler2D rfShadedColour;
uniform vec2 rfSize;
//VTK::Output::Dec
//RF::ReflectedFilter
void main()
{
  ivec2 pixel = ivec2(texCoord * rfSize);
  gl_FragData[0] =
    vec4(rfReflectedFilterColour(rfShadedColour, pixel, ivec2(rfSize) - 1), 1.0);
}
