#!/bin/sh
# Issue 19's measurement, as a new user makes it: four_boxes with its own camera, 200 shots of
# each algorithm, the camera image compared with a converged solve (0.999). RMS of the tone-mapped
# PNG (--image, each image auto-exposed, as the issue did) and of the linear render (--out .exr,
# the same quantity for all), each with the ambient term on (the preview's) and off (solve's default).
# Usage: docs/experiments/views/reproduce.sh [SCENE] [SHOTS]   (B=hemirad binary, default build/hemirad)
set -eu
B=${B:-build/hemirad}
S=${1:-scenes/four_boxes/four_boxes.obj}
N=${2:-200}
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
rms() { idiff -a "$1" "$2" 2>/dev/null | sed -n 's/.*RMS error = \([0-9.e+-]*\).*/\1/p' | head -1; }
$B solve "$S" --converge 0.999 --quiet --ambient off --out "$T/ref.exr" --image "$T/ref.png"
echo "| algorithm | ambient | PNG RMS (auto exposure) | linear RMS | linear RMS / mean |"
echo "|---|---|---|---|---|"
mean=$(oiiotool "$T/ref.exr" --printstats 2>/dev/null | sed -n 's/.*Stats Avg: *\([0-9.e+-]*\) \([0-9.e+-]*\) \([0-9.e+-]*\).*/\1 \2 \3/p' | head -1 |
       awk '{ print 0.2126 * $1 + 0.7152 * $2 + 0.0722 * $3 }')
for a in progressive importance perspective; do
  for amb in on off; do
    $B solve "$S" --algorithm $a --shots "$N" --quiet --ambient $amb --out "$T/$a-$amb.exr" --image "$T/$a-$amb.png"
    l=$(rms "$T/$a-$amb.exr" "$T/ref.exr")
    echo "| $a | $amb | $(rms "$T/$a-$amb.png" "$T/ref.png") | $l | $(awk -v l="$l" -v m="$mean" 'BEGIN { printf "%.4f", l / m }') |"
  done
done
