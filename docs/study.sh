#!/usr/bin/env bash
# The hemisphere-artifact study (issue 4): GPU item-buffer visibility and form factors against
# the exact CPU reference, at item-mesh levels L = 0..6, two item-buffer budgets, orthographic
# (seed 003's map, named stereographic before issue 27) and hemicube, on the Cornell box and its 4 x 4-subdivided variant. Writes docs/validation/.
# Run after ci/build:   docs/study.sh
set -euo pipefail
cd "$(dirname "$0")/.."
out=docs/validation
mkdir -p "$out"
for scene in scenes/cornell/cornell.obj scenes/cornell_subdivided/cornell_x4.obj; do
  name=$(basename "$scene" .obj)
  build/hemirad validate "$scene" --levels 0,1,2,3,4,5,6 --item-res 256,512 --hemisphere orthographic,hemicube \
    --shooters 16 --report "$out/$name.json" --figures "$out/$name" | tee "$out/$name.md"
done
