#!/usr/bin/env bash
# Runs a pvbatch script on N MPI ranks (N = 1: plain pvbatch) under a private Xvfb server
# (with-xvfb.sh), with python3-paraview's unpacked Python package on PYTHONPATH for
# pvbatch only (scripts/install-paraview.sh; never for the VTK 9.1 build).
# Usage: pvbatch-test.sh <ranks> <script.py> [script args...]
# CLUSTERED_LIGHTING_PARAVIEW_PREFIX: the prefix of scripts/install-paraview.sh.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
ranks=$1
shift
prefix=${CLUSTERED_LIGHTING_PARAVIEW_PREFIX:-/opt/clustered-lighting/paraview-5.11}
# The script's folder too, for its helper module (clustered_test.py).
export PYTHONPATH="$prefix/python3-paraview/usr/lib/python3/dist-packages:$(cd "$(dirname "$1")" && pwd)"
if [ "$ranks" -eq 1 ]; then
  cmd=(pvbatch --force-offscreen-rendering "$@")
else
  mpi=(--oversubscribe) # more ranks than cores is fine for a test
  [ "$(id -u)" -eq 0 ] && mpi+=(--allow-run-as-root)
  cmd=(mpirun "${mpi[@]}" -np "$ranks" pvbatch --force-offscreen-rendering "$@")
fi
exec "$here/with-xvfb.sh" "${cmd[@]}"
