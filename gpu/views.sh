#!/bin/sh
# Issue 19 on the H200 (EGL): error in view against shots and time for progressive, importance-
# and perspective-driven shooting, still camera in room 0 of the 16-room building and the
# walkthrough through its doors; prints the summary tables (about 1-2 minutes of GPU time).
# Run from the repository root with B set to the binary, e.g. B="./run --backend egl" or
# B="build/hemirad"; the CSVs and SVG plots go to ${OUT:-/tmp/views-egl}.
set -eu
B=${B:-build/hemirad}
OUT=${OUT:-/tmp/views-egl}
$B experiment --scenes scenes/building/building_16.obj --elements 4000 --width 128 --height 128 \
  --camera-path docs/experiments/views/still.path --fps 1 --frame-shots 16 --out-dir "$OUT/still"
$B experiment --scenes scenes/building/building_16.obj --elements 4000 --width 128 --height 128 \
  --fps 2 --frame-shots 32 --out-dir "$OUT/walk"
