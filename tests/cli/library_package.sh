#!/usr/bin/env bash
# The installed CMake package: `cmake --install` of this build into a temporary prefix, then the separate
# project examples/library configured with find_package(hullopt), built and run.
set -euo pipefail
bin=$1
build_dir=$(cd "$(dirname "$bin")/.." && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cmake --install "$build_dir" --prefix "$tmp/prefix" > "$tmp/install.log"
test -f "$tmp/prefix/include/hullopt/hullopt.h"
test -f "$tmp/prefix/lib/cmake/hullopt/hulloptConfig.cmake"
# The executables: hullopt and, beside it, hullopt-calibrate, which runs `hullopt calibrate`.
test -x "$tmp/prefix/bin/hullopt"
test -x "$tmp/prefix/bin/hullopt-calibrate"
"$tmp/prefix/bin/hullopt" calibrate examples/calibrate_synthetic.yaml --out "$tmp/calibrate" --quiet
test -s "$tmp/calibrate/calibration.json"
# Every installed header is under include/hullopt/, and only those the entry header reaches: no io/ or app/.
others=$(ls "$tmp/prefix/include" | grep -vx hullopt || true)
[ -z "$others" ] || { echo "headers installed outside include/hullopt: $others"; exit 1; }
if [ -d "$tmp/prefix/include/hullopt/io" ] || [ -d "$tmp/prefix/include/hullopt/app" ]; then
  echo "private headers installed"; exit 1
fi
test -f "$tmp/prefix/include/hullopt/seas/wave_spectrum.h"
# A sanitized build (HULLOPT_SANITIZE) installs instrumented static libraries: the consumer links the runtimes.
extra=()
grep -q '^HULLOPT_SANITIZE:BOOL=ON' "$build_dir/CMakeCache.txt" && extra=(-DCMAKE_EXE_LINKER_FLAGS=-fsanitize=address,undefined)
cmake -S examples/library -B "$tmp/build" -DCMAKE_PREFIX_PATH="$tmp/prefix" -DCMAKE_BUILD_TYPE=Release "${extra[@]}" \
  > "$tmp/configure.log" 2>&1 || { cat "$tmp/configure.log"; exit 1; }
cmake --build "$tmp/build" -j2 > "$tmp/build.log" 2>&1 || { cat "$tmp/build.log"; exit 1; }
out=$("$tmp/build/npl5b_msi")
echo "$out"
echo "$out" | grep -q "mean MSI"
