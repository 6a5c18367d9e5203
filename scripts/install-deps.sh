#!/usr/bin/env bash
# Installs what ClusteredLighting needs on a fresh Debian bookworm machine.
# Idempotent: packages already present are skipped by apt.
set -euo pipefail

pkgs=(
  build-essential cmake ninja-build pkg-config
  libvtk9-dev python3-vtk9          # VTK 9.1 (X11/GLX build) and its Python
  python3-numpy                     # clusteredlighting.light_set_from_numpy / _to_numpy
  libpython3-dev                    # Python wrapping (headers; also pulled in by libvtk9-dev)
  libglm-dev                        # GL-free math core
  libgtest-dev googletest           # core unit tests
  clang-tidy                        # lint of the GL-free core (scripts/run-clang-tidy.sh)
  xvfb xauth                        # every render runs under xvfb-run
  libgl1-mesa-dri mesa-utils        # llvmpipe
  glmark2-data                      # Stanford bunny (bunny.obj)
  assimp-utils assimp-testmodels    # FZK-Haus interior (IFC -> OBJ)
)

missing=()
for p in "${pkgs[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  SUDO=""
  [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get update -qq
  $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
