#!/usr/bin/python3
"""The element layout of a hemirad PLY (solve --ply) on one plane, as PNG: docs/adaptive.md's figures.

  ply_layout.py SOLUTION.ply OUT.png AXIS VALUE [WIDTH]

Draws every face whose vertices all lie on the plane AXIS = VALUE (AXIS x, y or z; within 1e-3 of
the scene's size), seen along AXIS, filled with its vertices' tone-mapped colour, its edges dark,
so the elements' sizes show. Pure Python (no numpy), deterministic output.
"""
import struct
import sys
import zlib


def read_ply(path):
    data = open(path, "rb").read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    header = data[:end].decode().splitlines()
    nv = int(next(l for l in header if l.startswith("element vertex")).split()[2])
    nf = int(next(l for l in header if l.startswith("element face")).split()[2])
    at, vertices, faces = end, [], []
    for _ in range(nv):  # x y z (float), r g b (uchar), radiosity rgb (float)
        x, y, z, r, g, b = struct.unpack_from("<fffBBB", data, at)
        vertices.append(((x, y, z), (r, g, b)))
        at += 27
    for _ in range(nf):
        n = data[at]
        faces.append(struct.unpack_from("<%dI" % n, data, at + 1))
        at += 1 + 4 * n
    return vertices, faces


def write_png(path, width, height, pixels):
    rows = b"".join(b"\x00" + bytes(pixels[y * width * 3:(y + 1) * width * 3]) for y in range(height))
    chunk = lambda kind, data: struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))
    png = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0))
    open(path, "wb").write(png + chunk(b"IDAT", zlib.compress(rows, 9)) + chunk(b"IEND", b""))


def fill(pixels, width, height, points, rgb):
    """A convex polygon (pixel coordinates): pixels whose centre is inside get rgb, within 0.5 px of an edge dark."""
    xs, ys = [p[0] for p in points], [p[1] for p in points]
    n = len(points)
    area = sum(points[i][0] * points[(i + 1) % n][1] - points[(i + 1) % n][0] * points[i][1] for i in range(n))
    sign = 1 if area > 0 else -1
    edges = []
    for i in range(n):
        (ax, ay), (bx, by) = points[i], points[(i + 1) % n]
        length = ((bx - ax) ** 2 + (by - ay) ** 2) ** 0.5 or 1.0
        edges.append((ax, ay, (bx - ax) / length, (by - ay) / length))
    for y in range(max(0, int(min(ys))), min(height, int(max(ys)) + 1)):
        for x in range(max(0, int(min(xs))), min(width, int(max(xs)) + 1)):
            d = min(sign * ((x + 0.5 - ax) * dy - (y + 0.5 - ay) * dx) * -1 for ax, ay, dx, dy in edges)
            if d < 0:
                continue
            at = (y * width + x) * 3
            pixels[at:at + 3] = [40, 40, 40] if d < 0.5 else rgb


def main():
    ply, out, axis, value = sys.argv[1], sys.argv[2], "xyz".index(sys.argv[3]), float(sys.argv[4])
    width = int(sys.argv[5]) if len(sys.argv) > 5 else 600
    vertices, faces = read_ply(ply)
    span = max(max(p[i] for p, _ in vertices) - min(p[i] for p, _ in vertices) for i in range(3))
    u, v = [i for i in range(3) if i != axis]
    on = [f for f in faces if all(abs(vertices[k][0][axis] - value) <= 1e-3 * span for k in f)]
    us = [vertices[k][0][u] for f in on for k in f]
    vs = [vertices[k][0][v] for f in on for k in f]
    lo_u, lo_v, size = min(us), min(vs), max(max(us) - min(us), max(vs) - min(vs))
    scale = (width - 1) / size
    height = int((max(vs) - lo_v) * scale) + 1
    pixels = [255] * (width * height * 3)
    for f in on:
        points = [((vertices[k][0][u] - lo_u) * scale, height - 1 - (vertices[k][0][v] - lo_v) * scale) for k in f]
        rgb = [sum(vertices[k][1][c] for k in f) // len(f) for c in range(3)]
        fill(pixels, width, height, points, rgb)
    write_png(out, width, height, pixels)


if __name__ == "__main__":
    main()
