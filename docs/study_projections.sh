#!/usr/bin/env bash
# The four-projection study (issue 27): orthographic (seed 003's), hemicube, conformal (the true
# stereographic map) and equal-area item buffers against the exact CPU reference on the Cornell
# box, at item-mesh levels L = 0..5 and budgets of 256^2 and 512^2 pixels. Writes
# docs/validation/projections{.json,.md,/} (about a minute and a half on 2 cores).
# Run after ci/build:   docs/study_projections.sh
set -euo pipefail
cd "$(dirname "$0")/.."
out=docs/validation
mkdir -p "$out"
build/hemirad validate scenes/cornell/cornell.obj --levels 0,1,2,3,4,5 --item-res 256,512 --hemisphere all \
  --shooters 16 --report "$out/projections.json" --figures "$out/projections" | tee "$out/projections.md"
