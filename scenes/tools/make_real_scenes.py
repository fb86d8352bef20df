#!/usr/bin/env python3
"""Builds the real-scene benchmark suite (docs/real-scenes.md): closed rooms lit by ceiling panels
and furnished with CC0 models from Debian's sweethome3d-furniture package (its BlendSwap-CC-0
library, OBJ+MTL), at about 20k, 400k and 1M triangles, as OBJ+MTL and a .camera each.

    python3 scenes/tools/make_real_scenes.py [--out build/real_scenes] [--cache ~/.cache/hemirad]
                                              [--scenes real_20k,real_400k,real_1m]

Downloads the package once into the cache (apt-get download: Debian's own client), checks the
library's checksum and every used model's own license file (CC0), and writes the scenes
deterministically: the same package gives byte-identical files. Nothing here is committed.
"""
import argparse
import glob
import hashlib
import math
import os
import re
import shutil
import subprocess
import sys
import zipfile

PACKAGE, VERSION = "sweethome3d-furniture", "1.8-1"
LIBRARY = "usr/share/sweethome3d/furniture/BlendSwap-CC-0.sh3f"
LIBRARY_SHA256 = "7ef093fe70cedbb160bdb532d86a84580459635e34130c16777f549eba1993dc"

# Placements in centimetres within a bay (the catalogue's unit): (model folder, x, z, degrees
# about +y, elevation). A model's front faces +z; 90 degrees turns it to face +x.
LIVING = [
    ("L_shaped_sofa", 140, 80, 0, 0), ("couch", 50, 300, 90, 0),
    ("modernArmchair", 160, 290, 180, 0), ("modernArmchair", 280, 290, 180, 0),
    ("televisionCabinet", 150, 460, 180, 0), ("bookcase", 310, 20, 0, 0),
    ("pianoAQueue", 450, 100, 0, 0), ("pianoBench", 450, 205, 0, 0),
    ("decorativePlant", 560, 35, 0, 0), ("radiator1", 400, 492, 180, 10),
    ("oakTable", 470, 350, 0, 0), ("orchids", 470, 350, 0, 74.1),
    ("oakChair", 470, 255, 0, 0), ("oakChair", 470, 445, 180, 0),
    ("oakChair", 375, 350, 90, 0), ("oakChair", 565, 350, 270, 0),
]
MEDIUM = [m for m in LIVING if m[0] in ("L_shaped_sofa", "bookcase", "oakTable", "pianoAQueue", "radiator1")]
DINING = [m for m in LIVING if m[0] in ("L_shaped_sofa", "bookcase", "oakTable", "oakChair", "pianoAQueue")]
LIGHT = [
    ("couch2", 125, 90, 0, 0), ("armchair2", 400, 100, 0, 0), ("tableWithTablecloth", 300, 270, 0, 0),
    ("chair2", 300, 200, 0, 0), ("chair2", 300, 340, 180, 0), ("osakaChair", 220, 270, 90, 0),
    ("bookcase", 20, 300, 90, 0), ("shelves", 420, 375, 180, 0),
]
# Scenes: bays side by side along x, each bay (width, depth) cm with two ceiling panels.
SCENES = {
    "real_20k": {"bay": (500, 400), "bays": [LIGHT]},
    "real_80k": {"bay": (600, 500), "bays": [MEDIUM]},
    "real_400k": {"bay": (600, 500), "bays": [LIVING]},
    "real_1m": {"bay": (600, 500), "bays": [LIVING, LIVING, DINING]},
}
HEIGHT, PANEL = 260.0, 80.0  # room height, light panel side (cm)
ROOM_MATERIALS = ("newmtl wall\nKd 0.75 0.73 0.7\n\nnewmtl floor\nKd 0.45 0.35 0.25\n\n"
                  "newmtl ceiling\nKd 0.8 0.8 0.8\n\nnewmtl light\nKd 0.8 0.8 0.8\nKe 12 11 9\n\n")


def fail(message):
    print(f"make_real_scenes: error: {message}", file=sys.stderr)
    sys.exit(1)


