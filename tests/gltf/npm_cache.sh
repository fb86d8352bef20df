# Sourced by validate_gltf.sh and render_threejs.sh: npm_package NAME VERSION SHA1 puts the pinned
# npm package (its registry tarball, checked against the registry's sha1; both packages have no
# dependencies, so no npm is needed) into ${XDG_CACHE_HOME:-$HOME/.cache}/hemirad/npm/NAME-VERSION,
# reused across runs, and sets $npm_modules to its node_modules. Exits 77 (skipped) with one line
# where node is missing or the registry does not answer within 20 s.
npm_package() {
  local name=$1 version=$2 sha1=$3
  command -v node >/dev/null || { echo "node is not installed (Debian package nodejs): skipped"; exit 77; }
  local dir=${XDG_CACHE_HOME:-$HOME/.cache}/hemirad/npm/$name-$version
  npm_modules=$dir/node_modules
  [ -f "$npm_modules/$name/package.json" ] && return 0
  # Into a fresh folder, then renamed into place: tests run in parallel (ctest -j) never see half
  # an install.
  mkdir -p "$(dirname "$dir")"
  local part status=0
  part=$(mktemp -d "$dir.part.XXXXXX")
  /usr/bin/python3 - "https://registry.npmjs.org/$name/-/$name-$version.tgz" "$sha1" "$part/package.tgz" <<'PY' || status=$?
import hashlib, sys, urllib.request
url, sha1, out = sys.argv[1:]
try:
    data = urllib.request.urlopen(url, timeout=20).read()
except OSError as e:
    print(f"the npm registry did not answer for {url} within 20 s ({e}): skipped")
    sys.exit(77)
if hashlib.sha1(data).hexdigest() != sha1:
    print(f"{url}: sha1 {hashlib.sha1(data).hexdigest()}, pinned {sha1}")
    sys.exit(1)
open(out, "wb").write(data)
PY
  [ "$status" -eq 0 ] || { rm -rf "$part"; exit "$status"; }
  mkdir -p "$part/node_modules/$name"
  tar -xzf "$part/package.tgz" -C "$part/node_modules/$name" --strip-components=1
  rm -f "$part/package.tgz"
  rm -rf "$dir" 2>/dev/null || true
  mv -T "$part" "$dir" 2>/dev/null || rm -rf "$part"  # another run got there first: keep its copy
}
