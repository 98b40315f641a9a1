#!/usr/bin/env bash
# The main job (scripts/run) builds the glossy command alone, not the tests and benchmarks, and
# scripts/setup without --target (scripts/test's call) still builds everything. Run on a copy of the two
# scripts with cmake, the package installer and glossy itself replaced by stubs that record their calls.
# Usage: main_job_test.sh SOURCE_DIR
set -euo pipefail
source_dir=$1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mkdir -p "$tmp/repo/scripts" "$tmp/repo/build/renderer" "$tmp/bin"
cp "$source_dir/scripts/run" "$source_dir/scripts/setup" "$tmp/repo/scripts/"
printf '#!/bin/sh\nexit 0\n' > "$tmp/repo/scripts/install-packages"
touch "$tmp/repo/build/build.ninja"  # configured: setup only builds
printf '#!/bin/sh\necho "cmake $*" >> "%s/calls"\n' "$tmp" > "$tmp/bin/cmake"
printf '#!/bin/sh\necho "glossy $*" >> "%s/calls"\n' "$tmp" > "$tmp/repo/build/renderer/glossy"
chmod +x "$tmp/repo/scripts/"* "$tmp/bin/cmake" "$tmp/repo/build/renderer/glossy"

fail() { echo "main_job_test: $*" >&2; echo "calls:" >&2; cat "$tmp/calls" >&2 || true; exit 1; }

PATH="$tmp/bin:$PATH" GLOSSY_MERL_DIR=/nonexistent "$tmp/repo/scripts/run" --spp 4
grep -qx "cmake --build build --target glossy" "$tmp/calls" || fail "scripts/run does not build the glossy target alone"
grep -q "^glossy sheet .*--spp 4$" "$tmp/calls" || fail "scripts/run does not render the sheet"

rm "$tmp/calls"
PATH="$tmp/bin:$PATH" "$tmp/repo/scripts/setup" build
grep -qx "cmake --build build" "$tmp/calls" || fail "scripts/setup without --target does not build every target"
echo "main_job_test: ok"
