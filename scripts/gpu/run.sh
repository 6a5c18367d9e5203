#!/usr/bin/env bash
# On a bare headless NVIDIA GPU machine, from the repository root, with .gpu/ from
# scripts/gpu/make-bundle.sh and the build's files it names: starts Xvfb, checks that a
# GLX window renders on the GPU (through libglx-over-egl.so), runs the GL tests, then the
# benchmark. Writes tests.txt, test-logs.tgz, bench.log and bench.tgz to $OUT (default
# ./gpu-out). Run as root (it unpacks libglvnd and Xvfb's files into /).
# Environment: VARIANTS (names of library variants, see the end), REQUIRE_GPU=0 runs on whatever renders (to try the harness without a GPU), BENCH_S (seconds the benchmark may run, default 280; it prints each row as
# it is measured), BENCH_ARGS (e.g. --filter REGEX), TESTS=0 to skip the tests, TEST_JOBS (tests run at once, default 1).
set -uo pipefail
here="$PWD"
out="${OUT:-$here/gpu-out}"
mkdir -p "$out"
start=$(date +%s)
for f in .gpu/gl/*.deb; do dpkg -x "$f" /; done
ldconfig
root="$(cat .gpu/root.txt)"
[ -e "$root" ] || { mkdir -p "$(dirname "$root")" && ln -s "$here" "$root"; }
mkdir -p /opt/clustered-gpu && tar -C /opt/clustered-gpu -xJf .gpu/bundle.tar.xz
b=/opt/clustered-gpu
[ -e /usr/bin/xkbcomp ] || cp $b/bin/xkbcomp /usr/bin/
mkdir -p /usr/share/X11 && { [ -e /usr/share/X11/xkb ] || cp -r $b/xkb /usr/share/X11/xkb; }
mkdir -p /usr/share/glmark2/models && xz -dc .gpu/bunny.obj.xz > /usr/share/glmark2/models/bunny.obj
vendor=/usr/local/nvidia/share/glvnd/egl_vendor.d/10_nvidia.json
[ -e $vendor ] || vendor=$(find / -name 10_nvidia.json -not -path '/proc/*' 2>/dev/null | head -1)
nvidia-smi -L
export LD_LIBRARY_PATH=$b/lib
[ -z "$vendor" ] || export __EGL_VENDOR_LIBRARY_FILENAMES=$vendor
# Without its GLX extension (which would need Mesa's software driver): the shim answers
# every GLX call on the client's side and draws through EGL.
$b/bin/Xvfb :7 -screen 0 1280x1024x24 -noreset -extension GLX > /tmp/xvfb.log 2>&1 &
xvfb=$!
trap 'kill $xvfb 2>/dev/null' EXIT
sleep 2
export DISPLAY=:7 __GL_SHADER_DISK_CACHE=0 LD_PRELOAD=$here/.gpu/libglx-over-egl.so
.gpu/gl-info | tee "$out/gl-info.txt" || { cat /tmp/xvfb.log; exit 3; }
[ "${REQUIRE_GPU:-1}" = 0 ] || grep -q NVIDIA "$out/gl-info.txt" || { echo "not rendering on the GPU (REQUIRE_GPU=0 runs anyway)"; exit 4; }
echo "set up in $(($(date +%s) - start)) s"
if [ "${TESTS:-1}" != 0 ]; then
  bash .gpu/tests.sh 2>&1 | tee "$out/tests.txt"
  tar -C /tmp -czf "$out/test-logs.tgz" gpu-tests
  echo "tests done at $(($(date +%s) - start)) s"
fi
cd "$root" || exit 5
args=()
eval "args=(${BENCH_ARGS:-})" # BENCH_ARGS is shell words: quote a regex in it
bench() { # bench <name> <library path>: the benchmark's rows, to $out/<name>.log
  LD_LIBRARY_PATH="$2" timeout "${BENCH_S:-280}" build/Testing/Benchmark/ClusteredLightingBenchmark \
    --output "/tmp/gpu-$1" "${args[@]}" > "$out/$1.log" 2>&1
  echo "$1: benchmark exit $? at $(($(date +%s) - start)) s (124: stopped at BENCH_S; the log has every row measured)"
}
bench bench "$b/lib"
tar -C /tmp -czf "$out/bench.tgz" gpu-bench 2>/dev/null
# Variants of the library to compare side by side in the same session: each is a folder
# .gpu/variants/NAME holding a libvtkRenderingClustered.so built from changed code; the
# benchmark (the same rows) runs again with it first on the library path.
for v in ${VARIANTS:-}; do
  bench "bench-$v" "$here/.gpu/variants/$v:$b/lib"
done
true
