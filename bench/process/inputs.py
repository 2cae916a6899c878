"""The whole-process bench's inputs, made once in the work folder and kept:
the scans of the data folder as .vdb (by `isoform convert`, as a user makes
them) and as NRRD headers over the raw files, a 256^3 noisy scan with
thousands of small parts, the level-set sphere of the contour bench, and
the meshes the reductions start from."""
import collections
import os
import subprocess

import numpy as np

Vdb = collections.namedtuple("Vdb", "label path iso")
Dense = collections.namedtuple("Dense", "label raw nhdr dims type spacing iso")
Mesh = collections.namedtuple("Mesh", "label path kind")

# name, file, dims, spacing, isovalue
SCANS = [
    ("headsq", "headsq_64x64x93_u16le.raw", (64, 64, 93), (3.2, 3.2, 1.5), 1150.5),
    ("frog", "frog_256x256x44_u16le.raw", (256, 256, 44), (1.0, 1.0, 1.0), 20.5),
    ("teapot", "teapot_256x256x100_u16le.raw", (256, 256, 100), (1.0, 1.0, 1.0), 40.5),
]
NOISY = ("noisy", "noisy_256x256x256_u16le.raw", (256, 256, 256), (1.0, 1.0, 1.0), 500.5)


def run(argv):
    subprocess.run(argv, check=True, stdout=subprocess.DEVNULL)


def write_atomically(path, data):
    with open(path + ".tmp", "wb") as f:
        f.write(data)
    os.replace(path + ".tmp", path)


def make_noisy_scan(path, n=256, seed=1991):
    """A CT-like 256^3 scan: a thick shell and rods of bone (1200) in tissue
    (100), with spatially correlated noise whose peaks pass the isovalue in
    thousands of small blobs, as the specks of a real noisy scan."""
    rng = np.random.default_rng(seed)
    axis = (np.arange(n) - (n - 1) / 2) / (n / 2)
    z, y, x = np.meshgrid(axis, axis, axis, indexing="ij")
    r = np.sqrt(x * x + y * y + z * z)
    bone = ((r > 0.62) & (r < 0.72)) | ((np.hypot(x - 0.2, y) < 0.08) & (np.abs(z) < 0.6)) | \
           ((np.hypot(y + 0.25, z) < 0.06) & (np.abs(x) < 0.55))
    del x, y, z, r
    noise = rng.standard_normal((n, n, n))
    k = np.fft.fftfreq(n)
    kz, ky, kx = np.meshgrid(k, k, np.fft.rfftfreq(n), indexing="ij", sparse=True)
    sigma = 1.2  # voxels of correlation
    kernel = np.exp(-2 * np.pi ** 2 * sigma ** 2 * (kx ** 2 + ky ** 2 + kz ** 2))
    noise = np.fft.irfftn(np.fft.rfftn(noise) * kernel, s=(n, n, n))
    noise *= 125.0 / noise.std()
    values = np.where(bone, 1200.0, 100.0) + noise
    write_atomically(path, np.clip(values, 0, 65535).astype("<u2").tobytes(order="C"))


def write_nhdr(path, raw, dims, spacing):
    text = (f"NRRD0004\ntype: ushort\ndimension: 3\nsizes: {dims[0]} {dims[1]} {dims[2]}\n"
            f"spacings: {spacing[0]} {spacing[1]} {spacing[2]}\nencoding: raw\nendian: little\n"
            f"data file: {os.path.abspath(raw)}\n")
    write_atomically(path, text.encode())


def torus_ply(path, nu=1000, nv=500, major=1.0, minor=0.4):
    """A closed torus of 2 nu nv triangles: a smooth surface of about 1M."""
    u = np.arange(nu) * 2 * np.pi / nu
    v = np.arange(nv) * 2 * np.pi / nv
    uu, vv = np.meshgrid(u, v, indexing="ij")
    ring = major + minor * np.cos(vv)
    points = np.stack([ring * np.cos(uu), ring * np.sin(uu), minor * np.sin(vv)], axis=-1).reshape(-1, 3)
    i, j = np.meshgrid(np.arange(nu), np.arange(nv), indexing="ij")
    a, b = i * nv + j, ((i + 1) % nu) * nv + j
    c, d = ((i + 1) % nu) * nv + (j + 1) % nv, i * nv + (j + 1) % nv
    tris = np.concatenate([np.stack([a, b, c], -1).reshape(-1, 3), np.stack([a, c, d], -1).reshape(-1, 3)])
    write_ply(path, points, tris)


