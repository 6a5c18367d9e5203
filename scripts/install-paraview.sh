#!/usr/bin/env bash
# Installs what the ParaView plugin needs on Debian bookworm, next to the project's VTK 9.1
# (scripts/install-deps.sh), and prepares a prefix that find_package(ParaView) and pvbatch
# can use without installing python3-paraview. Idempotent.
#
#  - paraview, paraview-dev (ParaView 5.11 with its own VTK 9.2, libvtk*-pv5.11.so),
#    openmpi-bin (mpirun), xvfb, xauth, python3-numpy (the tests compare images with it).
#  - python3-paraview is NEVER installed: it conflicts with python3-vtk9 (both own
#    dist-packages/vtkmodules) and apt would remove the VTK this project builds on. Its
#    .deb is unpacked with dpkg -x into $prefix/python3-paraview instead: pvbatch needs its
#    Python package (paraview.simple), and ParaView's CMake config names its files.
#  - $prefix/overlay/usr: looks like /usr (symbolic links) except for a real copy of
#    ParaView's CMake folder (a link would resolve back to /usr and the config would compute
#    the wrong prefix), and lib/python3/dist-packages, lib/x86_64-linux-gnu/vtk (wrap
#    hierarchy files) and bin/pvpython* taken from the unpacked package.
#
# Prefix: $CLUSTERED_LIGHTING_PARAVIEW_PREFIX, default /opt/clustered-lighting/paraview-5.11.
# Prints nothing but a summary when everything is in place already.
set -euo pipefail
prefix=${CLUSTERED_LIGHTING_PARAVIEW_PREFIX:-/opt/clustered-lighting/paraview-5.11}
multiarch=x86_64-linux-gnu

SUDO=""
[ "$(id -u)" -ne 0 ] && SUDO="sudo"
export DEBIAN_FRONTEND=noninteractive

pkgs=(paraview paraview-dev openmpi-bin xvfb xauth python3-numpy)
missing=()
for p in "${pkgs[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if dpkg-query -W -f='${Status}' python3-paraview 2>/dev/null | grep -q "install ok installed"; then
  echo "python3-paraview is installed: it conflicts with python3-vtk9, which this project" \
    "needs. Remove it (apt-get remove python3-paraview) and reinstall python3-vtk9." >&2
  exit 1
fi
if [ ${#missing[@]} -gt 0 ]; then
  echo "== apt-get install ${missing[*]}"
  $SUDO apt-get update -qq
  $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" > /dev/null
fi

version=$(dpkg-query -W -f='${Version}' paraview)
stamp="$prefix/.ready-$version"
if [ -f "$stamp" ]; then
  echo "ParaView $version: overlay prefix $prefix/overlay ready"
  exit 0
fi

echo "== unpack python3-paraview $version into $prefix/python3-paraview"
$SUDO rm -rf "$prefix"
$SUDO mkdir -p "$prefix"
$SUDO chown "$(id -u):$(id -g)" "$prefix"
download="$(mktemp -d "${TMPDIR:-/tmp}/python3-paraview.XXXXXX")"
trap 'rm -rf "$download"' EXIT
(cd "$download" && apt-get download -qq -o APT::Sandbox::User=root "python3-paraview=$version")
dpkg -x "$download"/python3-paraview_*.deb "$prefix/python3-paraview"
py="$prefix/python3-paraview/usr"
test -f "$py/lib/python3/dist-packages/paraview/simple.py"
test -d "$py/lib/$multiarch/vtk/hierarchy"

echo "== overlay prefix $prefix/overlay/usr"
o="$prefix/overlay/usr"
mkdir -p "$o/lib/$multiarch/cmake" "$o/lib/python3" "$o/bin"
link_all_but() { # link_all_but <from dir> <to dir> <names to skip...>
  local from=$1 to=$2 e skip
  shift 2
  for e in "$from"/* "$from"/.[!.]*; do
    [ -e "$e" ] || [ -L "$e" ] || continue
    for skip in "$@"; do
      [ "$(basename "$e")" = "$skip" ] && continue 2
    done
    ln -s "$e" "$to/$(basename "$e")"
  done
}
link_all_but /usr "$o" lib bin
link_all_but /usr/bin "$o/bin"
link_all_but "$py/bin" "$o/bin"
link_all_but /usr/lib "$o/lib" "$multiarch" python3
link_all_but /usr/lib/python3 "$o/lib/python3" dist-packages
ln -s "$py/lib/python3/dist-packages" "$o/lib/python3/dist-packages"
link_all_but "/usr/lib/$multiarch" "$o/lib/$multiarch" cmake vtk
ln -s "$py/lib/$multiarch/vtk" "$o/lib/$multiarch/vtk"
link_all_but "/usr/lib/$multiarch/cmake" "$o/lib/$multiarch/cmake" paraview-5.11
cp -r "/usr/lib/$multiarch/cmake/paraview-5.11" "$o/lib/$multiarch/cmake/"
touch "$stamp"
echo "ParaView $version: overlay prefix $prefix/overlay ready"
