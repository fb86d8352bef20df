#!/usr/bin/env bash
# ctest (tests/CMakeLists.txt): `cmake --install` into a fresh prefix; this folder's consumer built
# against it with find_package(hemirad) and, separately, with pkg-config; both load the Cornell box
# and must print `hemirad info`'s polygon count. Then the installed hemirad runs bench from an
# empty folder: the default scene comes from PREFIX/share/hemirad, not the source tree.
# Usage: consumer.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
build=$(cd "$1" && pwd) src=$(cd "$2" && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
prefix=$tmp/prefix
cmake --install "$build" --prefix "$prefix" >"$tmp/install.log"
for f in bin/hemirad bin/hemirad-bench lib/cmake/hemirad/hemiradConfig.cmake lib/cmake/hemirad/hemiradTargets.cmake \
         lib/pkgconfig/hemirad.pc include/hemirad/src/scene/SceneLoader.h lib/libhemirad_scene.a \
         share/hemirad/scenes/cornell/cornell.obj share/hemirad/python/plot.py; do
  [ -e "$prefix/$f" ] || { echo "not installed: $f"; exit 1; }
done
scene=$src/scenes/cornell/cornell.obj
expected=$("$prefix/bin/hemirad" info "$scene" | grep '^polygons')
echo "hemirad info: $expected"

# The source tree must play no part: the consumer sees only the prefix.
cmake -S "$src/tests/install" -B "$tmp/cmake" -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$prefix" \
  -DCMAKE_CXX_FLAGS=-O0 >"$tmp/configure.log" || { cat "$tmp/configure.log"; exit 1; }
cmake --build "$tmp/cmake" >"$tmp/build.log" || { cat "$tmp/build.log"; exit 1; }
got=$("$tmp/cmake/consumer" "$scene")
echo "find_package consumer: $got"
[ "$got" = "$expected" ]
# A baker: solve and export a lightmap (the packer is stb's, the writer tinygltf's).
"$tmp/cmake/consumer" "$scene" "$tmp/fp.glb" | grep '^lightmap'
[ "$(head -c 4 "$tmp/fp.glb")" = glTF ]

export PKG_CONFIG_PATH=$prefix/lib/pkgconfig
flags=$(pkg-config --cflags --libs hemirad)
c++ -std=c++20 -O0 -o "$tmp/pc-consumer" "$src/tests/install/main.cpp" $flags
got=$("$tmp/pc-consumer" "$scene")
echo "pkg-config consumer ($(pkg-config --modversion hemirad)): $got"
[ "$got" = "$expected" ]
"$tmp/pc-consumer" "$scene" "$tmp/pc.glb" | grep '^lightmap'
[ "$(head -c 4 "$tmp/pc.glb")" = glTF ]

mkdir "$tmp/elsewhere"
cd "$tmp/elsewhere"
"$prefix/bin/hemirad" bench --elements 300 --split-shots 4 --json bench.json >bench.log
grep -q "\"scene\": \"$prefix/share/hemirad/scenes/cornell/cornell.obj\"" bench.json ||
  { echo "bench did not use the installed scene:"; cat bench.json; exit 1; }
echo "installed bench from $PWD: $(grep -c '"scene"' bench.json) row on $prefix/share/hemirad/scenes/cornell/cornell.obj"
# The README's first example, as written, from an empty folder: the shipped scene.
"$prefix/bin/hemirad" solve scenes/cornell/cornell.obj --elements 300 --shots 4 --image cornell.png --quiet
[ -s cornell.png ] && echo "installed solve from $PWD: the README's scene path found in $prefix/share/hemirad"
