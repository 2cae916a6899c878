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

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
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


def fog_vdb(tmp):
    """A 32^3 fog volume of varying values, written by isoform convert; its bytes."""
    raw = os.path.join(tmp, "fog.raw")
    with open(raw, "wb") as f:
        f.write(struct.pack("<32768f", *[float((i * 7919) % 97) for i in range(32768)]))
    vdb = os.path.join(tmp, "fog.vdb")
    test_cli.run("convert", raw, "--dims", "32,32,32", "--type", "f32", "-o", vdb)
    with open(vdb, "rb") as f:
        data = bytearray(f.read())
    os.remove(raw)
    os.remove(vdb)
    return data


def leaf_chunk(data):
    """Where the first leaf's blosc chunk size lies: an int64 n, then a blosc
    header saying 2,048 bytes decoded from n."""
    for at in range(len(data) - 24):
        n = struct.unpack_from("<q", data, at)[0]
        if 16 < n < 100000 and data[at + 8] == 2 and struct.unpack_from("<I", data, at + 12)[0] == 2048 \
                and struct.unpack_from("<I", data, at + 20)[0] == n:
            return at
    raise test_cli.CaseFailure("no leaf chunk in the fog volume")


def string_at(data, text, start=0):
    """Where the length field of the length-prefixed string text lies."""
    at = data.find(struct.pack("<I", len(text)) + text.encode(), start)
    expect(at >= 0, f"no string {text!r}")
    return at


def hostile_vdb(tmp, name, change):
    data = fog_vdb(tmp)
    change(data)
    path = os.path.join(tmp, name)
    with open(path, "wb") as f:
        f.write(data)
    return path


def case_negative_chunk_size(tmp):
    """OpenVDB's bloscFromStream would write 100,000 bytes into 2,048."""
    path = hostile_vdb(tmp, "negative.vdb", lambda d: struct.pack_into("<q", d, leaf_chunk(d), -100000))
    expect_refused(tmp, path, VDB_COMMANDS[1:], "a raw chunk of 100000 bytes where 2048 are expected")
    # info reads every grid's facts, which read the tree.
    expect_refused(tmp, path, VDB_COMMANDS[:1], "a raw chunk of 100000 bytes")


def case_huge_chunk_size(tmp):
    path = hostile_vdb(tmp, "huge.vdb", lambda d: struct.pack_into("<q", d, leaf_chunk(d), 10 ** 15))
    expect_refused(tmp, path, VDB_COMMANDS, "a compressed chunk at byte")


def case_huge_type_name_length(tmp):
    """GridDescriptor::read would allocate 7.5 GB."""
    def change(d):
        struct.pack_into("<I", d, string_at(d, "density") + 4 + 7, 1918107664)
    path = hostile_vdb(tmp, "typename.vdb", change)
    expect_refused(tmp, path, VDB_COMMANDS, "a grid type name at byte")


def case_huge_metadata_string(tmp):
    """StringMetadata::readValue would allocate 2 GB."""
    def change(d):
        struct.pack_into("<I", d, string_at(d, "string", string_at(d, "class")) + 10, 2000000000)
    path = hostile_vdb(tmp, "metadata.vdb", change)
    expect_refused(tmp, path, VDB_COMMANDS, "a metadata value at byte")


def case_lying_blosc_header(tmp):
    path = hostile_vdb(tmp, "blosc.vdb", lambda d: struct.pack_into("<I", d, leaf_chunk(d) + 12, 4096))
    expect_refused(tmp, path, VDB_COMMANDS, "whose header says 4096 bytes")


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


GROUPS = {
    "hostile_vdb": [case_negative_chunk_size, case_huge_chunk_size, case_huge_type_name_length,
                    case_huge_metadata_string, case_lying_blosc_header],
    "hostile_mesh_nrrd": [case_stl_subnormal_repeated_vertex, case_stl_solid_header_lying_count,
                          case_nrrd_sizes_beyond_the_data],
}

if __name__ == "__main__":
    run_groups(GROUPS, sys.argv)
