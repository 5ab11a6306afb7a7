#!/usr/bin/env python3
"""Gaussian noise on the vertices of an OBJ mesh, for the benchmark's noise rows (issue 20).

Usage: python3 bench/noise.py IN.obj SIGMA_REL SEED OUT.obj

Every `v x y z` line gets independent Gaussian noise of standard deviation SIGMA_REL times the
diagonal of the mesh's bounding box on each coordinate (Python's own generator, seeded with
SEED, so a seed always gives the same mesh on any machine); every other line (faces, normals,
comments) is copied as it is. The faces and their order do not change. Pure Python, no
dependencies, as bench/subdivide.py.
"""
import math
import random
import sys


def main():
    if len(sys.argv) != 5:
        sys.exit("usage: noise.py IN.obj SIGMA_REL SEED OUT.obj")
    src, sigma_rel, seed, dst = sys.argv[1], float(sys.argv[2]), int(sys.argv[3]), sys.argv[4]
    with open(src) as fh:
        lines = fh.readlines()
    rows = [i for i, line in enumerate(lines) if line.startswith("v ")]
    if not rows:
        sys.exit(f"noise.py: {src} has no vertices")
    points = [[float(t) for t in lines[i].split()[1:4]] for i in rows]
    diagonal = math.dist([min(p[c] for p in points) for c in range(3)],
                         [max(p[c] for p in points) for c in range(3)])
    rng = random.Random(seed)
    sigma = sigma_rel * diagonal
    for i, p in zip(rows, points):
        q = [x + rng.gauss(0.0, sigma) for x in p]
        lines[i] = "v %.9g %.9g %.9g\n" % (q[0], q[1], q[2])
    with open(dst, "w") as fh:
        fh.writelines(lines)


if __name__ == "__main__":
    main()
