#!/usr/bin/python3
"""The add-on's bpy-free native module (ctypes over libisoform), no Blender.

usage: test_native.py GROUP --cli ISOFORM --layout STRUCT_LAYOUT
                      --vector-vdb-maker MAKE_VECTOR_VDB --wrong-version LIB --data DIR

The library is found through $ISOFORM_LIBRARY, as in a development build.
Each group is one CTest test; a group runs all its cases and reports each.
Counts are compared with the isoform command run on the same input, so the
binding is checked against an independent caller of the same library.
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile
import threading
import traceback

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..",
                                "blender_addon"))
from isoform_blender import native, native_structs  # noqa: E402

ARGS = None


class CaseFailure(Exception):
    pass


def expect(condition, message):
    if not condition:
        raise CaseFailure(message)


def expect_raises(kind, function, *fragments):
    """Calls function; it must raise kind with every fragment in its message."""
    try:
        function()
    except kind as error:
        for fragment in fragments:
            expect(fragment in str(error), f"message {str(error)!r} lacks {fragment!r}")
        return error
    raise CaseFailure(f"expected {kind.__name__}, nothing was raised")


def data(name):
    path = os.path.join(ARGS.data, name)
    expect(os.path.isfile(path), f"missing shared test data {path}")
    return path


def cli(*args, code=0):
    proc = subprocess.run([ARGS.cli, *args], capture_output=True, text=True, timeout=600)
    expect(proc.returncode == code, f"isoform {' '.join(args)}: exit {proc.returncode}, "
                                    f"expected {code}: {proc.stderr[-2000:]}")
    return proc


def cli_contour_json(path, *options):
    with tempfile.TemporaryDirectory() as tmp:
        proc = cli("contour", path, *options, "-o", os.path.join(tmp, "out.ply"), "--json")
        return json.loads(proc.stdout)


def vector_vdb(tmp):
    path = os.path.join(tmp, "velocity.vdb")
    subprocess.run([ARGS.vector_vdb_maker, path], check=True, timeout=60)
    return path


# ---------------------------------------------------------------- layout

def case_layout_matches_c():
    """Every ctypes mirror has the C struct's size, field names, offsets, sizes."""
    reported = json.loads(subprocess.run([ARGS.layout], capture_output=True, text=True,
                                         check=True).stdout)
    expect(reported["version"] == native.ISOFORM_VERSION,
           f"isoform.h has ISOFORM_VERSION {reported['version']}, native.py "
           f"{native.ISOFORM_VERSION}")
    expect(set(reported["structs"]) == set(native_structs.STRUCTS),
           f"structs in C {sorted(reported['structs'])}, mirrored "
           f"{sorted(native_structs.STRUCTS)}")
    for name, c_side in reported["structs"].items():
        mirror = native_structs.STRUCTS[name]
        expect(c_side["size"] == native_structs.ctypes.sizeof(mirror),
               f"{name}: C size {c_side['size']}, ctypes {native_structs.ctypes.sizeof(mirror)}")
        py_fields = [(f, getattr(mirror, f).offset, getattr(mirror, f).size)
                     for f, _ in mirror._fields_]
        c_fields = [tuple(f) for f in c_side["fields"]]
        expect(py_fields == c_fields, f"{name}: C fields {c_fields}\nctypes {py_fields}")


def case_library_reports_header_version():
    expect(native.library().version == native.ISOFORM_VERSION,
           f"library version {native.library().version}")


# ---------------------------------------------------------------- contour

def case_smoke_counts_match_cli():
    """smoke.vdb at 0.5: same counts as the isoform command, and a closed mesh."""
    expected = cli_contour_json(data("smoke.vdb"), "--iso", "0.5")
    arrays = native.contour_file(data("smoke.vdb"), isovalue=0.5)
    n, m = len(arrays.points), len(arrays.triangles)
    expect(n == expected["vertices"] and m == expected["triangles"],
           f"native {n} vertices {m} triangles, CLI {expected['vertices']} {expected['triangles']}")
    expect(arrays.stats.vertices == n and arrays.stats.triangles == m, "stats disagree with arrays")
    expect(arrays.stats.parts == expected["parts"], f"parts {arrays.stats.parts} vs {expected}")
    expect(arrays.stats.boundary_edges == 0 and arrays.stats.nonmanifold_edges == 0,
           "smoke contour is not closed and manifold")
    expect(abs(arrays.stats.isovalue - 0.5) < 1e-12 and not arrays.stats.isovalue_was_auto,
           f"isovalue {arrays.stats.isovalue}")
    check_arrays(arrays)


