#!/usr/bin/env python3
"""Writes the shipped scenes (scenes/cornell, cornell_hung, cornell_subdivided, four_boxes,
analytic). Run from the repository root.

Every face is emitted counter-clockwise around its front normal: room faces face the room's
centre, block faces face away from their block's centre.
"""
import os

def sub(a, b): return [a[i] - b[i] for i in range(3)]
def cross(a, b): return [a[1]*b[2]-a[2]*b[1], a[2]*b[0]-a[0]*b[2], a[0]*b[1]-a[1]*b[0]]
def dot(a, b): return sum(a[i]*b[i] for i in range(3))
def centre(ps): return [sum(p[i] for p in ps) / len(ps) for i in range(3)]

def orient(face, towards=None, away=None):
    n = cross(sub(face[1], face[0]), sub(face[2], face[0]))
    c = centre(face)
    want = sub(towards, c) if towards else sub(c, away)
    return face if dot(n, want) > 0 else face[::-1]

class Obj:
    def __init__(self, mtl):
        self.lines = [f"mtllib {mtl}"]
        self.count = 0
    def group(self, name, material, faces):
        self.lines += [f"o {name}", f"usemtl {material}"]
        for f in faces:
            idx = []
            for p in f:
                self.lines.append("v " + " ".join(f"{x:g}" for x in p))
                self.count += 1
                idx.append(str(self.count))
            self.lines.append("f " + " ".join(idx))
    def write(self, path, header):
        with open(path, "w") as fh:
            fh.write("\n".join([f"# {l}" for l in header] + self.lines) + "\n")

def rect(x0, x1, z0, z1, y):
    return [[x0, y, z0], [x1, y, z0], [x1, y, z1], [x0, y, z1]]

# The Cornell box's blocks: top quads (x, y, z) and heights.
SHORT_BLOCK = [[130, 165, 65], [82, 165, 225], [240, 165, 272], [290, 165, 114]]
TALL_BLOCK = [[423, 330, 247], [265, 330, 296], [314, 330, 456], [472, 330, 406]]

def block_faces(top, h, ox=0.0, oz=0.0):
    """A block standing on y = 0 under the quad `top`, moved by (ox, 0, oz): top and four sides."""
    top = [[x + ox, y, z + oz] for x, y, z in top]
    c = centre(top)
    c[1] = h / 2
    faces = [orient([[x, h, z] for x, _, z in top], away=c)]
    for i in range(4):
        a, b = top[i], top[(i + 1) % 4]
        faces.append(orient([[a[0], 0, a[2]], [b[0], 0, b[2]], [b[0], h, b[2]], [a[0], h, a[2]]], away=c))
    return faces


def walls_and_blocks(o, X, Y, Z, mid):
    """The Cornell box's three walls and two blocks, into `o` (both Cornell scenes share them)."""
    o.group("back_wall", "white", [orient([[0, 0, Z], [X, 0, Z], [X, Y, Z], [0, Y, Z]], towards=mid)])
    o.group("left_wall", "red", [orient([[X, 0, 0], [X, 0, Z], [X, Y, Z], [X, Y, 0]], towards=mid)])
    o.group("right_wall", "green", [orient([[0, 0, 0], [0, 0, Z], [0, Y, Z], [0, Y, 0]], towards=mid)])
    o.group("short_block", "white", block_faces(SHORT_BLOCK, 165.0))
    o.group("tall_block", "white", block_faces(TALL_BLOCK, 330.0))


