#!/usr/bin/env bash
# The main job: install what is missing, build, and run the demo on built-in data.
# RefractionDemo is RefractionViewer with a preset: it renders headless through EGL (no X
# server; an X server's off-screen window when EGL fails and DISPLAY is set; Xvfb as the last
# resort), writes out/demo/frame_NNNN.png and prints the frame times. With a display, pass
# --interactive for a window. Extra arguments go to RefractionDemo (--help lists them, e.g.
# --demo waves --contact-sheet out/waves.png).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/build.sh
rc=0
build/bin/RefractionDemo "$@" || rc=$?
if [ "$rc" -eq 3 ] && [ -z "${DISPLAY:-}" ]; then
  echo "demo: no EGL context, trying an X server (xvfb-run)"
  exec xvfb-run -a -s "-screen 0 1280x1024x24" build/bin/RefractionDemo "$@"
fi
exit "$rc"