def check_arrays(arrays):
    n, m = len(arrays.points), len(arrays.triangles)
    for name, array, dtype, shape in (("points", arrays.points, np.float32, (n, 3)),
                                      ("normals", arrays.normals, np.float32, (n, 3)),
                                      ("triangles", arrays.triangles, np.int32, (m, 3)),
                                      ("parts", arrays.parts, np.int32, (m,))):
        expect(array.dtype == dtype and array.shape == shape and array.flags.c_contiguous,
               f"{name}: {array.dtype} {array.shape}")
    expect(m == 0 or (arrays.triangles.min() >= 0 and arrays.triangles.max() < n),
           "triangle index out of range")
    lengths = np.linalg.norm(arrays.normals, axis=1)
    expect(np.all(np.abs(lengths - 1) < 1e-4), f"normal lengths {lengths.min()}..{lengths.max()}")
    expect(m == 0 or (arrays.parts.min() == 0 and arrays.parts.max() == arrays.stats.parts - 1),
           "part ids not 0..parts-1")
    low, high = np.array(arrays.stats.bbox_min), np.array(arrays.stats.bbox_max)
    expect(np.allclose(arrays.points.min(axis=0), low) and
           np.allclose(arrays.points.max(axis=0), high), "points outside the stats bbox")


def case_tetra_counts_match_cli():
    expected = cli_contour_json(data("sphere.vdb"), "--method", "tetra")
    arrays = native.contour_file(data("sphere.vdb"), method="tetra")
    expect((len(arrays.points), len(arrays.triangles)) ==
           (expected["vertices"], expected["triangles"]),
           f"native {len(arrays.points)} {len(arrays.triangles)}, CLI {expected}")
    expect(arrays.stats.isovalue_was_auto and arrays.stats.isovalue == 0.0, "auto level set iso")


def case_dense_octahedron():
    """A 3^3 array, 1 at the centre and 0 elsewhere, at 0.5: an octahedron
    with its six corners half-way to the face centres (hand-checkable)."""
    values = np.zeros((3, 3, 3), dtype=np.float32)
    values[1, 1, 1] = 1.0
    with native.Volume.from_dense(values, origin=(10, 20, 30)) as volume:
        with volume.contour(0, isovalue=0.5) as mesh:
            arrays = mesh.arrays()
    expect((len(arrays.points), len(arrays.triangles)) == (6, 8),
           f"{len(arrays.points)} vertices {len(arrays.triangles)} triangles")
    centre = np.array([11, 21, 31], dtype=np.float32)
    offsets = np.sort(np.abs(arrays.points - centre), axis=1)
    expect(np.allclose(offsets, [[0, 0, 0.5]] * 6), f"corners {arrays.points.tolist()}")
    expect(arrays.stats.euler_characteristic == 2 and arrays.stats.boundary_edges == 0,
           "octahedron not closed")
    outward = np.einsum("ij,ij->i", arrays.normals, arrays.points - centre)
    expect(np.all(outward > 0), "fog normals should face away from the dense centre")


def case_progress_from_worker_thread():
    """A contour on a worker thread reports stages and ends at DONE."""
    progress = native.Progress()
    result = {}
    worker = threading.Thread(target=lambda: result.update(
        arrays=native.contour_file(data("sphere.vdb"), progress=progress)))
    worker.start()
    seen = set()
    while worker.is_alive():
        seen.add(progress.stage)
        expect(0.0 <= progress.fraction <= 1.0, f"fraction {progress.fraction}")
        worker.join(0.005)
    expect("arrays" in result, "the worker raised")
    expect(progress.stage == 5 and progress.stage_name == "done", f"stage {progress.stage}")
    expect(seen <= set(native.STAGE_NAMES), f"unknown stages {seen}")


def case_cancel_before_start():
    progress = native.Progress()
    progress.cancel()
    error = expect_raises(native.CancelledError,
                          lambda: native.contour_file(data("smoke.vdb"), progress=progress))
    expect(error.status == native.STATUS_CANCELLED, f"status {error.status}")


# ---------------------------------------------------------------- errors

def cli_message(*args):
    return cli(*args, code=1).stderr.strip()


def case_missing_file():
    with tempfile.TemporaryDirectory() as tmp:
        missing = os.path.join(tmp, "absent.vdb")
        error = expect_raises(native.IsoformError, lambda: native.contour_file(missing), missing)
        expect(error.status == 2 and error.status_name == "io error", f"status {error.status}")
        expect(str(error) in cli_message("info", missing), "message differs from the CLI's")


