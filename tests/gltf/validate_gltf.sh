#!/usr/bin/env bash
# ctest (tests/CMakeLists.txt): hemirad's .glb exports pass Khronos's glTF-Validator (the npm
# package gltf-validator, pinned, cached across runs: npm_cache.sh) with no error and no warning.
# Checked: the Cornell box baked from its OBJ, the same baked from the shipped glTF
# (scenes/cornell/cornell.gltf), the OBJ's bake written to a stream (--gltf /dev/stdout: the .glb
# alone, no EXR beside it), and the shipped cornell.gltf itself (an input, external resources
# resolved beside it). hemirad writes no .gltf (--gltf takes .glb only). Infos and hints are
# printed, not counted (each bake has 8 UNUSED_OBJECT for TEXCOORD_0, there for material textures
# that no material has, and IMAGE_NPOT_DIMENSIONS for the lightmap). Exit 77 (skipped) without
# node or the npm registry. Usage: validate_gltf.sh HEMIRAD SOURCE_DIR
set -euo pipefail
hemirad=$1 src=$2
validator_version=2.0.0-dev.3.10
. "$src/tests/gltf/npm_cache.sh"
npm_package gltf-validator "$validator_version" 9b09225db864fe3f0a584259f65d087e2213a93a
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
bake() {  # bake SCENE OUT.glb
  "$hemirad" solve "$src/$1" --elements 2000 --gltf "$2" 2>"$tmp/solve.log" >/dev/null ||
    { echo "hemirad solve $1 --elements 2000 --gltf $2 failed:"; cat "$tmp/solve.log"; exit 1; }
  echo "hemirad solve $1 --elements 2000 --gltf $(basename "$2"): $(head -1 "$tmp/solve.log")"
}
bake scenes/cornell/cornell.obj "$tmp/cornell.glb"
bake scenes/cornell/cornell.gltf "$tmp/cornell-from-gltf.glb"
"$hemirad" solve "$src/scenes/cornell/cornell.obj" --elements 2000 --gltf /dev/stdout >"$tmp/stream.glb" 2>"$tmp/solve.log" ||
  { echo "hemirad solve --gltf /dev/stdout failed:"; cat "$tmp/solve.log"; exit 1; }
cd "$tmp"
node "$src/tests/gltf/validate.mjs" "$npm_modules" cornell.glb cornell-from-gltf.glb stream.glb \
  "$src/scenes/cornell/cornell.gltf"
