#!/usr/bin/env bash
# Every test: install what is missing, build, run ctest (under Xvfb when there is no display).
# Extra arguments go to ctest (for example -L unit).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/build.sh
cd build
if [ -n "${DISPLAY:-}" ]; then
  exec ctest --output-on-failure "$@"
fi
exec xvfb-run -a -s "-screen 0 1280x1024x24" ctest --output-on-failure "$@"
