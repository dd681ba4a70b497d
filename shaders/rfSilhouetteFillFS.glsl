//VTK::System::Dec
// The silhouette's fill (vtkRefractionSampleComposite), before the composite at the window's
// samples: writes into the glass colour target, at the pixels without glass only (the front
// capture's depth test: the quad at the far plane passes where the depth buffer holds 1), the
// glass colour around each pixel, so that a fragment of the glass's silhouette whose pixel's
// centre is off the glass reads its colour with one fetch, as every other fragment does.
// Before, each fragment of the composite filtered two mipmap levels itself, and llvmpipe ran
// both lookups for every fragment of the draw, whichever path it took (about 7 ms of a 55 ms
// frame at 512 on the benchmark's sphere); here they run only at the pixels that need them.
// The glass colour around: levels 1 and 2 of the glass colour's mipmaps, at the pixel's centre
// (rfGlassAround). The level being written (0) is outside the levels read: the target's base
// level is 1 for this draw, so lod 0 reads level 1.
in vec2 texCoord;
uniform sampler2D rfGlassColour;
uniform vec2 rfSize;
//VTK::Output::Dec
//RF::GlassAround
void main()
{
  vec2 centre = (floor(texCoord * rfSize) + 0.5) / rfSize;
  gl_FragData[0] = rfGlassAround(rfGlassColour, centre, 0.0);
}
