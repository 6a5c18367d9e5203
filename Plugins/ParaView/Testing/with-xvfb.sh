#!/usr/bin/env bash
# Runs a command with DISPLAY set to a private Xvfb server (ParaView 5.11 in Debian is
# X11-only: pvbatch and paraview need an X display even for offscreen rendering).
# The server picks a free display number itself (-displayfd), so runs in parallel never
# collide, and a number another X server holds is never reused (xvfb-run -a once picked
# such a number). -noreset: an X server resets when its last client leaves and refuses
# connections meanwhile (see scripts/with-display.sh). The server is stopped at the end;
# the command's exit code is returned.
# Usage: with-xvfb.sh command [args...]   (XVFB_SCREEN overrides 1280x1024x24)
set -euo pipefail
dir="$(mktemp -d "${TMPDIR:-/tmp}/with-xvfb.XXXXXX")"
: > "$dir/display" # exists before the server starts writing to it
Xvfb -displayfd 3 -screen 0 "${XVFB_SCREEN:-1280x1024x24}" -noreset -nolisten tcp \
  3>> "$dir/display" 2> "$dir/xvfb.log" &
xvfb_pid=$!
cleanup() {
  kill "$xvfb_pid" 2> /dev/null || true
  wait "$xvfb_pid" 2> /dev/null || true
  rm -rf "$dir"
}
trap cleanup EXIT
# Xvfb writes the display number and a newline once it accepts connections.
for _ in $(seq 200); do
  if [ "$(wc -l < "$dir/display")" -ge 1 ]; then
    break
  fi
  if ! kill -0 "$xvfb_pid" 2> /dev/null; then
    echo "with-xvfb.sh: Xvfb did not start:" >&2
    cat "$dir/xvfb.log" >&2
    exit 1
  fi
  sleep 0.05
done
display="$(head -n 1 "$dir/display")"
if [ -z "$display" ]; then
  echo "with-xvfb.sh: Xvfb gave no display number in 10 s" >&2
  exit 1
fi
export DISPLAY=":$display"
rc=0
"$@" || rc=$?
exit "$rc"