def cornell(folder):
    # Cornell's published box (graphics.cornell.edu/online/box/data.html), squared so every wall
    # is planar (the published walls are off-plane by up to 3.2 units), with a hole in the
    # ceiling for the light so no two faces overlap.
    X, Y, Z = 556.0, 548.8, 559.2
    mid = [X / 2, Y / 2, Z / 2]
    lx0, lx1, lz0, lz1 = 213.0, 343.0, 227.0, 332.0
    o = Obj("cornell.mtl")
    o.group("floor", "white", [orient(rect(0, X, 0, Z, 0), towards=mid)])
    ceiling = [rect(0, X, 0, lz0, Y), rect(0, X, lz1, Z, Y), rect(0, lx0, lz0, lz1, Y), rect(lx1, X, lz0, lz1, Y)]
    o.group("ceiling", "white", [orient(f, towards=mid) for f in ceiling])
    o.group("light", "light", [orient(rect(lx0, lx1, lz0, lz1, Y - 0.0), towards=mid)])
    walls_and_blocks(o, X, Y, Z, mid)
    o.write(os.path.join(folder, "cornell.obj"), [
        "Cornell box: Cornell's published geometry (units: mm), walls squared to be planar,",
        "ceiling split around the light. Written by scenes/tools/make_scenes.py."])
    with open(os.path.join(folder, "cornell.mtl"), "w") as fh:
        fh.write("# Reflectances: RGB fits of Cornell's measured spectra (as in pbrt-v4/Mitsuba).\n"
                 "# Ke is emitted radiosity.\n"
                 "newmtl white\nKd 0.725 0.71 0.68\n\n"
                 "newmtl red\nKd 0.63 0.065 0.05\n\n"
                 "newmtl green\nKd 0.14 0.45 0.091\n\n"
                 "newmtl light\nKd 0.78 0.78 0.78\nKe 17 12 4\n")
    with open(os.path.join(folder, "cornell.camera"), "w") as fh:
        fh.write("# Cornell's published camera: 35 mm lens, 25 mm film -> 39.3 degrees.\n"
                 "eye=278,273,-800 target=278,273,0 up=0,1,0 fov=39.3\n")

def cornell_hung(folder, gap=0.5):
    """The Cornell box with its light hung `gap` mm under a whole ceiling (issue 31's hung light):
    ceiling elements straddling the light's rim are half hidden above it, the D0 contact case."""
    X, Y, Z = 556.0, 548.8, 559.2
    mid = [X / 2, Y / 2, Z / 2]
    o = Obj("../cornell/cornell.mtl")
    o.group("floor", "white", [orient(rect(0, X, 0, Z, 0), towards=mid)])
    o.group("ceiling", "white", [orient(rect(0, X, 0, Z, Y), towards=mid)])
    o.group("light", "light", [orient(rect(213.0, 343.0, 227.0, 332.0, Y - gap), towards=mid)])
    walls_and_blocks(o, X, Y, Z, mid)
    o.write(os.path.join(folder, "cornell_hung.obj"), [
        f"The Cornell box (scenes/cornell, units: mm) with its light hung {gap:g} mm under a whole ceiling,",
        "emitting downward. Written by scenes/tools/make_scenes.py."])
    with open(os.path.join(folder, "cornell_hung.camera"), "w") as fh:
        fh.write("eye=278,273,-800 target=278,273,0 up=0,1,0 fov=39.3\n")

def subdivide(faces, n):
    """Splits each planar quad into n x n quads (the thesis's subdivided Cornell boxes)."""
    out = []
    for f in faces:
        a, b, c, d = f
        def at(u, v):
            return [a[i] + (b[i] - a[i]) * u + (d[i] - a[i]) * v + (a[i] - b[i] + c[i] - d[i]) * u * v for i in range(3)]
        for j in range(n):
            for i in range(n):
                out.append([at(i / n, j / n), at((i + 1) / n, j / n), at((i + 1) / n, (j + 1) / n), at(i / n, (j + 1) / n)])
    return out

def subdivided(src_obj, mtl, n):
    """The scene in src_obj (quads only) with every face split n x n, as an Obj using mtl."""
    src = open(src_obj).read().splitlines()
    o = Obj(mtl)
    verts, name, mtl, faces = [], None, None, []
    def flush():
        if name:
            o.group(name, mtl, subdivide(faces, n))
    for line in src:
        t = line.split()
        if not t or t[0] == "#":
            continue
        if t[0] == "v":
            verts.append([float(x) for x in t[1:4]])
        elif t[0] == "o":
            flush()
            name, faces = t[1], []
        elif t[0] == "usemtl":
            mtl = t[1]
        elif t[0] == "f":
            faces.append([verts[int(k) - 1] for k in t[1:]])
    flush()
    return o

