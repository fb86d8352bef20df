#!/bin/sh
# Issue 16 on the H200: instant radiosity frames per second at 1024 x 1024, 128..512 VPLs,
# forward and deferred, interleave 1 (every VPL at every pixel: the exact path) and 4, 8
# (interleaved sampling), full frame (trace + shadow maps + shading) and shading only (a
# camera move: the shadow maps kept; what seed 002 timed). About a minute of GPU time.
# B is the bench binary with its backend, e.g. B="./hemirad-bench --backend egl".
set -eu
B=${B:-"./hemirad-bench --backend egl"}
OUT=${OUT:-.}
# The exact path is slow: fewer frames a row.
$B --method instant --vpls 128,256,384,512 --interleave 1 --width 1024 --height 1024 --shots 16 \
  --json "$OUT/instant-h200-exact.json" --markdown "$OUT/instant-h200-exact.md"
$B --method instant --vpls 128,256,384,512 --interleave 4,8 --width 1024 --height 1024 --shots 128 \
  --json "$OUT/instant-h200-interleaved.json" --markdown "$OUT/instant-h200-interleaved.md"
