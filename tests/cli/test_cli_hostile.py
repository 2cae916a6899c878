#!/usr/bin/python3
"""Hostile files given to the isoform command, as the fuzzers found them.

usage: test_cli_hostile.py ISOFORM_BINARY SHARED_DATA_DIR GROUP

Each file is made here, by code: a good file written by isoform itself,
then one field changed. For every one, each command that reads it must end
with exit code 1 (no signal), print one line on stderr that names the file,
stay under 1 GiB of resident memory and 10 seconds, and leave no output.
"""
import os
import resource
import struct
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "..", "tools"))
import hostile_files  # noqa: E402
import test_cli  # noqa: E402
from test_cli import expect, run_groups  # noqa: E402

LIMIT_BYTES = 1 << 30
LIMIT_SECONDS = 10


def run_limited(args):
    """Runs isoform; returns (exit status, stderr, peak resident bytes, seconds)."""
    start = time.monotonic()
    proc = subprocess.Popen([test_cli.BINARY, *args], stdout=subprocess.DEVNULL,
                            stderr=subprocess.PIPE, text=True)
    try:
        _, err = proc.communicate(timeout=LIMIT_SECONDS * 3)
    except subprocess.TimeoutExpired:
        proc.kill()
        proc.communicate()
        raise test_cli.CaseFailure(f"isoform {' '.join(args)}: still running after {LIMIT_SECONDS * 3} s")
    seconds = time.monotonic() - start
    # The children's peak: each run is the only child that ended since the last.
    peak = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss * 1024
    return proc.returncode, err, peak, seconds


def expect_refused(tmp, path, commands, message):
    """Each command on path fails cleanly, naming path and saying message."""
    before = sorted(os.listdir(tmp))
    for command in commands:
        out = os.path.join(tmp, "out" + command[1])
        args = [command[0], path] + (["-o", out] if command[1] else [])
        code, err, peak, seconds = run_limited(args)
        what = f"isoform {' '.join(args)}"
        expect(code == 1, f"{what}: exit {code} (a negative status is a signal)\n{err}")
        lines = err.strip().split("\n")
        expect(len(lines) == 1 and lines[0].startswith(f"isoform: error: {path}: "),
               f"{what}: not one line naming the file:\n{err}")
        expect(message in lines[0], f"{what}: {lines[0]!r} does not say {message!r}")
        expect(peak < LIMIT_BYTES, f"{what}: peak resident memory {peak >> 20} MiB")
        expect(seconds < LIMIT_SECONDS, f"{what}: took {seconds:.1f} s")
        expect(sorted(os.listdir(tmp)) == before, f"{what}: left {sorted(os.listdir(tmp))}")


VDB_COMMANDS = [("info", ""), ("contour", ".ply"), ("convert", ".vdb")]


def case_hostile_vdbs(tmp):
    """Each hostile VDB of tests/tools/hostile_files.py, through each command
    that reads a VDB (info describes every grid, which reads its tree)."""
    files = hostile_files.write_hostile_vdbs(test_cli.BINARY, tmp)
    for path, message in files.items():
        expect_refused(tmp, path, VDB_COMMANDS, message)


def stl_bytes(header, count, triangles):
    body = b"".join(struct.pack("<12fH", 0, 0, 0, *a, *b, *c, 0) for a, b, c in triangles)
    return header.ljust(80, b" ") + struct.pack("<I", count) + body


def case_stl_subnormal_repeated_vertex(tmp):
    """The fuzzer's crash of the curvature's colour map."""
    t = 1e-45
    triangles = [((t, 0, 0), (1, 0, 0), (0, 1e-33, 0)), ((1, 0, 0), (0, 1e-33, 0), (0, 0, 1e-40)),
                 ((t, 0, 0), (0, 0, 1e-40), (t, 0, 0)), ((0, 1e-33, 0), (t, 0, 0), (1, 0, 0))]
    path = os.path.join(tmp, "subnormal.stl")
    with open(path, "wb") as f:
        f.write(stl_bytes(b"binary", len(triangles), triangles))
    expect_refused(tmp, path, [("curvature", ".ply")], "uses a vertex twice")
    expect_refused(tmp, path, [("reduce", ".ply")], "uses a vertex twice")


