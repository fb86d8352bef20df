#!/bin/sh
# Issue 19 on the H200 (EGL): error in view against shots and time for progressive, importance-
# and perspective-driven shooting: a still camera in room 0 of the 4-, 16- and 64-room buildings,
# and the walkthrough through the 16-room building's doors with a budget of shots per frame and
# with one of solver time per frame (where perspective-driven shooting's saved gathers would
# show). Prints the summary tables; a few minutes of GPU time.
# Run from the repository root with B the binary: B=".gpu/run" (hemirad-bench from ci/gpu-bundle:
# CSVs and summaries, no figures) or B="build/hemirad"; BACKEND (egl); out to ${OUT:-/tmp/views-egl}.
set -eu
B=${B:-build/hemirad}
BACKEND=${BACKEND:-egl}
OUT=${OUT:-/tmp/views-egl}
still=$PWD/docs/experiments/views/still.path
x() { $B experiment --backend "$BACKEND" --elements 4000 --width 128 --height 128 "$@"; }
for n in 4 16 64; do
  x --scenes scenes/building/building_$n.obj --camera-path "$still" --fps 1 --frame-shots 16 --out-dir "$OUT/building_${n}_still"
done
x --scenes scenes/building/building_16.obj --fps 2 --frame-shots 32 --out-dir "$OUT/building_16_walk"
x --scenes scenes/building/building_16.obj --fps 2 --frame-ms 10 --out-dir "$OUT/building_16_walk_10ms"
