#!/usr/bin/env python3
"""Writes the fuzz targets' seed corpora, made from small generated meshes (no copied files).

usage: make_seeds.py DIR   ->  DIR/mesh/* (first byte: 0 PLY, 1 OBJ, 2 OFF) and DIR/field/*
(first byte: 0 .ffield, 1 .rosy, for the icosahedron the field target reads against).
"""
import math
import os
import struct
import sys


def icosahedron():
    t = (1 + math.sqrt(5)) / 2
    p = [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t),
         (0, -1, -t), (0, 1, -t), (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]
    n = [math.sqrt(x * x + y * y + z * z) for x, y, z in p]
    p = [(x / l, y / l, z / l) for (x, y, z), l in zip(p, n)]
    f = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4),
         (11, 10, 2), (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8),
         (3, 8, 9), (4, 9, 5), (2, 4, 11), (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    return p, f


def grid(n):
    """An n x n grid of quads on a bumpy height field (polygons for the readers to triangulate)."""
    p = [(i, j, 0.1 * math.sin(i) * math.cos(j)) for j in range(n + 1) for i in range(n + 1)]
    f = [(j * (n + 1) + i, j * (n + 1) + i + 1, (j + 1) * (n + 1) + i + 1, (j + 1) * (n + 1) + i)
         for j in range(n) for i in range(n)]
    return p, f


def ply(p, f, fmt, extras=False):
    head = ["ply", "format %s 1.0" % fmt, "comment seed", "element vertex %d" % len(p),
            "property float x", "property float y", "property double z"]
    if extras:
        head += ["property uchar red", "property list uchar short junk"]
    head += ["element face %d" % len(f), "property list uchar int vertex_indices"]
    if extras:
        head += ["property int patch"]
    head += ["end_header"]
    out = ("\n".join(head) + "\n").encode()
    if fmt == "ascii":
        rows = []
        for x, y, z in p:
            rows.append("%g %g %g" % (x, y, z) + (" 7 2 1 -1" if extras else ""))
        for i, c in enumerate(f):
            rows.append(" ".join(map(str, (len(c),) + tuple(c))) + (" %d" % i if extras else ""))
        return out + ("\n".join(rows) + "\n").encode()
    e = "<" if fmt == "binary_little_endian" else ">"
    for x, y, z in p:
        out += struct.pack(e + "ffd", x, y, z)
        if extras:
            out += struct.pack(e + "BBhh", 7, 2, 1, -1)
    for i, c in enumerate(f):
        out += struct.pack(e + "B" + "i" * len(c), len(c), *c)
        if extras:
            out += struct.pack(e + "i", i)
    return out


def obj(p, f):
    return ("".join("v %g %g %g\n" % v for v in p) +
            "".join("f " + " ".join(str(i + 1) for i in c) + "\n" for c in f)).encode()


def off(p, f):
    return ("OFF\n%d %d 0\n" % (len(p), len(f)) + "".join("%g %g %g\n" % v for v in p) +
            "".join("%d %s\n" % (len(c), " ".join(map(str, c))) for c in f)).encode()


def fields():
    p, f = icosahedron()
    tangents = []
    for a, b, _ in f:
        d = [p[b][k] - p[a][k] for k in range(3)]
        tangents.append(d)
    ffield = "# frame\ntarget frame\n%d\nk1 k2 k1v_x k1v_y k1v_z k2v_x k2v_y k2v_z\n" % len(f)
    ffield += "".join("1 1 %g %g %g 0 0 0\n" % tuple(t) for t in tangents)
    rosy = "%d\n4\n" % len(f) + "".join("%g %g %g\n" % tuple(t) for t in tangents)
    return {"ffield": b"\0" + ffield.encode(), "rosy": b"\1" + rosy.encode()}


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    root = sys.argv[1]
    os.makedirs(os.path.join(root, "mesh"), exist_ok=True)
    os.makedirs(os.path.join(root, "field"), exist_ok=True)
    seeds = {}
    for name, (p, f) in {"ico": icosahedron(), "grid": grid(3)}.items():
        for fmt in ("ascii", "binary_little_endian", "binary_big_endian"):
            seeds["%s_%s.ply" % (name, fmt)] = b"\0" + ply(p, f, fmt)
            seeds["%s_%s_extras.ply" % (name, fmt)] = b"\0" + ply(p, f, fmt, extras=True)
        seeds[name + ".obj"] = b"\1" + obj(p, f)
        seeds[name + ".off"] = b"\2" + off(p, f)
    for name, data in seeds.items():
        with open(os.path.join(root, "mesh", name), "wb") as out:
            out.write(data)
    for name, data in fields().items():
        with open(os.path.join(root, "field", "ico." + name), "wb") as out:
            out.write(data)


if __name__ == "__main__":
    main()
