#!/usr/bin/env bash
# Runs a command with an X display: Debian's VTK 9.1 is X11/GLX only, so renders need one
# even offscreen. Uses the current DISPLAY if set, else a private Xvfb server.
# -noreset: an X server resets when its last client disconnects, and a connection made
# during the reset fails. VTK makes one whenever a program destroys its only window and
# creates another, and aborts when it fails ("bad X server connection"): without
# -noreset the Python test aborted in 13 runs of 150 (ctest Display.ReopenAfterLastClient).
set -euo pipefail
if [ -n "${DISPLAY:-}" ]; then
  exec "$@"
fi
exec xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" "$@"
