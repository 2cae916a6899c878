"""Writes the analytic volumes and the coarse scans of the comparison study
(docs/compare.md) as raw float32 arrays, x fastest, for `isoform convert`.

usage: /usr/bin/python3 docs/make_compare_volume.py KIND N OUT.raw [SCAN.raw]

KIND sphere   signed distance to the unit sphere, over [-1.3, 1.3]^3
     torus    signed distance to the torus around z with radii 1 and 0.4,
              over [-1.6, 1.6]^2 x [-0.6, 0.6] (same spacing on all axes)
     box      signed distance to the cube [-1, 1]^3 (sharp edges), over [-1.4, 1.4]^3
     headsq   the 64x64x93 u16 CT scan SCAN.raw averaged over N x N x N blocks
Prints "NX,NY,NZ SX,SY,SZ OX,OY,OZ" (dims, spacing, origin) for convert.
"""
import sys

import numpy as np


def grid(n, half):
    xs = np.linspace(-half[0], half[0], n[0])
    ys = np.linspace(-half[1], half[1], n[1])
    zs = np.linspace(-half[2], half[2], n[2])
    z, y, x = np.meshgrid(zs, ys, xs, indexing="ij")
    spacing = tuple(2 * h / (k - 1) for h, k in zip(half, n))
    return x, y, z, spacing, tuple(-h for h in half)


def main(argv):
    kind, n, out = argv[1], int(argv[2]), argv[3]
    if kind == "sphere":
        x, y, z, s, o = grid((n, n, n), (1.3, 1.3, 1.3))
        f = np.sqrt(x * x + y * y + z * z) - 1.0
    elif kind == "torus":
        nz = max(4, int(round((n - 1) * 0.6 / 1.6)) + 1)
        x, y, z, s, o = grid((n, n, nz), (1.6, 1.6, 0.6 * (nz - 1) / ((n - 1) * 0.6 / 1.6)))
        f = np.sqrt((np.sqrt(x * x + y * y) - 1.0) ** 2 + z * z) - 0.4
    elif kind == "box":
        x, y, z, s, o = grid((n, n, n), (1.4, 1.4, 1.4))
        q = np.stack([np.abs(x) - 1, np.abs(y) - 1, np.abs(z) - 1])
        outside = np.sqrt(np.sum(np.maximum(q, 0) ** 2, axis=0))
        f = outside + np.minimum(np.max(q, axis=0), 0)
    elif kind == "headsq":
        scan = np.fromfile(argv[4], dtype="<u2").reshape(93, 64, 64).astype(np.float64)
        b = n
        nz, ny, nx = (93 // b, 64 // b, 64 // b)
        f = scan[:nz * b, :ny * b, :nx * b].reshape(nz, b, ny, b, nx, b).mean(axis=(1, 3, 5))
        s = (3.2 * b, 3.2 * b, 1.5 * b)
        o = (3.2 * (b - 1) / 2, 3.2 * (b - 1) / 2, 1.5 * (b - 1) / 2)
    else:
        sys.exit(f"unknown kind {kind}")
    # A sample exactly 0 would be inactive after convert (background 0).
    f = np.where(f == 0, 1e-7, f)
    f.astype("<f4").tofile(out)
    dims = f.shape[::-1]
    print(f"{dims[0]},{dims[1]},{dims[2]} {s[0]!r},{s[1]!r},{s[2]!r} {o[0]!r},{o[1]!r},{o[2]!r}")


if __name__ == "__main__":
    main(sys.argv)
