#!/usr/bin/env bash
# The main job: install what is missing, build, and run the demo on built-in data.
# Headless (no DISPLAY) it writes out/demo/frame_NNNN.png and prints frame times; with a
# display, pass --interactive for a window. Extra arguments go to RefractionDemo.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/build.sh
if [ -n "${DISPLAY:-}" ]; then
  exec build/bin/RefractionDemo "$@"
fi
exec xvfb-run -a -s "-screen 0 1280x1024x24" build/bin/RefractionDemo "$@"