def fetch_library(cache):
    """The CC0 library (.sh3f, a zip), downloaded and unpacked into `cache` once (the package's
    other libraries, CC-BY, and the .deb are not kept)."""
    folder = os.path.join(cache, "sweethome3d-furniture")
    sh3f = os.path.join(folder, LIBRARY)
    if not os.path.exists(sh3f):
        os.makedirs(folder, exist_ok=True)
        try:
            subprocess.run(["apt-get", "download", f"{PACKAGE}={VERSION}"], cwd=folder, check=True)
            deb = glob.glob(os.path.join(folder, f"{PACKAGE}_*.deb"))[0]
            tar = subprocess.run(["dpkg-deb", "--fsys-tarfile", deb], check=True, capture_output=True).stdout
            subprocess.run(["tar", "-x", "-C", folder, "./" + LIBRARY], input=tar, check=True)
            os.remove(deb)
        except (OSError, subprocess.CalledProcessError, IndexError) as e:
            fail(f"cannot fetch {PACKAGE} {VERSION} with apt-get download / dpkg-deb: {e}")
    with open(sh3f, "rb") as fh:
        digest = hashlib.sha256(fh.read()).hexdigest()
    if digest != LIBRARY_SHA256:
        fail(f"{sh3f}: sha256 {digest}, expected {LIBRARY_SHA256} ({PACKAGE} {VERSION})")
    unpacked = os.path.join(folder, "BlendSwap-CC-0")
    if not os.path.exists(os.path.join(unpacked, "PluginFurnitureCatalog.properties")):
        zipfile.ZipFile(sh3f).extractall(unpacked)
    return unpacked


def read_catalog(library):
    """Catalogue entries by model folder: size (cm), model path, creator, optional rotation."""
    entries = {}
    with open(os.path.join(library, "PluginFurnitureCatalog.properties"), encoding="latin-1") as fh:
        for line in fh:
            m = re.match(r"(\w+)#(\d+)=(.*)", line.strip())
            if m:
                entries.setdefault(int(m.group(2)), {})[m.group(1)] = m.group(3)
    return {e["model"].split("/")[2]: e for e in entries.values()}


def check_cc0(library, folder):
    """Refuses a model whose own license file does not release it under CC0 (two of the
    library's models say CC-BY 3.0 there)."""
    files = glob.glob(os.path.join(library, "blendswap-cc-0", folder, "*[Ll][Ii][Cc][Ee][Nn][Ss][Ee]*"))
    text = open(files[0], encoding="latin-1").read() if files else ""
    if "Creative Commons Zero" not in text or "Released under Creative Commons Attribution" in text:
        fail(f"{folder}: its license file does not state CC0")
    return os.path.basename(files[0])


def read_mtl(path):
    """Material name -> reflectance: Kd, times 0.6 where a texture (map_Kd) would have scaled it
    (its mean is unknown here), at most 0.85 so no surface reflects everything."""
    materials, name = {}, None
    for line in open(path, encoding="latin-1") if os.path.exists(path) else []:
        w = line.split()
        if w and w[0] == "newmtl":
            name = " ".join(w[1:])
            materials[name] = [[0.6, 0.6, 0.6], False]
        elif name and w and w[0] == "Kd" and len(w) >= 4:
            materials[name][0] = [float(x) for x in w[1:4]]
        elif name and w and w[0] == "map_Kd":
            materials[name][1] = True
    return {n: [min(0.85, c * (0.6 if textured else 1.0)) for c in kd] for n, (kd, textured) in materials.items()}


def read_obj(path):
    """Vertices and faces (material name, 0-based vertex indices) of an OBJ."""
    vertices, faces, material = [], [], ""
    for line in open(path, encoding="latin-1"):
        w = line.split()
        if not w:
            continue
        if w[0] == "v":
            vertices.append([float(x) for x in w[1:4]])
        elif w[0] == "usemtl":
            material = " ".join(w[1:])
        elif w[0] == "f" and len(w) >= 4:
            ids = [int(t.split("/")[0]) for t in w[1:]]
            faces.append((material, [i - 1 if i > 0 else len(vertices) + i for i in ids]))
    return vertices, faces


class Model:
    """One catalogue model, scaled to its catalogue size (cm), standing on y = 0, centred in x and z."""
    def __init__(self, library, folder, entry):
        self.folder, self.entry = folder, entry
        self.license = check_cc0(library, folder)
        obj = os.path.join(library, entry["model"].lstrip("/"))
        vertices, self.faces = read_obj(obj)
        self.materials = read_mtl(os.path.splitext(obj)[0] + ".mtl")
        if "modelRotation" in entry:
            r = [float(x) for x in entry["modelRotation"].split()]
            vertices = [[sum(r[3 * i + j] * v[j] for j in range(3)) for i in range(3)] for v in vertices]
        lo = [min(v[i] for v in vertices) for i in range(3)]
        hi = [max(v[i] for v in vertices) for i in range(3)]
        size = [float(entry["width"]), float(entry["height"]), float(entry["depth"])]
        s = [size[i] / (hi[i] - lo[i]) for i in range(3)]
        self.vertices = [[(v[0] - (lo[0] + hi[0]) / 2) * s[0], (v[1] - lo[1]) * s[1],
                          (v[2] - (lo[2] + hi[2]) / 2) * s[2]] for v in vertices]

    def triangles(self):
        return sum(len(f) - 2 for _, f in self.faces)


