#!/usr/bin/env bash
# Installs what the build, the demo and the tests need on Debian bookworm, only what is
# missing: as root directly, through sudo otherwise. Safe to run again.
set -euo pipefail
packages=(cmake g++ make pkg-config libvtk9-dev libglew-dev libegl-dev libegl-mesa0
  libgl1-mesa-dri xvfb xauth libopenimageio-dev libembree-dev)
# The Python wrapping (vtk_module_wrap_python) and the python tests: VTK's Python modules and
# wrapper tools, and the headers of the system python3 they were built for.
packages+=(python3-vtk9 python3-dev)
# clang with libFuzzer (Debian keeps it in libclang-rt-14-dev): the fuzz test of the C core.
packages+=(clang libclang-rt-14-dev)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi
echo "setup: installing ${missing[*]}"
run=()
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "setup: need root or sudo to install ${missing[*]}" >&2; exit 1; }
  run=(sudo)
fi
export DEBIAN_FRONTEND=noninteractive
"${run[@]}" apt-get update -qq
"${run[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