def cornell_subdivided(folder, n):
    """The Cornell box with every face split n x n: n^2 times the polygons (and lights)."""
    o = subdivided("scenes/cornell/cornell.obj", "../cornell/cornell.mtl", n)
    o.write(os.path.join(folder, f"cornell_x{n}.obj"), [
        f"The Cornell box with every face split {n} x {n} (as the thesis's subdivided environments).",
        "Written by scenes/tools/make_scenes.py."])
    with open(os.path.join(folder, f"cornell_x{n}.camera"), "w") as fh:
        fh.write("eye=278,273,-800 target=278,273,0 up=0,1,0 fov=39.3\n")

def room_shell(o, k, ox, oz, X, Y, Z, lx0, lx1, lz0, lz1):
    """Room k's floor, its ceiling split around the light panel [lx0, lx1] x [lz0, lz1] (relative
    to the room's corner (ox, oz)), and the panel, all facing the room's centre."""
    mid = [ox + X / 2, Y / 2, oz + Z / 2]
    o.group(f"room{k}_floor", "white", [orient(rect(ox, ox + X, oz, oz + Z, 0), towards=mid)])
    ceiling = [rect(ox, ox + X, oz, oz + lz0, Y), rect(ox, ox + X, oz + lz1, oz + Z, Y),
               rect(ox, ox + lx0, oz + lz0, oz + lz1, Y), rect(ox + lx1, ox + X, oz + lz0, oz + lz1, Y)]
    o.group(f"room{k}_ceiling", "white", [orient(f, towards=mid) for f in ceiling])
    o.group(f"room{k}_light", "light", [orient(rect(ox + lx0, ox + lx1, oz + lz0, oz + lz1, Y), towards=mid)])
    return mid

FOUR_BOXES_CAMERA = "eye=150,450,40 target=278,150,559.2 up=0,1,0 fov=60"