class ObjWriter:
    """Streams OBJ lines, counting vertices, polygons, triangles and objects."""
    def __init__(self, fh, mtl):
        self.fh, self.vertices, self.polygons, self.triangles, self.objects = fh, 0, 0, 0, 0
        fh.write(f"mtllib {mtl}\n")

    def group(self, name, faces):
        """faces: (material, [[x, y, z] in metres]) in order; consecutive faces share no vertices."""
        self.fh.write(f"o {name}\n")
        self.objects += 1
        current = None
        for material, poly in faces:
            if material != current:
                self.fh.write(f"usemtl {material}\n")
                current = material
            self.fh.write("".join(f"v {x:.5f} {y:.5f} {z:.5f}\n" for x, y, z in poly))
            self.fh.write("f " + " ".join(str(self.vertices + k + 1) for k in range(len(poly))) + "\n")
            self.vertices += len(poly)
            self.polygons += 1
            self.triangles += len(poly) - 2

    def instance(self, name, model, x, z, degrees, elevation):
        """The model turned by `degrees` about +y and stood at (x, elevation, z) cm, in metres,
        its vertices written once and shared by its faces."""
        c, s = math.cos(math.radians(degrees)), math.sin(math.radians(degrees))
        self.fh.write(f"o {name}\n")
        self.objects += 1
        self.fh.write("".join(f"v {(vx * c + vz * s + x) / 100:.5f} {(vy + elevation) / 100:.5f} "
                              f"{(-vx * s + vz * c + z) / 100:.5f}\n" for vx, vy, vz in model.vertices))
        current = None
        for material, face in model.faces:
            if material != current:
                self.fh.write(f"usemtl {mtl_name(model.folder, material)}\n")
                current = material
            self.fh.write("f " + " ".join(str(self.vertices + i + 1) for i in face) + "\n")
            self.polygons += 1
            self.triangles += len(face) - 2
        self.vertices += len(model.vertices)


def mtl_name(folder, material):
    return re.sub(r"[^A-Za-z0-9_.-]", "_", f"{folder}.{material}")


def room_faces(width, depth, panels):
    """Floor, four walls and the ceiling (cut around the light panels, which sit in its holes),
    in metres, counter-clockwise seen from inside."""
    W, D, H = width / 100, depth / 100, HEIGHT / 100
    faces = [("floor", [[0, 0, 0], [0, 0, D], [W, 0, D], [W, 0, 0]]),
             ("wall", [[0, 0, 0], [W, 0, 0], [W, H, 0], [0, H, 0]]),
             ("wall", [[W, 0, D], [0, 0, D], [0, H, D], [W, H, D]]),
             ("wall", [[0, 0, D], [0, 0, 0], [0, H, 0], [0, H, D]]),
             ("wall", [[W, 0, 0], [W, 0, D], [W, H, D], [W, H, 0]])]
    xs = sorted({0, width} | {p[0] for p in panels} | {p[1] for p in panels})
    zs = sorted({0, depth} | {p[2] for p in panels} | {p[3] for p in panels})
    for x0, x1 in zip(xs, xs[1:]):
        for z0, z1 in zip(zs, zs[1:]):
            lit = any(p[0] <= x0 and x1 <= p[1] and p[2] <= z0 and z1 <= p[3] for p in panels)
            a, b, c, d = x0 / 100, x1 / 100, z0 / 100, z1 / 100
            faces.append(("light" if lit else "ceiling", [[a, H, c], [b, H, c], [b, H, d], [a, H, d]]))
    return faces


