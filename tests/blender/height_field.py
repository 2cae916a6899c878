"""A height field for the reduction's graph mode: the paraboloid
z = 0.4 (x^2 + y^2) on an n x n grid over [-1, 1]^2, every triangle
counterclockwise seen from +z, and the signed (x, y) areas of a mesh's
triangles. Plain numpy, for the native and the in-Blender tests."""
import numpy as np


def paraboloid_grid(n=41):
    """Points (n^2 x 3, float64) and triangles (2 (n - 1)^2 x 3, int32)."""
    x = np.linspace(-1.0, 1.0, n)
    yy, xx = np.meshgrid(x, x, indexing="ij")
    points = np.stack([xx, yy, 0.4 * (xx * xx + yy * yy)], -1).reshape(-1, 3)
    j, i = np.meshgrid(np.arange(n - 1), np.arange(n - 1), indexing="ij")
    a = (j * n + i).ravel()
    triangles = np.stack([a, a + 1, a + n + 1, a, a + n + 1, a + n], -1).reshape(-1, 3)
    return points, triangles.astype(np.int32)


def projected_areas(points, triangles):
    """The signed area of each triangle's (x, y) projection (positive: counterclockwise)."""
    p = np.asarray(points, dtype=np.float64)[np.asarray(triangles)]
    e1, e2 = p[:, 1, :2] - p[:, 0, :2], p[:, 2, :2] - p[:, 0, :2]
    return 0.5 * (e1[:, 0] * e2[:, 1] - e1[:, 1] * e2[:, 0])
