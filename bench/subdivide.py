#!/usr/bin/env python3
"""Loop subdivision of a triangle mesh (OBJ in, OBJ out), for the scale series of the benchmark.

Usage: python3 bench/subdivide.py IN.obj LEVELS OUT.obj

Each level splits every triangle into four (faces × 4) and moves the vertices with Loop's
weights (Warren's β for interior vertices; the 1/8-3/4-1/8 rule and edge midpoints on the
border), so the result stays a smooth, valid, oriented manifold mesh: kitten.obj (3700 faces)
gives 14.8K, 59.2K, 236.8K and 947.2K faces at levels 1 to 4. Only `v` and `f` lines are read
(`f a/b/c` and negative indices are accepted); polygons are fanned into triangles. Pure Python,
no dependencies: level 4 of the kitten takes a few seconds.
"""
import math
import sys


def read_obj(path):
    verts, faces = [], []
    with open(path) as fh:
        for line in fh:
            if line.startswith("v "):
                x, y, z = line.split()[1:4]
                verts.append((float(x), float(y), float(z)))
            elif line.startswith("f "):
                idx = []
                for tok in line.split()[1:]:
                    i = int(tok.split("/")[0])
                    idx.append(i - 1 if i > 0 else len(verts) + i)
                for k in range(1, len(idx) - 1):
                    faces.append((idx[0], idx[k], idx[k + 1]))
    return verts, faces


def loop_once(verts, faces):
    nv = len(verts)
    edge_vertex = {}     # undirected (a, b), a < b -> new vertex index
    edge_opposite = {}   # undirected (a, b) -> list of opposite corners
    for a, b, c in faces:
        for u, v, w in ((a, b, c), (b, c, a), (c, a, b)):
            key = (u, v) if u < v else (v, u)
            edge_opposite.setdefault(key, []).append(w)
    neighbours = [set() for _ in range(nv)]
    border_neighbours = [[] for _ in range(nv)]
    new_verts = [None] * nv
    for (u, v), opp in edge_opposite.items():
        neighbours[u].add(v)
        neighbours[v].add(u)
        pu, pv = verts[u], verts[v]
        if len(opp) == 2:
            po, pq = verts[opp[0]], verts[opp[1]]
            p = tuple(0.375 * (pu[k] + pv[k]) + 0.125 * (po[k] + pq[k]) for k in range(3))
        else:  # border edge (or a non-manifold one, treated the same)
            border_neighbours[u].append(v)
            border_neighbours[v].append(u)
            p = tuple(0.5 * (pu[k] + pv[k]) for k in range(3))
        edge_vertex[(u, v)] = len(verts) + len(edge_vertex)
        new_verts.append(p)
    for i in range(nv):
        p = verts[i]
        if border_neighbours[i]:
            if len(border_neighbours[i]) == 2:
                a, b = verts[border_neighbours[i][0]], verts[border_neighbours[i][1]]
                new_verts[i] = tuple(0.75 * p[k] + 0.125 * (a[k] + b[k]) for k in range(3))
            else:
                new_verts[i] = p
            continue
        n = len(neighbours[i])
        if n == 0:
            new_verts[i] = p
            continue
        beta = (0.625 - (0.375 + 0.25 * math.cos(2 * math.pi / n)) ** 2) / n
        s = [0.0, 0.0, 0.0]
        for j in neighbours[i]:
            q = verts[j]
            s[0] += q[0]
            s[1] += q[1]
            s[2] += q[2]
        new_verts[i] = tuple((1 - n * beta) * p[k] + beta * s[k] for k in range(3))
    new_faces = []
    for a, b, c in faces:
        ab = edge_vertex[(a, b) if a < b else (b, a)]
        bc = edge_vertex[(b, c) if b < c else (c, b)]
        ca = edge_vertex[(c, a) if c < a else (a, c)]
        new_faces += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
    return new_verts, new_faces


def main():
    if len(sys.argv) != 4:
        sys.exit("usage: subdivide.py IN.obj LEVELS OUT.obj")
    verts, faces = read_obj(sys.argv[1])
    for _ in range(int(sys.argv[2])):
        verts, faces = loop_once(verts, faces)
    with open(sys.argv[3], "w") as out:
        out.write("# %s, %s Loop subdivision levels (%d faces, %d vertices)\n"
                  % (sys.argv[1].rsplit("/", 1)[-1], sys.argv[2], len(faces), len(verts)))
        out.write("".join("v %.9g %.9g %.9g\n" % p for p in verts))
        out.write("".join("f %d %d %d\n" % (a + 1, b + 1, c + 1) for a, b, c in faces))


if __name__ == "__main__":
    main()
