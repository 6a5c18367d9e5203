#!/usr/bin/env bash
# Runs a pvpython client script against pvserver on N MPI ranks (N = 1: plain pvserver),
# both under one private Xvfb server (with-xvfb.sh), with python3-paraview's unpacked
# Python package on PYTHONPATH (see pvbatch-test.sh). The server listens on a free port
# of localhost; the client gets --server localhost:<port>. The server ends when the
# client disconnects; it is stopped if it has not 30 s later.
# Usage: client-server-test.sh <ranks> <client.py> [client args...]
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
if [ -z "${CLUSTERED_LIGHTING_IN_XVFB:-}" ]; then
  exec "$here/with-xvfb.sh" env CLUSTERED_LIGHTING_IN_XVFB=1 "$0" "$@"
fi
ranks=$1
script=$2
shift 2
prefix=${CLUSTERED_LIGHTING_PARAVIEW_PREFIX:-/opt/clustered-lighting/paraview-5.11}
python_root="$prefix/python3-paraview/usr"
export PYTHONPATH="$python_root/lib/python3/dist-packages:$(cd "$(dirname "$script")" && pwd)"
port=$(/usr/bin/python3 -c \
  'import socket; s = socket.socket(); s.bind(("localhost", 0)); print(s.getsockname()[1])')
log="$(mktemp "${TMPDIR:-/tmp}/pvserver.XXXXXX")"
server_cmd=(pvserver --force-offscreen-rendering --server-port="$port")
if [ "$ranks" -gt 1 ]; then
  mpi=(--oversubscribe)
  [ "$(id -u)" -eq 0 ] && mpi+=(--allow-run-as-root)
  server_cmd=(mpirun "${mpi[@]}" -np "$ranks" "${server_cmd[@]}")
fi
"${server_cmd[@]}" > "$log" 2>&1 &
server=$!
stop_server() {
  for _ in $(seq 60); do
    kill -0 "$server" 2> /dev/null || break
    sleep 0.5
  done
  if kill -0 "$server" 2> /dev/null; then
    echo "client-server-test.sh: pvserver still running; stopping it" >&2
    kill "$server" 2> /dev/null || true
  fi
  wait "$server" 2> /dev/null || true
  echo "--- pvserver's output:"
  cat "$log"
  rm -f "$log"
}
trap stop_server EXIT
for _ in $(seq 120); do
  grep -q "Accepting connection" "$log" && break
  if ! kill -0 "$server" 2> /dev/null; then
    echo "client-server-test.sh: pvserver did not start" >&2
    exit 1
  fi
  sleep 0.5
done
grep -q "Accepting connection" "$log" || { echo "pvserver did not listen in 60 s" >&2; exit 1; }
echo "pvserver on $ranks rank(s) listens on localhost:$port"
"$python_root/bin/pvpython" --force-offscreen-rendering "$script" \
  --server "localhost:$port" "$@"
