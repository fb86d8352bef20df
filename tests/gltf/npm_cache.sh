# Sourced by validate_gltf.sh and render_threejs.sh: npm_package NAME VERSION installs the pinned
# npm package into ${XDG_CACHE_HOME:-$HOME/.cache}/hemirad/npm/NAME-VERSION (reused across runs:
# no registry needed once there) and sets $npm_modules to its node_modules. Exits 77 (skipped)
# with one line where node or npm is missing or the registry does not answer within 20 s.
npm_package() {
  local name=$1 version=$2
  command -v node >/dev/null || { echo "node is not installed (Debian package nodejs): skipped"; exit 77; }
  local dir=${XDG_CACHE_HOME:-$HOME/.cache}/hemirad/npm/$name-$version
  npm_modules=$dir/node_modules
  if [ "$(node -p "require('$npm_modules/$name/package.json').version" 2>/dev/null)" = "$version" ]; then
    return 0
  fi
  command -v npm >/dev/null || { echo "npm is not installed (Debian package npm): skipped"; exit 77; }
  timeout 20 npm view "$name@$version" version >/dev/null 2>&1 ||
    { echo "the npm registry ($(npm config get registry 2>/dev/null)) did not answer for $name@$version within 20 s: skipped"; exit 77; }
  # Into a fresh folder, then renamed into place: tests run in parallel (ctest -j) never see half
  # an install.
  mkdir -p "$(dirname "$dir")"
  local part
  part=$(mktemp -d "$dir.part.XXXXXX")
  if ! timeout 120 npm install --prefix "$part" --no-save --no-package-lock --no-audit --no-fund \
       "$name@$version" >"$part/npm.log" 2>&1; then
    echo "npm install $name@$version failed:"; cat "$part/npm.log"; rm -rf "$part"; exit 1
  fi
  rm -rf "$dir" 2>/dev/null || true
  mv -T "$part" "$dir" 2>/dev/null || rm -rf "$part"  # another run got there first: keep its copy
}