def four_boxes(folder):
    """The thesis's multiple-enclosure environment: four closed Cornell rooms in a 2 x 2 grid,
    each with its own ceiling light and blocks, joined by doorways in the walls they share
    (walls 10 units thick), the camera inside room 0 looking at its doorway into room 2."""
    X, Y, Z, T = 556.0, 548.8, 559.2, 10.0
    lx0, lx1, lz0, lz1 = 213.0, 343.0, 227.0, 332.0
    DW, DH = 160.0, 300.0  # doorway width and height
    o = Obj("four_boxes.mtl")
    jambs = []
    def wall_x(x, z0, z1, door, towards):
        # The wall in the plane x, spanning z0..z1, with a centred doorway if door.
        if not door:
            return [orient([[x, 0, z0], [x, 0, z1], [x, Y, z1], [x, Y, z0]], towards=towards)]
        d0, d1 = (z0 + z1 - DW) / 2, (z0 + z1 + DW) / 2
        return [orient(f, towards=towards) for f in (
            [[x, 0, z0], [x, 0, d0], [x, Y, d0], [x, Y, z0]], [[x, 0, d1], [x, 0, z1], [x, Y, z1], [x, Y, d1]],
            [[x, DH, d0], [x, DH, d1], [x, Y, d1], [x, Y, d0]])]
    def wall_z(z, x0, x1, door, towards):
        if not door:
            return [orient([[x0, 0, z], [x1, 0, z], [x1, Y, z], [x0, Y, z]], towards=towards)]
        d0, d1 = (x0 + x1 - DW) / 2, (x0 + x1 + DW) / 2
        return [orient(f, towards=towards) for f in (
            [[x0, 0, z], [d0, 0, z], [d0, Y, z], [x0, Y, z]], [[d1, 0, z], [x1, 0, z], [x1, Y, z], [d1, Y, z]],
            [[d0, DH, z], [d1, DH, z], [d1, Y, z], [d0, Y, z]])]
    def doorway(axis, w, c):
        # The tunnel through a shared wall (plane `axis` = w .. w + T), centred at c along the wall.
        d0, d1 = c - DW / 2, c + DW / 2
        mid = [w + T / 2, DH / 2, c] if axis == "x" else [c, DH / 2, w + T / 2]
        def p(n, t, y):  # n along the wall's normal, t along the wall
            return [n, y, t] if axis == "x" else [t, y, n]
        for f in ([p(w, d0, 0), p(w + T, d0, 0), p(w + T, d0, DH), p(w, d0, DH)],
                  [p(w, d1, 0), p(w + T, d1, 0), p(w + T, d1, DH), p(w, d1, DH)],
                  [p(w, d0, DH), p(w + T, d0, DH), p(w + T, d1, DH), p(w, d1, DH)],
                  [p(w, d0, 0), p(w + T, d0, 0), p(w + T, d1, 0), p(w, d1, 0)]):
            jambs.append(orient(f, towards=mid))
    for j in range(2):
        for i in range(2):
            k, ox, oz = 2 * j + i, i * (X + T), j * (Z + T)
            mid = room_shell(o, k, ox, oz, X, Y, Z, lx0, lx1, lz0, lz1)
            o.group(f"room{k}_red_wall", "red", wall_x(ox + X, oz, oz + Z, i == 0, mid))
            o.group(f"room{k}_green_wall", "green", wall_x(ox, oz, oz + Z, i == 1, mid))
            o.group(f"room{k}_back_wall", "white", wall_z(oz + Z, ox, ox + X, j == 0, mid))
            o.group(f"room{k}_front_wall", "white", wall_z(oz, ox, ox + X, j == 1, mid))
            o.group(f"room{k}_short_block", "white", block_faces(SHORT_BLOCK, 165.0, ox, oz))
            o.group(f"room{k}_tall_block", "white", block_faces(TALL_BLOCK, 330.0, ox, oz))
    for j in range(2):
        doorway("x", X, j * (Z + T) + Z / 2)
    for i in range(2):
        doorway("z", Z, i * (X + T) + X / 2)
    o.group("doorways", "white", jambs)
    o.write(os.path.join(folder, "four_boxes.obj"), [
        "Four closed Cornell rooms (2 x 2, room k = 2 j + i at x = i (556 + 10), z = j (559.2 + 10)),",
        "each lit by its own ceiling light, joined by 160 x 300 doorways through their 10-unit shared",
        "walls: the thesis's multiple-enclosure environment. Written by scenes/tools/make_scenes.py."])
    with open(os.path.join(folder, "four_boxes.mtl"), "w") as fh:
        fh.write(open("scenes/cornell/cornell.mtl").read())
    with open(os.path.join(folder, "four_boxes.camera"), "w") as fh:
        fh.write("# Inside room 0, by its front wall, looking through the doorway into room 2.\n" + FOUR_BOXES_CAMERA + "\n")
    o = subdivided(os.path.join(folder, "four_boxes.obj"), "four_boxes.mtl", 2)
    o.write(os.path.join(folder, "four_boxes_x2.obj"), [
        "four_boxes with every face split 2 x 2 (the thesis's subdivided multiple-enclosure environment).",
        "Written by scenes/tools/make_scenes.py."])
    with open(os.path.join(folder, "four_boxes_x2.camera"), "w") as fh:
        fh.write(FOUR_BOXES_CAMERA + "\n")

# The many-room building (issue 19): rooms of ROOM x ROOM_H x ROOM in an n x n grid, walls WALL
# thick, a doorway through every wall two rooms share, one ceiling light per room, one block per
# room. The camera stands in room 0 and sees mostly that room: the case view-driven shooting is for.
ROOM, ROOM_H, WALL, DOOR_W, DOOR_H, LIGHT = 400.0, 300.0, 10.0, 100.0, 210.0, 80.0
BUILDING_CAMERA = "eye=40,170,30 target=330,60,330 up=0,1,0 fov=60"

