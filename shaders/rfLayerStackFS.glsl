//VTK::System::Dec
// PEEL: one layer's texels copied to its place in the stack of all K layers
// (vtkRefractionTargets::PEEL_STACK), from which the shading reads any layer in one fetch
// instead of going through every layer's sampler (rfMethodPEEL.glsl). Drawn once for each layer
// found this frame, with the viewport on that layer's place.
in vec2 texCoord;
uniform sampler2D rfLayer;
//VTK::Output::Dec
void main()
{
  gl_FragData[0] = texelFetch(rfLayer, ivec2(texCoord * vec2(textureSize(rfLayer, 0))), 0);
}
