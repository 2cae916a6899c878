"""A torus-shaped thin shell for the reduction's overlap guard: the outer
tube (radius 1) facing out, the inner one (radius 1 - gap) facing in, on
offset grids so the two sheets differ. Its sheets lie closer than a
reduction's triangles grow, so an unguarded reduction pushes them through
each other. Plain numpy, for the native and the in-Blender tests."""
import numpy as np


def tube(nu, nv, r, inward, base):
    """((2 + r cos u) cos v, (2 + r cos u) sin v, r sin u) on an nu x nv grid."""
    u = 2 * np.pi * np.arange(nu) / nu
    v = 2 * np.pi * np.arange(nv) / nv
    vv, uu = np.meshgrid(v, u, indexing="ij")
    points = np.stack([(2 + r * np.cos(uu)) * np.cos(vv), (2 + r * np.cos(uu)) * np.sin(vv),
                       r * np.sin(uu)], -1).reshape(-1, 3)
    j, i = np.meshgrid(np.arange(nv), np.arange(nu), indexing="ij")
    a, b = base + j * nu + i, base + j * nu + (i + 1) % nu
    c, d = base + ((j + 1) % nv) * nu + (i + 1) % nu, base + ((j + 1) % nv) * nu + i
    corners = [a, b, c, a, c, d] if inward else [a, c, b, a, d, c]
    return points, np.stack(corners, -1).reshape(-1, 3)


def thin_shell(nu=32, nv=60, gap=0.02):
    """(points float64 (n, 3), triangles int32 (m, 3)): 6864 triangles by default."""
    outer, outer_triangles = tube(nu, nv, 1.0, False, 0)
    inner, inner_triangles = tube(nu - 4, nv - 6, 1.0 - gap, True, len(outer))
    return (np.concatenate([outer, inner]),
            np.concatenate([outer_triangles, inner_triangles]).astype(np.int32))
