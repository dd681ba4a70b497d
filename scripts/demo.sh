#!/usr/bin/env bash
# The main job: install what is missing, build, and run the demo on built-in data.
# Without a display it renders through EGL (no X server), falling back to Xvfb, and writes
# out/demo/frame_NNNN.png and the frame times; with a display, pass --interactive for a
# window. Extra arguments go to RefractionDemo.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/build.sh
if [ -n "${DISPLAY:-}" ]; then
  exec build/bin/RefractionDemo "$@"
fi
rc=0
build/bin/RefractionDemo --egl "$@" || rc=$?
if [ "$rc" -eq 3 ]; then
  echo "demo: no EGL context, trying an X server (xvfb-run)"
  exec xvfb-run -a -s "-screen 0 1280x1024x24" build/bin/RefractionDemo "$@"
fi
exit "$rc"
