// The default demo: the viewer with a preset. A time-varying metaball isosurface drawn as
// refractive glass over a checkered floor, before a low wall and beside an opaque cone, 48 frames written to out/demo/frame_NNNN.png, then
// the median frame time of DIR, SIR, ISR, SSP, PEEL and of a plain VTK render of the same
// mesh over 3 interleaved rounds.
// Any viewer option overrides the preset (`RefractionDemo --help`), e.g. --demo waves,
// --frames 8, --timing 0, --environment sky.exr, or --interactive with a display.
#include "rfViewer.h"

int main(int argc, char* argv[])
{
  return rfViewerMain(argc, argv,
    { "--demo", "metaballs", "--frames", "48", "--size", "512", "--out", "out/demo", "--timing",
      "50" });
}