def case_vector_grid():
    with tempfile.TemporaryDirectory() as tmp:
        path = vector_vdb(tmp)
        with native.Volume.open(path) as volume:
            expect(volume.grid_count == 1, f"{volume.grid_count} grids")
            info = volume.grid_info(0)
            expect(info.name == "velocity" and info.value_type == "vec3s" and not info.is_scalar,
                   f"info {info}")
        expect_raises(native.IsoformError, lambda: native.contour_file(path), path,
                      "no scalar grid", "velocity")
        error = expect_raises(native.IsoformError,
                              lambda: native.contour_file(path, grid="velocity"),
                              "velocity", "vec3s", "scalar grids only")
        expect(error.status == 4, f"status {error.status}")
        expect(str(error) in cli_message("contour", path, "--grid", "velocity", "-o",
                                         os.path.join(tmp, "out.ply")),
               "message differs from the CLI's")


def case_unknown_grid_lists_names():
    expect_raises(native.IsoformError, lambda: native.contour_file(data("smoke.vdb"), grid="dens"),
                  "dens", "density")


def case_error_message_is_per_thread():
    """A failure on a worker thread carries that thread's message."""
    errors = []

    def fail():
        try:
            native.contour_file("/nonexistent/worker.vdb")
        except native.IsoformError as error:
            errors.append(str(error))
    worker = threading.Thread(target=fail)
    worker.start()
    worker.join()
    expect(len(errors) == 1 and "/nonexistent/worker.vdb" in errors[0], f"errors {errors}")


def case_bad_arguments():
    expect_raises(ValueError, lambda: native.contour_file(data("sphere.vdb"), method="marching"),
                  "marching", "cells")
    expect_raises(ValueError, lambda: native.Mesh.from_arrays(np.zeros((3, 2)), [[0, 1, 2]]),
                  "(n, 3)")


# ---------------------------------------------------------------- version

def case_wrong_version_refused():
    error = expect_raises(native.VersionMismatch, lambda: native.Library(ARGS.wrong_version),
                          ARGS.wrong_version, native.version_text(native.ISOFORM_VERSION))
    expect(native.version_text(native.ISOFORM_VERSION + 1) in str(error), str(error))


def case_expected_version_checked():
    real = os.environ[native.LIBRARY_ENV]
    expect_raises(native.VersionMismatch,
                  lambda: native.Library(real, expected_version=native.ISOFORM_VERSION + 100),
                  native.version_text(native.ISOFORM_VERSION),
                  native.version_text(native.ISOFORM_VERSION + 100))
    expect(native.Library(real).version == native.ISOFORM_VERSION, "the real library refused")


def case_library_lookup():
    expect(native.find_library() == os.environ[native.LIBRARY_ENV], native.find_library())
    saved = os.environ[native.LIBRARY_ENV]
    try:
        os.environ[native.LIBRARY_ENV] = "/nonexistent/libisoform.so"
        expect_raises(native.LibraryError, native.find_library, "/nonexistent/libisoform.so")
        del os.environ[native.LIBRARY_ENV]
        expect_raises(native.LibraryError, native.find_library, native.LIBRARY_ENV)
    finally:
        os.environ[native.LIBRARY_ENV] = saved


# ---------------------------------------------------------------- arrays in

TETRA_POINTS = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], dtype=np.float32)
# Counter-clockwise seen from outside.
TETRA_TRIANGLES = np.array([[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]], dtype=np.int32)


def case_from_arrays_tetrahedron():
    with native.Mesh.from_arrays(TETRA_POINTS, TETRA_TRIANGLES) as mesh:
        stats = mesh.stats()
        expect((stats.vertices, stats.triangles, stats.parts) == (4, 4, 1), f"stats {stats}")
        expect(stats.boundary_edges == 0 and stats.inconsistent_edges == 0 and
               stats.euler_characteristic == 2, f"stats {stats}")
        expect(np.array_equal(mesh.points(), TETRA_POINTS), "points changed")
        expect(np.array_equal(mesh.triangles(), TETRA_TRIANGLES), "triangles changed")
        # Across the edge from vertex 0 to 2 of triangle 0 lies triangle 2.
        expect(mesh.neighbours()[0].tolist() == [2, 3, 1], f"{mesh.neighbours().tolist()}")
        centre = TETRA_POINTS.mean(axis=0)
        outward = np.einsum("ij,ij->i", mesh.normals(), TETRA_POINTS - centre)
        expect(np.all(outward > 0), f"estimated normals {mesh.normals().tolist()}")


