#!/usr/bin/env bash
# TestGlassMPIServer.sh RANKS PLUGIN OUTPUT_DIR: pvserver on RANKS MPI ranks, and a pvpython
# client connected to it that renders TestGlassMPI.py's pictures remotely (the server's ranks
# render and composite; the client receives the image).
set -euo pipefail
ranks=$1
plugin=$2
output=$3
here="$(cd "$(dirname "$0")" && pwd)"
mkdir -p "$output"
# A free port: the server says which one it listens on (--server-port=0 is not understood by
# ParaView 5.11), so try a few in a high range.
port=$(( 20000 + (RANDOM % 20000) ))
# stdbuf: pvserver's "Accepting connection(s)" would otherwise wait in its output buffer.
mpiexec --oversubscribe -n "$ranks" stdbuf -oL pvserver --server-port="$port" \
  > "$output/server.log" 2>&1 &
server=$!
trap 'kill "$server" 2>/dev/null || true; wait "$server" 2>/dev/null || true' EXIT
for _ in $(seq 1 120); do
  grep -q "Accepting connection" "$output/server.log" 2>/dev/null && break
  if ! kill -0 "$server" 2>/dev/null; then
    echo "pvserver exited:"; cat "$output/server.log"; exit 1
  fi
  sleep 0.5
done
grep -q "Accepting connection" "$output/server.log" || { echo "pvserver did not start:"; cat "$output/server.log"; exit 1; }
pvpython "$here/TestGlassMPI.py" client "127.0.0.1:$port" "$plugin" "$output" "$ranks"
