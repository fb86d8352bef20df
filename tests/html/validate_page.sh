#!/usr/bin/env bash
# ctest (tests/CMakeLists.txt): validate --figures' index.html loaded in headless Chromium. A page
# of this test's own holds the report in an iframe and, once it has loaded, lists the report's
# tables with their body row counts and its images with whether each decoded; Chromium's
# --dump-dom prints that list. Every table must have the rows the JSON report says, every image
# (the SVG figures and PNG renders) must have loaded. Exit 77 (skipped) without chromium.
# Usage: validate_page.sh HEMIRAD SOURCE_DIR
set -euo pipefail
hemirad=$1 src=$2
browser=$(command -v chromium || command -v chromium-browser || true)
[ -n "$browser" ] || { echo "chromium is not installed (Debian package chromium): skipped"; exit 77; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$hemirad" validate "$src/scenes/cornell/cornell.obj" --elements 300 --levels 0,1 --shooters 2 \
  --hemisphere orthographic,hemicube --report "$tmp/v.json" --figures "$tmp/fig" >"$tmp/validate.log" 2>&1 ||
  { cat "$tmp/validate.log"; exit 1; }
cat >"$tmp/check.html" <<HTML
<!doctype html><html><body><pre id="result">not loaded</pre>
<iframe id="report" src="file://$tmp/fig/index.html" width="1200" height="900"></iframe>
<script>
document.getElementById('report').addEventListener('load', () => {
  const d = document.getElementById('report').contentDocument, out = [];
  for (const t of d.querySelectorAll('table')) out.push('table ' + t.id + ' ' + t.querySelectorAll('tbody tr').length);
  for (const i of d.images) out.push('image ' + i.getAttribute('src') + ' ' + (i.complete && i.naturalWidth > 0 ? 'loaded' : 'broken'));
  document.getElementById('result').textContent = out.join('\n');
});
</script></body></html>
HTML
"$browser" --headless --no-sandbox --disable-gpu --allow-file-access-from-files --virtual-time-budget=10000 \
  --dump-dom "file://$tmp/check.html" >"$tmp/dom.html" 2>"$tmp/chromium.log" || { cat "$tmp/chromium.log"; exit 1; }
/usr/bin/python3 - "$tmp" <<'PY'
import html, json, re, sys
tmp = sys.argv[1]
dom = open(f"{tmp}/dom.html").read()
lines = html.unescape(re.search(r'<pre id="result">(.*?)</pre>', dom, re.S).group(1)).splitlines()
report = json.load(open(f"{tmp}/v.json"))
page = open(f"{tmp}/fig/index.html").read()
tables = {l.split()[1]: int(l.split()[2]) for l in lines if l.startswith("table ")}
images = [l.split()[1:] for l in lines if l.startswith("image ")]
print("\n".join(lines))
expected = {"provenance": 5, "levels": len(report["levels"]), "form_factors": len(report["object_form_factors"])}
problems = [f"table {k}: {tables.get(k)} rows, expected {v}" for k, v in expected.items() if tables.get(k) != v]
problems += [f"image {src} did not load" for src, state in images if state != "loaded"]
if len(images) != page.count("<img ") or len(images) < 8:
    problems.append(f"{len(images)} images loaded of {page.count('<img ')} in the page")
problems += [f"{f} missing from the page" for f in ("agreement_vs_level.svg", "atlas_ff_error_L1.svg")
             if f"src=\"{f}\"" not in page]
print("\n".join(problems) or f"{len(tables)} tables with the report's row counts, {len(images)} images loaded")
sys.exit(1 if problems else 0)
PY