def graph_ply(path, n=708):
    """The graph of a smooth function on an n x n grid of the unit square:
    2 (n-1)^2 triangles, about 1M, with a boundary."""
    axis = np.linspace(0.0, 1.0, n)
    x, y = np.meshgrid(axis, axis, indexing="ij")
    z = 0.25 * np.sin(np.pi * x) * np.cos(np.pi * y) + 0.1 * np.exp(-8 * ((x - 0.6) ** 2 + (y - 0.3) ** 2))
    points = np.stack([x, y, z], -1).reshape(-1, 3)
    i, j = np.meshgrid(np.arange(n - 1), np.arange(n - 1), indexing="ij")
    a, b, c, d = i * n + j, (i + 1) * n + j, (i + 1) * n + j + 1, i * n + j + 1
    tris = np.concatenate([np.stack([a, b, c], -1).reshape(-1, 3), np.stack([a, c, d], -1).reshape(-1, 3)])
    write_ply(path, points, tris)


def write_ply(path, points, tris):
    header = (f"ply\nformat binary_little_endian 1.0\nelement vertex {len(points)}\nproperty float x\n"
              f"property float y\nproperty float z\nelement face {len(tris)}\n"
              f"property list uchar int vertex_indices\nend_header\n").encode()
    faces = np.zeros(len(tris), dtype=[("n", "u1"), ("i", "<i4", 3)])
    faces["n"] = 3
    faces["i"] = tris
    write_atomically(path, header + points.astype("<f4").tobytes() + faces.tobytes())


class Prepared:
    def __init__(self, vdbs, sphere, dense, meshes):
        self._vdbs, self._sphere, self._dense, self._meshes = vdbs, sphere, dense, meshes

    def vdb_cases(self, no_sphere):
        return self._vdbs[:2] + ([] if no_sphere or not self._sphere else [self._sphere]) + self._vdbs[2:]

    def dense_cases(self):
        return self._dense

    def reduce_cases(self):
        return self._meshes


def make_sphere(build, data, work):
    """The contour bench's level-set sphere (about 50M active voxels), made by its prepare step."""
    folder = os.path.join(work, "sphere")
    os.makedirs(folder, exist_ok=True)
    result = os.path.join(folder, "prepare.json")
    program = os.path.join(build, "bench", "isoform_bench")
    existing = [f for f in os.listdir(folder) if f.endswith(".vdb") and "sphere" in f]
    if not existing:
        run([program, "prepare", "--data", data, "--work", folder, "--result", result, "--no-resample"])
        existing = [f for f in os.listdir(folder) if f.endswith(".vdb") and "sphere" in f]
    return Vdb("level-set sphere, 50M voxels", os.path.join(folder, existing[0]), 0.0)


def prepare(build, data, work, no_sphere):
    isoform = os.path.join(build, "cli", "isoform")
    vdbs = [Vdb("cube.vdb", os.path.join(data, "cube.vdb"), 0.0),
            Vdb("smoke.vdb at 0.5", os.path.join(data, "smoke.vdb"), 0.5)]
    dense, meshes = [], []
    noisy_raw = os.path.join(work, NOISY[1])
    if not os.path.exists(noisy_raw):
        make_noisy_scan(noisy_raw)
    for name, file, dims, spacing, iso in SCANS + [NOISY]:
        raw = noisy_raw if name == "noisy" else os.path.join(data, file)
        vdb = os.path.join(work, name + ".vdb")
        if not os.path.exists(vdb):
            run([isoform, "convert", raw, "--dims", ",".join(map(str, dims)), "--type", "u16",
                 "--spacing", ",".join(map(str, spacing)), "-o", vdb])
        nhdr = os.path.join(work, name + ".nhdr")
        write_nhdr(nhdr, raw, dims, spacing)
        label = f"{name} at {iso}" + (" (256³, made by the bench)" if name == "noisy" else "")
        vdbs.append(Vdb(label, vdb, iso))
        dense.append(Dense(label, raw, nhdr, dims, "u16", spacing, iso))
        if name != "headsq":
            contour = os.path.join(work, name + "-contour.ply")
            if not os.path.exists(contour):
                run([isoform, "contour", vdb, "--iso", str(iso), "-o", contour, "-q"])
            meshes.append(Mesh(f"{name} contour", contour, "scan"))
    for label, maker, file in (("torus, 1M triangles", torus_ply, "torus.ply"),
                               ("graph, 1M triangles", graph_ply, "graph.ply")):
        path = os.path.join(work, file)
        if not os.path.exists(path):
            maker(path)
        meshes.insert(0 if file == "torus.ply" else 1, Mesh(label, path, "smooth"))
    sphere = None if no_sphere else make_sphere(build, data, work)
    return Prepared(vdbs, sphere, dense, meshes)
