#!/usr/bin/python3
"""`isoform curvature-volume` run as a program, the way a user runs it.

usage: test_cli_curvature_volume.py ISOFORM_BINARY SHARED_DATA_DIR MAKE_VECTOR_VDB GROUP

The written file is read back with `isoform info --json` (the library's
OpenVDB reader), so the test sees what any VDB reader sees: which grids, how
many active voxels.
"""
import hashlib
import json
import os
import shutil
import subprocess
import sys
import tempfile
import traceback

BINARY = None
DATA = None
MAKE_VECTOR_VDB = None
RUN_TIMEOUT_SECONDS = 600
SMOKE_ACTIVE = 1049275  # smoke.vdb's active voxels, as OpenVDB counts them
SPHERE_ACTIVE = 270638
RESULT_GRIDS = ["mean", "gauss", "k1", "k2", "k3"]


class CaseFailure(Exception):
    pass


def expect(condition, message):
    if not condition:
        raise CaseFailure(message)


def run(*args, code=0):
    proc = subprocess.run([BINARY, *args], capture_output=True, text=True, timeout=RUN_TIMEOUT_SECONDS)
    expect(proc.returncode == code,
           f"isoform {' '.join(args)}: exit {proc.returncode}, expected {code}\n"
           f"stdout: {proc.stdout[-2000:]}\nstderr: {proc.stderr[-2000:]}")
    return proc


def grids_of(path):
    return {g["name"]: g for g in json.loads(run("info", path, "--json").stdout)["grids"]}


def sha256(path):
    with open(path, "rb") as f:
        return hashlib.sha256(f.read()).hexdigest()


def expect_one_error(proc, mentions, tmp, keep):
    lines = proc.stderr.splitlines()
    expect(len(lines) == 1 and lines[0].startswith("isoform: error: "), f"stderr: {proc.stderr!r}")
    missing = [m for m in mentions if m not in lines[0]]
    expect(not missing, f"error line does not name {missing}: {lines[0]}")
    expect(proc.stdout == "", f"a failure printed a summary: {proc.stdout}")
    left = sorted(set(os.listdir(tmp)) - set(keep))
    expect(left == [], f"left behind {left}")


def case_help(tmp):
    out = run("curvature-volume", "--help").stdout
    for word in ("--grid", "--method", "--json", "-o", "mean", "k3", "Section 4.3"):
        expect(word in out, f"--help does not mention {word}")
    expect("curvature-volume" in run("--help").stdout, "top-level --help does not list the command")


def case_smoke_default(tmp):
    out = os.path.join(tmp, "curv.vdb")
    summary = json.loads(run("curvature-volume", os.path.join(DATA, "smoke.vdb"), "-o", out, "--json").stdout)
    expect(summary["points"] == SMOKE_ACTIVE, f"points {summary['points']}")
    expect(sum(f["points"] for f in summary["fits"]) == SMOKE_ACTIVE, "fit counts do not add up")
    for name in RESULT_GRIDS:
        s = summary["grids"][name]
        expect(s["min"] <= s["p01"] <= s["p50"] <= s["p99"] <= s["max"], f"{name}: percentiles out of order {s}")
    k1, k2, k3 = (summary["grids"][n]["p50"] for n in ("k1", "k2", "k3"))
    expect(k1 >= k2 >= k3, f"medians of k1, k2, k3 out of order: {k1}, {k2}, {k3}")
    grids = grids_of(out)
    expect(sorted(grids) == sorted(RESULT_GRIDS), f"grids {sorted(grids)}")
    for name, g in grids.items():
        expect(g["active_voxels"] == SMOKE_ACTIVE, f"{name}: {g['active_voxels']} active voxels")
        expect(g["class"] == "other" and g["value_type"] == "float", f"{name}: {g['class']}, {g['value_type']}")


def case_sphere_seed_text(tmp):
    out = os.path.join(tmp, "curv.vdb")
    text = run("curvature-volume", os.path.join(DATA, "sphere.vdb"), "--grid", "ls_sphere",
               "--method", "seed", "-o", out).stdout
    for word in ("method seed", "points", "k1", "gauss", "fallback", "wrote"):
        expect(word in text, f"summary lacks {word!r}: {text}")
    grids = grids_of(out)
    expect(sorted(grids) == sorted(RESULT_GRIDS), f"grids {sorted(grids)}")
    for name, g in grids.items():
        expect(g["active_voxels"] == SPHERE_ACTIVE, f"{name}: {g['active_voxels']} active voxels")


def case_bad_input(tmp):
    vector = os.path.join(tmp, "vel.vdb")
    subprocess.run([MAKE_VECTOR_VDB, vector], check=True)
    proc = run("curvature-volume", vector, "-o", os.path.join(tmp, "o.vdb"), "--grid", "velocity", code=1)
    expect_one_error(proc, ["vel.vdb", "velocity", "vec3s"], tmp, ["vel.vdb"])
    missing = os.path.join(tmp, "missing.vdb")
    proc = run("curvature-volume", missing, "-o", os.path.join(tmp, "o.vdb"), code=1)
    expect_one_error(proc, ["missing.vdb"], tmp, ["vel.vdb"])
    copy = os.path.join(tmp, "in.vdb")
    shutil.copyfile(os.path.join(DATA, "sphere.vdb"), copy)
    before = sha256(copy)
    proc = run("curvature-volume", copy, "-o", copy, code=1)
    expect_one_error(proc, ["in.vdb", "refusing"], tmp, ["vel.vdb", "in.vdb"])
    expect(sha256(copy) == before, "the input changed")
    proc = run("curvature-volume", copy, "-o", os.path.join(tmp, "o.ply"), code=1)
    expect_one_error(proc, ["o.ply"], tmp, ["vel.vdb", "in.vdb"])
    run("curvature-volume", copy, "--method", "newton", "-o", os.path.join(tmp, "o.vdb"), code=2)


GROUPS = {
    "help": [case_help],
    "smoke": [case_smoke_default],
    "sphere_seed": [case_sphere_seed_text],
    "bad_input": [case_bad_input],
}


def main():
    global BINARY, DATA, MAKE_VECTOR_VDB
    if len(sys.argv) != 5 or sys.argv[4] not in GROUPS:
        sys.exit(f"usage: {sys.argv[0]} ISOFORM_BINARY SHARED_DATA_DIR MAKE_VECTOR_VDB {{{','.join(GROUPS)}}}")
    BINARY, DATA, MAKE_VECTOR_VDB = (os.path.abspath(a) for a in sys.argv[1:4])
    group = sys.argv[4]
    failed = 0
    for case in GROUPS[group]:
        with tempfile.TemporaryDirectory(prefix="isoform-cli-curv-") as tmp:
            try:
                case(tmp)
                print(f"PASS {case.__name__}")
            except CaseFailure as failure:
                failed += 1
                print(f"FAIL {case.__name__}: {failure}")
            except Exception:
                failed += 1
                print(f"FAIL {case.__name__}: unexpected error\n{traceback.format_exc()}")
    print(f"{group}: {len(GROUPS[group]) - failed} passed, {failed} failed")
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
