#!/usr/bin/env bash
# The error-versus-run-time benchmark: installs what it needs (glmark2-data for the Stanford
# bunny), builds, and writes bench/results/<host-kind>/{results.csv,results.md,pareto.png}.
# Extra arguments go to RefractionBenchmark (for example --sizes 256,512 --frames 30).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
if ! dpkg-query -W -f='${Status}' glmark2-data 2>/dev/null | grep -q "install ok installed"; then
  run=()
  [ "$(id -u)" -ne 0 ] && run=(sudo)
  DEBIAN_FRONTEND=noninteractive "${run[@]}" apt-get install -y -qq --no-install-recommends glmark2-data \
    || { "${run[@]}" apt-get update -qq && DEBIAN_FRONTEND=noninteractive "${run[@]}" apt-get install -y -qq --no-install-recommends glmark2-data; }
fi
bash scripts/build.sh
exec build/bin/RefractionBenchmark "$@"
