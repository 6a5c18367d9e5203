#!/usr/bin/env bash
# Runs clang-tidy (bugprone-*, performance-*; see .clang-tidy) on the GL-free core,
# Rendering/Core/*.h, through Testing/Lint/ClangTidyCore.cxx, which includes every core
# header. Fails on any finding. CLANG_TIDY may name the executable.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
tidy=${CLANG_TIDY:-$(command -v clang-tidy || command -v clang-tidy-14 || true)}
if [ -z "$tidy" ]; then
  echo "clang-tidy not found (scripts/install-deps.sh installs it)" >&2
  exit 1
fi
cd "$root"
# Every core header must be reached through the translation unit.
for h in Rendering/Core/*.h; do
  grep -q "#include \"$(basename "$h")\"" Testing/Lint/ClangTidyCore.cxx || {
    echo "Testing/Lint/ClangTidyCore.cxx does not include $h" >&2
    exit 1
  }
done
"$tidy" --quiet Testing/Lint/ClangTidyCore.cxx -- -std=c++17 -IRendering/Core
echo "clang-tidy: no findings in Rendering/Core ($("$tidy" --version | grep -o 'version [0-9.]*'))"