def building(folder, n):
    """n x n rooms (room k = n j + i at x = i (ROOM + WALL), z = j (ROOM + WALL)), every pair of
    neighbours joined by a doorway tunnel through their shared wall."""
    P, Y = ROOM + WALL, ROOM_H
    o = Obj("building.mtl")
    jambs = []
    def wall(axis, w, t0, t1, door, towards):
        # The wall in the plane `axis` = w spanning t0..t1 along it, with a centred doorway if door.
        def p(t, y): return [w, y, t] if axis == "x" else [t, y, w]
        def quad(a, b, y0, y1): return orient([p(a, y0), p(b, y0), p(b, y1), p(a, y1)], towards=towards)
        if not door:
            return [quad(t0, t1, 0, Y)]
        d0, d1 = (t0 + t1 - DOOR_W) / 2, (t0 + t1 + DOOR_W) / 2
        return [quad(t0, d0, 0, Y), quad(d1, t1, 0, Y), quad(d0, d1, DOOR_H, Y)]
    def doorway(axis, w, c):
        d0, d1 = c - DOOR_W / 2, c + DOOR_W / 2
        mid = [w + WALL / 2, DOOR_H / 2, c] if axis == "x" else [c, DOOR_H / 2, w + WALL / 2]
        def p(m, t, y): return [m, y, t] if axis == "x" else [t, y, m]
        for f in ([p(w, d0, 0), p(w + WALL, d0, 0), p(w + WALL, d0, DOOR_H), p(w, d0, DOOR_H)],
                  [p(w, d1, 0), p(w + WALL, d1, 0), p(w + WALL, d1, DOOR_H), p(w, d1, DOOR_H)],
                  [p(w, d0, DOOR_H), p(w + WALL, d0, DOOR_H), p(w + WALL, d1, DOOR_H), p(w, d1, DOOR_H)],
                  [p(w, d0, 0), p(w + WALL, d0, 0), p(w + WALL, d1, 0), p(w, d1, 0)]):
            jambs.append(orient(f, towards=mid))
    l0, l1 = (ROOM - LIGHT) / 2, (ROOM + LIGHT) / 2
    for j in range(n):
        for i in range(n):
            k, ox, oz = n * j + i, i * P, j * P
            mid = room_shell(o, k, ox, oz, ROOM, Y, ROOM, l0, l1, l0, l1)
            o.group(f"room{k}_east_wall", "red", wall("x", ox + ROOM, oz, oz + ROOM, i < n - 1, mid))
            o.group(f"room{k}_west_wall", "green", wall("x", ox, oz, oz + ROOM, i > 0, mid))
            o.group(f"room{k}_north_wall", "white", wall("z", oz + ROOM, ox, ox + ROOM, j < n - 1, mid))
            o.group(f"room{k}_south_wall", "white", wall("z", oz, ox, ox + ROOM, j > 0, mid))
            b = [[ox + 230, 0, oz + 250], [ox + 310, 0, oz + 250], [ox + 310, 0, oz + 330], [ox + 230, 0, oz + 330]]
            o.group(f"room{k}_block", "white", block_faces([[x, 120, z] for x, _, z in b[::-1]], 120.0))
            if i < n - 1:
                doorway("x", ox + ROOM, oz + ROOM / 2)
            if j < n - 1:
                doorway("z", oz + ROOM, ox + ROOM / 2)
    o.group("doorways", "white", jambs)
    name = f"building_{n * n}"
    o.write(os.path.join(folder, f"{name}.obj"), [
        f"{n * n} rooms ({n} x {n}, room k = {n} j + i at x = i {P:g}, z = j {P:g}), each {ROOM:g} x {ROOM_H:g} x {ROOM:g}",
        f"with a ceiling light and a block, every two neighbours joined by a {DOOR_W:g} x {DOOR_H:g} doorway through",
        f"their {WALL:g}-unit wall (issue 19). Written by scenes/tools/make_scenes.py."])
    with open(os.path.join(folder, "building.mtl"), "w") as fh:
        fh.write(open("scenes/cornell/cornell.mtl").read())
    with open(os.path.join(folder, f"{name}.camera"), "w") as fh:
        fh.write("# Inside room 0, from its south-west corner across the room.\n" + BUILDING_CAMERA + "\n")
    # Through the doors: room 0 -> room 1 (east) -> room 1 + n (north), looking ahead, 2 s a leg.
    c, d = ROOM / 2, P + ROOM / 2
    with open(os.path.join(folder, f"{name}.path"), "w") as fh:
        fh.write("# Walkthrough through doors: still in room 0, to its east doorway, through it into room 1,\n"
                 "# across to room 1's north doorway and through it into the room beyond (issue 19).\n"
                 "# TIME(s)  camera (keys left out keep the previous keyframe's)\n"
                 f"0   {BUILDING_CAMERA}\n"
                 f"2   eye=40,170,30 target=330,60,330\n"
                 f"4   eye={c:g},160,{c:g} target={ROOM:g},120,{c:g}\n"
                 f"6   eye={ROOM - 20:g},160,{c:g} target={d:g},120,{c:g}\n"
                 f"8   eye={d:g},160,{c:g} target={d:g},120,{ROOM:g}\n"
                 f"10  eye={d:g},160,{ROOM - 20:g} target={d:g},120,{d:g}\n"
                 f"12  eye={d:g},160,{d - 60:g} target={d:g},60,{d + 150:g}\n")

