// The viewer users run on their own meshes and time series: `RefractionViewer --help`.
#include "rfViewer.h"

int main(int argc, char* argv[])
{
  return rfViewerMain(argc, argv, {});
}
