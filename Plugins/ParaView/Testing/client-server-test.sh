#!/usr/bin/env bash
# Runs a pvpython client script against pvserver on N MPI ranks (N = 1: plain pvserver),
# both under one private Xvfb server (with-xvfb.sh), with python3-paraview's unpacked
# Python package on PYTHONPATH (see pvbatch-test.sh). The server listens on a free port
# of localhost; the client gets --server localhost:<port>. The server ends when the
# client disconnects; it is stopped if it has not 30 s later.
# With "split" for N: a separate data server and render server (pvdataserver and
# pvrenderserver, one process each); the client also gets --render-server localhost:<port>.
# Usage: client-server-test.sh <ranks|split> <client.py> [client args...]
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
# Two free ports of localhost, from two sockets open at once (so never the same one).
read -r port render_port < <(/usr/bin/python3 -c '
import socket
a, b = socket.socket(), socket.socket()
a.bind(("localhost", 0))
b.bind(("localhost", 0))
print(a.getsockname()[1], b.getsockname()[1])')
servers=() # pids
logs=()
start_server() { # start_server <command...>: in the background, its output in a log
  local log
  log="$(mktemp "${TMPDIR:-/tmp}/pvserver.XXXXXX")"
  "$@" > "$log" 2>&1 &
  servers+=($!)
  logs+=("$log")
}
stop_servers() {
  for server in "${servers[@]}"; do
    for _ in $(seq 60); do
      kill -0 "$server" 2> /dev/null || break
      sleep 0.5
    done
    if kill -0 "$server" 2> /dev/null; then
      echo "client-server-test.sh: server $server still running; stopping it" >&2
      kill "$server" 2> /dev/null || true
    fi
    wait "$server" 2> /dev/null || true
  done
  for log in "${logs[@]}"; do
    echo "--- server output ($log):"
    cat "$log"
    rm -f "$log"
  done
}
trap stop_servers EXIT
client_args=(--server "localhost:$port")
if [ "$ranks" = split ]; then
  start_server pvdataserver --data-server-port="$port"
  start_server pvrenderserver --force-offscreen-rendering --render-server-port="$render_port"
  client_args+=(--render-server "localhost:$render_port")
else
  server_cmd=(pvserver --force-offscreen-rendering --server-port="$port")
  if [ "$ranks" -gt 1 ]; then
    mpi=(--oversubscribe)
    [ "$(id -u)" -eq 0 ] && mpi+=(--allow-run-as-root)
    server_cmd=(mpirun "${mpi[@]}" -np "$ranks" "${server_cmd[@]}")
  fi
  start_server "${server_cmd[@]}"
fi
for i in "${!servers[@]}"; do
  for _ in $(seq 120); do
    grep -q "Accepting connection" "${logs[$i]}" && break
    if ! kill -0 "${servers[$i]}" 2> /dev/null; then
      echo "client-server-test.sh: a server did not start" >&2
      exit 1
    fi
    sleep 0.5
  done
  grep -q "Accepting connection" "${logs[$i]}" ||
    { echo "a server did not listen in 60 s" >&2; exit 1; }
done
echo "server(s) (${ranks}) listen: ${client_args[*]}"
"$python_root/bin/pvpython" --force-offscreen-rendering "$script" "${client_args[@]}" "$@"