def case_from_arrays_refuses_bad_index():
    expect_raises(native.IsoformError,
                  lambda: native.Mesh.from_arrays(TETRA_POINTS, [[0, 1, 4]]), "vertex 4", "4 vertices")


def case_save_load_round_trip():
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "tetra.ply")
        with native.Mesh.from_arrays(TETRA_POINTS, TETRA_TRIANGLES) as mesh:
            mesh.save(path)
            normals = mesh.normals()
        with native.Mesh.load(path) as loaded:
            expect(np.array_equal(loaded.points(), TETRA_POINTS), "points differ after PLY")
            expect(np.array_equal(loaded.triangles(), TETRA_TRIANGLES), "triangles differ")
            expect(np.allclose(loaded.normals(), normals), "normals differ")
        expect_raises(native.IsoformError, lambda: native.Mesh.load(os.path.join(tmp, "no.ply")),
                      "no.ply")


def case_filter_parts_of_two_tetrahedra():
    """A big and a small tetrahedron: min_triangles, min_volume and largest."""
    big = TETRA_POINTS * 3.0
    points = np.concatenate([TETRA_POINTS + 10.0, big]).astype(np.float32)
    triangles = np.concatenate([TETRA_TRIANGLES, np.asarray(TETRA_TRIANGLES) + 4]).astype(np.int32)
    with native.Mesh.from_arrays(points, triangles) as mesh:
        dropped = mesh.filter_parts(min_triangles=5)
        expect((dropped.parts_before, dropped.parts_after) == (2, 0), f"{dropped}")
    with native.Mesh.from_arrays(points, triangles) as mesh:
        small = abs(np.linalg.det(TETRA_POINTS[1:] - TETRA_POINTS[0])) / 6
        dropped = mesh.filter_parts(min_volume=2 * small)
        expect((dropped.parts_after, dropped.triangles_after) == (1, 4), f"{dropped}")
        expect(np.allclose(mesh.points(), big), "the big tetrahedron's points, in order")
    with native.Mesh.from_arrays(points, triangles) as mesh:
        expect(mesh.filter_parts(largest=1).parts_after == 1, "largest=1")
        before = mesh.points()
        mesh.transform(np.diag([-1.0, -1.0, 1.0, 1.0]))  # RAS to LPS
        expect(np.array_equal(mesh.points(), before * [-1, -1, 1]), "points of the half turn")
        mesh.transform(np.diag([-1.0, 1.0, 1.0, 1.0]))  # a mirror
        expect(mesh.stats().inconsistent_edges == 0, "the mirror kept the orientation consistent")
        expect_raises(native.IsoformError, lambda: mesh.filter_parts(min_triangles=-1), "not negative")


GROUPS = {
    "layout": [case_layout_matches_c, case_library_reports_header_version],
    "contour": [case_smoke_counts_match_cli, case_tetra_counts_match_cli, case_dense_octahedron,
                case_progress_from_worker_thread, case_cancel_before_start],
    "errors": [case_missing_file, case_vector_grid, case_unknown_grid_lists_names,
               case_error_message_is_per_thread, case_bad_arguments],
    "version": [case_wrong_version_refused, case_expected_version_checked, case_library_lookup],
    "arrays": [case_from_arrays_tetrahedron, case_from_arrays_refuses_bad_index,
               case_save_load_round_trip, case_filter_parts_of_two_tetrahedra],
}


def run_groups(groups, options):
    """Runs the cases of the group named on the command line (options: the
    required --flags) and returns the exit code; sets ARGS first."""
    global ARGS
    parser = argparse.ArgumentParser()
    parser.add_argument("group", choices=sorted(groups))
    for option in options:
        parser.add_argument(option, required=True)
    ARGS = parser.parse_args()
    cases = groups[ARGS.group]
    failures = 0
    for case in cases:
        try:
            case()
            print(f"ok   {case.__name__}")
        except Exception:
            failures += 1
            print(f"FAIL {case.__name__}\n{traceback.format_exc()}")
    print(f"{len(cases) - failures}/{len(cases)} cases passed")
    return 1 if failures else 0


def main():
    return run_groups(GROUPS, ("--cli", "--layout", "--vector-vdb-maker", "--wrong-version",
                               "--data"))


if __name__ == "__main__":
    sys.exit(main())
