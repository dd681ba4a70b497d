#!/usr/bin/env bash
# Every test: install what is missing, build, run ctest (under Xvfb when there is no display).
# Extra arguments go to ctest (for example -L unit).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/build.sh
cd build
# The stability table (written by the stability tests) is printed after the run.
table=Testing/stability/stability.md
rm -f "$table"
status=0
if [ -n "${DISPLAY:-}" ]; then
  ctest --output-on-failure "$@" || status=$?
else
  xvfb-run -a -s "-screen 0 1280x1024x24" ctest --output-on-failure "$@" || status=$?
fi
if [ -f "$table" ]; then
  echo
  cat "$table"
fi
exit "$status"