def case_stl_solid_header_lying_count(tmp):
    triangles = [((0, 0, 0), (1, 0, 0), (0, 1, 0))] * 4
    path = os.path.join(tmp, "solid.stl")
    with open(path, "wb") as f:
        f.write(stl_bytes(b"solid evil", 1000, triangles))
    expect_refused(tmp, path, [("curvature", ".ply")],
                   "binary STL of 1000 triangles needs 50084 bytes but the file has 284 (truncated?)")


def case_nrrd_sizes_beyond_the_data(tmp):
    path = os.path.join(tmp, "huge.nrrd")
    with open(path, "wb") as f:
        f.write(b"NRRD0004\ntype: float\ndimension: 3\nsizes: 100000 100000 100000\nencoding: raw\n\n1234")
    expect_refused(tmp, path, [("info", ""), ("contour", ".ply"), ("convert", ".vdb")],
                   "need 4000000000000000 bytes")
    bomb = os.path.join(tmp, "bomb.nrrd")
    with open(bomb, "wb") as f:
        f.write(b"NRRD0004\ntype: float\ndimension: 3\nsizes: 1000 1000 1000\nencoding: gzip\n\n" + b"x" * 100)
    expect_refused(tmp, bomb, [("convert", ".vdb")], "more than 100 bytes of gzip data")


def case_memory_budget(tmp):
    """--memory, before or after the command, bounds what a file may take once
    read: a VDB grid, a raw scan and a NRRD past it are refused, naming the
    file and the budget, and leave nothing; a bad size is a usage error."""
    cube = test_cli.data("cube.vdb")
    out = os.path.join(tmp, "out.ply")
    for args in (["--memory", "1M", "contour", cube, "-o", out],
                 ["contour", cube, "-o", out, "--memory", "1MiB"]):
        code, err, peak, seconds = run_limited(args)
        expect(code == 1 and err.startswith(f"isoform: error: {cube}: ") and
               "in memory, beyond the budget of 1.0 MiB" in err, f"isoform {' '.join(args)}: {code} {err}")
        expect(os.listdir(tmp) == [], f"isoform {' '.join(args)} left {os.listdir(tmp)}")
    head = test_cli.data(test_cli.HEAD_RAW)
    code, err, _, _ = run_limited(["convert", head, "-o", os.path.join(tmp, "head.vdb"), "--memory", "2M",
                                   *test_cli.HEAD_LAYOUT])
    expect(code == 1 and "raw data of 64x64x93 samples would take 2.2 MiB in memory, beyond the budget "
           "of 2.0 MiB" in err, f"raw past the budget: {code} {err}")
    nrrd = os.path.join(tmp, "ball.nrrd")
    test_cli.write_ball_nrrd(nrrd, gzipped=False)
    code, err, _, _ = run_limited(["--memory", "40K", "info", nrrd])
    expect(code == 1 and err.startswith(f"isoform: error: {nrrd}: ") and
           "would take 62.5 KiB in memory, beyond the budget of 40.0 KiB" in err, f"NRRD past the budget: {code} {err}")
    os.remove(nrrd)
    for size in ("lots", "2X", "-1G", "0"):
        code, err, _, _ = run_limited(["--memory", size, "info", cube])
        expect(code == 2 and "--memory" in err, f"--memory {size}: exit {code} {err}")
    code, err, _, _ = run_limited(["contour", cube, "-o", out, "--memory", "2G"])
    expect(code == 0 and os.path.getsize(out) > 0, f"within the budget: exit {code} {err}")
    os.remove(out)


GROUPS = {
    "hostile_vdb": [case_hostile_vdbs],
    "hostile_mesh_nrrd": [case_stl_subnormal_repeated_vertex, case_stl_solid_header_lying_count,
                          case_nrrd_sizes_beyond_the_data],
    "memory_budget": [case_memory_budget],
}

if __name__ == "__main__":
    run_groups(GROUPS, sys.argv)
