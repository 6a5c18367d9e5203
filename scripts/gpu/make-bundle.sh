#!/usr/bin/env bash
# Packs into .gpu/ what scripts/gpu/run.sh needs to run this build's GL tests and the
# benchmark on a bare headless NVIDIA GPU machine (no X server, no VTK, no network):
#   gl/            libglvnd's loaders (Debian packages, unpacked there)
#   bundle.tar.xz  Debian's VTK and every other library the tests and the benchmark load,
#                  and Xvfb with its keymaps (started without its GLX extension: the shim
#                  answers every GLX call on the client's side)
#   libglx-over-egl.so, gl-info   (scripts/gpu/README.md)
#   bunny.obj.xz   the benchmark's mesh; tests.sh   the GL tests' ctest command lines
# Run it here after scripts/build.sh; then send the checkout with .gpu/ and the build's
# bin, lib, data, Examples/ManyLights and Testing/Benchmark/ClusteredLightingBenchmark.
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
build="$(cd "${1:-$root/build}" && pwd)"
out="$root/.gpu"
rm -rf "$out" && mkdir -p "$out/gl"
stage="$(mktemp -d)"
trap 'rm -rf "$stage"' EXIT
mkdir -p "$stage/lib" "$stage/bin"

# libglvnd's loaders, as Debian packages (the GPU machine's driver brings the vendor side).
(cd "$out/gl" && apt-get download libegl1 libglvnd0 libopengl0 libgl1 libglx0 libgles2 2>/dev/null)

# Every library the programs load, except the C and C++ runtimes (the machine has newer
# ones), libglvnd's (above) and this module's own, which comes with the build's lib/ (a
# copy here would go first on the library path there, and a stale one crashes the
# programs built with a newer header).
programs=("$build/bin/vtkRenderingClusteredCxxTests" "$build/Examples/ManyLights"
  "$build/Testing/Benchmark/ClusteredLightingBenchmark" /usr/bin/Xvfb /usr/bin/xkbcomp)
skip='^(libvtkRenderingClustered|libc|libm|libdl|libpthread|librt|ld-linux-x86-64|libstdc\+\+|libgcc_s|libGL|libGLX|libGLdispatch|libOpenGL|libEGL|libGLESv2)\.so'
for p in "${programs[@]}"; do ldd "$p" | awk '$3 ~ /^\// { print $3 }'; done | sort -u |
  while read -r lib; do
    basename "$lib" | grep -Eq "$skip" || cp -L "$lib" "$stage/lib/"
  done
cp /usr/bin/Xvfb /usr/bin/xkbcomp "$stage/bin/"
cp -r /usr/share/X11/xkb "$stage/xkb"
tar -C "$stage" -cf - . | xz -T0 -6 > "$out/bundle.tar.xz"

gcc -O2 -shared -fPIC -o "$out/libglx-over-egl.so" "$root/scripts/gpu/glx-over-egl.c" -lEGL -lX11 -ldl
gcc -O2 -o "$out/gl-info" "$root/scripts/gpu/gl-info.c" -lGL -lX11
xz -6 -c /usr/share/glmark2/models/bunny.obj > "$out/bunny.obj.xz"

# The GL tests' command lines as ctest runs them (absolute paths into this checkout and
# build: run.sh links the machine's copy of the checkout to the same path).
echo "$root" > "$out/root.txt"
# shellcheck disable=SC2016 # the Python below writes shell code
(cd "$build" && ctest --show-only=json-v1) | /usr/bin/python3 -c '
import json, shlex, sys
tests = json.load(sys.stdin)["tests"]
print("#!/bin/bash")
print("# TEST_JOBS (default 1): how many tests run at once (each makes its own window)")
print("jobs_max=${TEST_JOBS:-1}")
print("rm -rf /tmp/gpu-tests; mkdir -p /tmp/gpu-tests " + shlex.quote(sys.argv[1] + "/Testing/Temporary"))
print("t() { # t NAME DIR COMMAND...: one test in the background, its log and result in /tmp/gpu-tests")
print("  local name=$1 dir=$2; shift 2")
print("  (mkdir -p \"$dir\" && cd \"$dir\" && s=$(date +%s%N) && timeout 120 \"$@\" > \"/tmp/gpu-tests/$name.log\" 2>&1")
print("   rc=$?; echo \"$name rc=$rc $(( ($(date +%s%N) - s) / 1000000 )) ms\" | tee \"/tmp/gpu-tests/$name.rc\") &")
print("  while [ \"$(jobs -rp | wc -l)\" -ge \"$jobs_max\" ]; do wait -n; done")
print("}")
for t in tests:
    command = t.get("command") or []
    if not command or not ("vtkRenderingClusteredCxxTests" in command[0] or t["name"] == "Example.ManyLights"):
        continue
    wd = [p["value"] for p in t.get("properties", []) if p["name"] == "WORKING_DIRECTORY"]
    wd = wd[0] if wd else "."
    name = t["name"].split("-")[-1]
    print(f"t {shlex.quote(name)} {shlex.quote(wd)} {shlex.join(command)}")
print("wait")
print("pass=$(grep -l \" rc=0 \" /tmp/gpu-tests/*.rc | wc -l); fail=$(grep -L \" rc=0 \" /tmp/gpu-tests/*.rc | wc -l)")
print("echo \"GL tests: $pass passed, $fail failed\"")
' "$build" > "$out/tests.sh"
du -sh "$out"