def analytic(folder):
    mtl = ("newmtl emitter\nKd 0 0 0\nKe 1 1 1\n\n"
           "newmtl receiver\nKd 0.5 0.5 0.5\n\n"
           "newmtl grey_emitter\nKd 0.5 0.5 0.5\nKe 1 1 1\n")
    with open(os.path.join(folder, "analytic.mtl"), "w") as fh:
        fh.write("# Materials of the analytic test scenes.\n" + mtl)
    # Howell C-11: unit squares, parallel and opposed, one unit apart: F = 0.19982.
    o = Obj("analytic.mtl")
    o.group("emitter", "emitter", [[[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]]])
    o.group("receiver", "receiver", [[[0, 0, 1], [0, 1, 1], [1, 1, 1], [1, 0, 1]]])
    o.write(os.path.join(folder, "parallel_squares.obj"), ["Howell C-11 with a = b = c = 1: F = 0.19982"])
    # Howell C-14: unit squares sharing an edge at a right angle: F = 0.20004.
    o = Obj("analytic.mtl")
    o.group("emitter", "emitter", [[[0, 0, 0], [0, 0, 1], [1, 0, 1], [1, 0, 0]]])
    o.group("receiver", "receiver", [[[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]]])
    o.write(os.path.join(folder, "perpendicular_squares.obj"), ["Howell C-14 with l = w = h = 1: F = 0.20004"])
    # Furnace: a closed unit cube, every face emitting E = 1 with rho = 0.5: B = E / (1 - rho) = 2.
    o = Obj("analytic.mtl")
    mid = [0.5, 0.5, 0.5]
    faces = [rect(0, 1, 0, 1, 0), rect(0, 1, 0, 1, 1),
             [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]], [[0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1]],
             [[0, 0, 0], [0, 0, 1], [0, 1, 1], [0, 1, 0]], [[1, 0, 0], [1, 0, 1], [1, 1, 1], [1, 1, 0]]]
    o.group("box", "grey_emitter", [orient(f, towards=mid) for f in faces])
    o.write(os.path.join(folder, "furnace.obj"), ["Closed box, all faces E = 1, rho = 0.5: B = 2 everywhere"])

if __name__ == "__main__":
    import sys
    if sys.argv[1:2] == ["building"]:  # one building: make_scenes.py building N [FOLDER]
        building(sys.argv[3] if len(sys.argv) > 3 else "scenes/building", int(sys.argv[2]))
        sys.exit(0)
    os.makedirs("scenes/cornell", exist_ok=True)
    os.makedirs("scenes/analytic", exist_ok=True)
    cornell("scenes/cornell")
    os.makedirs("scenes/cornell_hung", exist_ok=True)
    cornell_hung("scenes/cornell_hung")
    os.makedirs("scenes/cornell_subdivided", exist_ok=True)
    cornell_subdivided("scenes/cornell_subdivided", 2)
    cornell_subdivided("scenes/cornell_subdivided", 4)
    os.makedirs("scenes/four_boxes", exist_ok=True)
    four_boxes("scenes/four_boxes")
    analytic("scenes/analytic")
    os.makedirs("scenes/building", exist_ok=True)
    for n in (2, 4, 8):  # 4, 16 and 64 rooms
        building("scenes/building", n)
