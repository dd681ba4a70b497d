//VTK::System::Dec
// PEEL: a full-screen quad drawn under the stencil test "at least two" after a peeling draw
// that counted, in the stencil, the fragments it kept at each pixel (vtkRefractionPeelCount):
// an occlusion query around it tells whether any pixel holds a surface behind the layer just
// drawn. Nothing is written; the colour is masked.
in vec2 texCoord;
//VTK::Output::Dec
void main()
{
  gl_FragData[0] = vec4(texCoord, 0.0, 0.0);
}