def write_scene(out, name, spec, models):
    """Writes NAME.obj, NAME.mtl and NAME.camera; returns the ObjWriter's counts."""
    (bw, bd), bays = spec["bay"], spec["bays"]
    width = bw * len(bays)
    panels = [(k * bw + f * bw - PANEL / 2, k * bw + f * bw + PANEL / 2, bd / 2 - PANEL / 2, bd / 2 + PANEL / 2)
              for k in range(len(bays)) for f in (0.25, 0.75)]
    used = {}
    with open(os.path.join(out, name + ".obj"), "w") as fh:
        fh.write(f"# {name}: written by scenes/tools/make_real_scenes.py (docs/real-scenes.md); "
                 f"units: metres; furniture: CC0 models of Debian's {PACKAGE} {VERSION}\n")
        w = ObjWriter(fh, name + ".mtl")
        room = [(m, f) for m, f in room_faces(width, bd, panels) if m != "light"]
        w.group("room", room)
        w.group("lights", [(m, f) for m, f in room_faces(width, bd, panels) if m == "light"])
        for k, bay in enumerate(bays):
            for n, (folder, x, z, degrees, elevation) in enumerate(bay):
                model = models[folder]
                w.instance(f"bay{k}_{n:02d}_{folder}", model, k * bw + x, z, degrees, elevation)
                for m, _ in model.faces:
                    used[mtl_name(folder, m)] = model.materials.get(m, [0.6, 0.6, 0.6])
    with open(os.path.join(out, name + ".mtl"), "w") as fh:
        fh.write("# Room and light, then the models' Kd (x0.6 where textured, at most 0.85). Ke: emitted radiosity.\n")
        fh.write(ROOM_MATERIALS + "".join(f"newmtl {m}\nKd {kd[0]:.4g} {kd[1]:.4g} {kd[2]:.4g}\n\n"
                                          for m, kd in sorted(used.items())))
    W, D = width / 100, bd / 100
    with open(os.path.join(out, name + ".camera"), "w") as fh:
        fh.write("# From the corner at the front right, eye height, across the room.\n"
                 f"eye={W - 0.4:g},1.6,{D - 0.4:g} target={min(W * 0.45, 3.0):g},0.6,{D * 0.3:g} up=0,1,0 fov=60\n")
    return w


def write_furnace(out, name):
    """Writes NAME_furnace.obj/.mtl/.camera: NAME with every material rho 0.5 and E 1, where every
    visible point has B = E / (1 - rho) = 2 whatever the geometry (docs/real-scenes.md)."""
    furnace = name + "_furnace"
    with open(os.path.join(out, name + ".obj")) as src, open(os.path.join(out, furnace + ".obj"), "w") as fh:
        for line in src:
            fh.write(f"mtllib {furnace}.mtl\n" if line.startswith("mtllib ") else line)
    with open(os.path.join(out, name + ".mtl")) as src:
        names = [line.split()[1] for line in src if line.startswith("newmtl ")]
    with open(os.path.join(out, furnace + ".mtl"), "w") as fh:
        fh.write("# The furnace: every material rho 0.5, E 1.\n")
        fh.write("".join(f"newmtl {m}\nKd 0.5 0.5 0.5\nKe 1 1 1\n\n" for m in names))
    shutil.copyfile(os.path.join(out, name + ".camera"), os.path.join(out, furnace + ".camera"))


def main():
    ap = argparse.ArgumentParser(description="Builds the real-scene benchmark suite (docs/real-scenes.md).")
    ap.add_argument("--out", default="build/real_scenes", help="folder for the scenes (default build/real_scenes)")
    ap.add_argument("--cache", default=os.path.join(os.path.expanduser("~"), ".cache", "hemirad"),
                    help="download cache (default ~/.cache/hemirad)")
    ap.add_argument("--scenes", default=",".join(SCENES), help=f"comma-separated, of {','.join(SCENES)}")
    ap.add_argument("--furnace", action="store_true",
                    help="also write NAME_furnace: every material rho 0.5 and E 1, so B = 2 wherever seen")
    args = ap.parse_args()
    names = args.scenes.split(",")
    for n in names:
        if n not in SCENES:
            fail(f"--scenes: unknown scene '{n}' (known: {', '.join(SCENES)})")
    library = fetch_library(args.cache)
    catalog = read_catalog(library)
    folders = sorted({m[0] for n in names for bay in SCENES[n]["bays"] for m in bay})
    models = {f: Model(library, f, catalog[f]) for f in folders}
    os.makedirs(args.out, exist_ok=True)
    print("| scene | triangles | polygons | objects | vertices | file |\n|---|---|---|---|---|---|")
    for n in names:
        w = write_scene(args.out, n, SCENES[n], models)
        if args.furnace:
            write_furnace(args.out, n)
        print(f"| {n} | {w.triangles} | {w.polygons} | {w.objects} | {w.vertices} | "
              f"{os.path.join(args.out, n + '.obj')} |")
    print("\n| model | creator | triangles | license file |\n|---|---|---|---|")
    for f, m in models.items():
        print(f"| {f} | {m.entry.get('creator', '?')} | {m.triangles()} | {m.license} |")


if __name__ == "__main__":
    main()
