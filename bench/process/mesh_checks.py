"""What the whole-process bench checks in each output mesh: triangle count,
boundary and non-manifold edges, parts, and folded edges (the two faces'
normals more than 2.5 rad apart: the surface turned over on itself; also
counted above 90 degrees)."""
import numpy as np

SIZES = {"char": "i1", "uchar": "u1", "int8": "i1", "uint8": "u1", "short": "<i2", "ushort": "<u2",
         "int16": "<i2", "uint16": "<u2", "int": "<i4", "uint": "<u4", "int32": "<i4", "uint32": "<u4",
         "float": "<f4", "float32": "<f4", "double": "<f8", "float64": "<f8"}
FOLD = 2.5


def read_header(f):
    elements, current = [], None
    while True:
        line = f.readline().decode("ascii", errors="replace").strip()
        words = line.split()
        if not words:
            continue
        if words[0] == "format" and words[1] != "binary_little_endian":
            raise ValueError(f"{f.name}: not binary little-endian PLY")
        if words[0] == "element":
            current = (words[1], int(words[2]), [])
            elements.append(current)
        elif words[0] == "property":
            current[2].append(words[1:])
        elif words[0] == "end_header":
            return elements


def triangle_count(path):
    with open(path, "rb") as f:
        return dict((name, count) for name, count, _ in read_header(f)).get("face", 0)


def load_ply(path):
    """(points as float64 n x 3, triangles as int64 m x 3)."""
    with open(path, "rb") as f:
        elements = read_header(f)
        points = tris = None
        for name, count, props in elements:
            fields = []
            for p in props:
                if p[0] == "list":
                    if p[1] not in ("uchar", "uint8"):
                        raise ValueError(f"{path}: face list count of type {p[1]}")
                    fields += [("n_" + p[3], "u1"), (p[3], SIZES[p[2]], 3)]
                else:
                    fields.append((p[1], SIZES[p[0]]))
            table = np.frombuffer(f.read(np.dtype(fields).itemsize * count), dtype=fields, count=count)
            if name == "vertex":
                points = np.stack([table["x"], table["y"], table["z"]], -1).astype(np.float64)
            elif name == "face":
                lists = [p for p in props if p[0] == "list"]
                if np.any(table["n_" + lists[0][3]] != 3):
                    raise ValueError(f"{path}: a face that is not a triangle")
                tris = table[lists[0][3]].astype(np.int64)
    return points, tris


def parts(n_vertices, tris):
    parent = np.arange(n_vertices)

    def find(a):
        while parent[a] != a:
            parent[a] = parent[parent[a]]
            a = parent[a]
        return a

    for a, b in np.unique(np.sort(np.concatenate([tris[:, [0, 1]], tris[:, [1, 2]]]), axis=1), axis=0):
        ra, rb = find(a), find(b)
        if ra != rb:
            parent[ra] = rb
    used = np.unique(tris)
    return len({find(v) for v in used})


def check(mesh):
    points, tris = mesh
    e = np.concatenate([tris[:, [0, 1]], tris[:, [1, 2]], tris[:, [2, 0]]])
    face = np.tile(np.arange(len(tris)), 3)
    key = np.sort(e, axis=1)
    key = key[:, 0] * (len(points) + 1) + key[:, 1]
    order = np.argsort(key, kind="stable")
    key, face = key[order], face[order]
    _, start, counts = np.unique(key, return_index=True, return_counts=True)
    n = np.cross(points[tris[:, 1]] - points[tris[:, 0]], points[tris[:, 2]] - points[tris[:, 0]])
    n /= np.maximum(np.linalg.norm(n, axis=1, keepdims=True), 1e-300)
    pair = start[counts == 2]
    cos = np.einsum("ij,ij->i", n[face[pair]], n[face[pair + 1]]).clip(-1, 1)
    angle = np.arccos(cos)
    return {"triangles": int(len(tris)), "vertices": int(len(np.unique(tris))),
            "boundary_edges": int(np.sum(counts == 1)), "nonmanifold_edges": int(np.sum(counts > 2)),
            "folds": int(np.sum(angle > FOLD)), "folds_90": int(np.sum(angle > np.pi / 2)),
            "parts": parts(len(points), tris)}
