#!/usr/bin/env bash
# Runs a command with an X display: Debian's VTK 9.1 is X11/GLX only, so renders need one
# even offscreen. Uses the current DISPLAY if set, else a private Xvfb server.
set -euo pipefail
if [ -n "${DISPLAY:-}" ]; then
  exec "$@"
fi
exec xvfb-run -a -s "-screen 0 1280x1024x24" "$@"
