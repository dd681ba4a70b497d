#!/usr/bin/env bash
# The ParaView stage of scripts/test.sh: builds the ParaView plugin and runs its tests
# (paraview/build-and-test.sh; arguments go to its ctest). ParaView 5.11's packages replace
# Debian's VTK 9.1 packages (libvtk9-dev, python3-vtk9: they conflict), so those are put back
# afterwards when the machine had them; the machine ends as it started, less the time.
# RF_SKIP_PARAVIEW=1 skips the stage (it says so).
set -euo pipefail
cd "$(dirname "$0")/.."
if [ "${RF_SKIP_PARAVIEW:-0}" = 1 ]; then
  echo "paraview stage: skipped (RF_SKIP_PARAVIEW=1)"
  exit 0
fi
restore=()
for p in libvtk9-dev python3-vtk9; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" && restore+=("$p")
done
set +e
RF_REPLACE_VTK=1 bash paraview/build-and-test.sh "$@"
status=$?
set -e
if [ ${#restore[@]} -gt 0 ]; then
  echo "paraview stage: putting back ${restore[*]} (ParaView's packages replaced them)"
  run=()
  [ "$(id -u)" -ne 0 ] && run=(sudo)
  DEBIAN_FRONTEND=noninteractive "${run[@]}" apt-get install -y -qq --no-install-recommends \
    "${restore[@]}" >/dev/null
fi
exit "$status"
