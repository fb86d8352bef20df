#!/usr/bin/env bash
# ctest (tests/CMakeLists.txt): the .glb of `hemirad solve --gltf` rendered in three.js.
# Usage: render_threejs.sh HEMIRAD SOURCE_DIR (render_threejs.py does the work; see there).
# Exit 77 (skipped) without chromium, node or the npm registry (three pinned, cached across runs).
set -euo pipefail
hemirad=$1 src=$2
three_version=0.187.0
browser=$(command -v chromium || command -v chromium-browser || true)
[ -n "$browser" ] || { echo "chromium is not installed (Debian package chromium): skipped"; exit 77; }
. "$src/tests/gltf/npm_cache.sh"
npm_package three "$three_version" face29ee2de9bcc31a1b573a76f224e35e0b2894
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
/usr/bin/python3 "$src/tests/gltf/render_threejs.py" "$hemirad" "$src" "$npm_modules" "$browser" "$tmp"
