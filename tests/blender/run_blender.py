#!/usr/bin/python3
"""Runs one group of in_blender.py in headless Blender with a throw-away
user configuration, after computing the expected figures with the isoform
command.

usage: run_blender.py GROUP --blender BLENDER --zip ADDON.zip --cli ISOFORM
                      --vector-vdb-maker MAKE_VECTOR_VDB --data DIR [--picture PNG]
                      [--xvfb-run XVFB_RUN]

Group "modal" runs Blender with a window under Xvfb (in_blender_window.py),
the others headless (in_blender.py).

Blender gets BLENDER_USER_CONFIG and BLENDER_USER_SCRIPTS inside a temporary
folder (the add-on is installed there from the zip), --factory-startup, and
no ISOFORM_LIBRARY: the add-on must load the library it carries. The real
user configuration folder is compared before and after.
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "tools"))
import hostile_files  # noqa: E402

BLENDER_TIMEOUT_SECONDS = 300


def snapshot(folder):
    """Names, sizes and times of everything under folder (empty if absent)."""
    found = {}
    for root, _, files in os.walk(folder):
        for name in files:
            path = os.path.join(root, name)
            try:
                status = os.stat(path)
            except OSError:
                continue
            found[path] = (status.st_size, status.st_mtime_ns)
    return found


def smoke_counts(args, tmp):
    """Vertices and triangles of smoke.vdb at 0.5 as the isoform command gives them."""
    proc = subprocess.run([args.cli, "contour", os.path.join(args.data, "smoke.vdb"), "--iso", "0.5",
                           "-o", os.path.join(tmp, "smoke.ply"), "--json"],
                          capture_output=True, text=True, check=True, timeout=600)
    summary = json.loads(proc.stdout)
    return summary["vertices"], summary["triangles"]


def blender_command(args):
    if args.group != "modal":
        return [args.blender, "-b", "--factory-startup", "--python-exit-code", "1",
                "--python", os.path.join(HERE, "in_blender.py")]
    # A window on a virtual screen; events are simulated (Esc), not read.
    return [args.xvfb_run, "-a", "-s", "-screen 0 1280x800x24", args.blender,
            "--factory-startup", "--enable-event-simulate",
            "--python", os.path.join(HERE, "in_blender_window.py")]


def window_result_ok(tmp):
    """in_blender_window.py writes one line per case to a file."""
    path = os.path.join(tmp, "window-result.txt")
    if not os.path.isfile(path):
        print("the window session wrote no result")
        return False
    with open(path) as result:
        text = result.read()
    print(text)
    lines = [line for line in text.splitlines() if line[:4] in ("ok  ", "FAIL")]
    return bool(lines) and all(line.startswith("ok") for line in lines)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("group")
    for option in ("--blender", "--zip", "--cli", "--vector-vdb-maker", "--data"):
        parser.add_argument(option, required=True)
    parser.add_argument("--picture", default="")
    parser.add_argument("--xvfb-run", default="xvfb-run")
    args = parser.parse_args()

    real_config = os.path.join(os.path.expanduser("~"), ".config", "blender")
    before = snapshot(real_config)
    with tempfile.TemporaryDirectory(prefix="isoform-blender-") as tmp:
        vertices, triangles = smoke_counts(args, tmp)
        vector = os.path.join(tmp, "velocity.vdb")
        subprocess.run([args.vector_vdb_maker, vector], check=True, timeout=60)
        # The hostile VDBs of tests/tools/hostile_files.py and what each
        # error must say, for the errors group.
        hostile = os.path.join(tmp, "hostile")
        os.makedirs(hostile)
        with open(os.path.join(hostile, "messages.json"), "w") as f:
            json.dump(hostile_files.write_hostile_vdbs(args.cli, hostile), f)
        env = dict(os.environ)
        env.pop("ISOFORM_LIBRARY", None)
        env["BLENDER_USER_CONFIG"] = os.path.join(tmp, "config")
        env["BLENDER_USER_SCRIPTS"] = os.path.join(tmp, "scripts")
        env["TMPDIR"] = os.path.join(tmp, "tmp")  # temporary .vdb files land here
        os.makedirs(env["TMPDIR"])
        command = blender_command(args) + [
            "--", args.group, "--zip", args.zip, "--data", args.data, "--vector-vdb", vector,
            "--expect-vertices", str(vertices), "--expect-triangles", str(triangles),
            "--scratch", tmp]
        if args.picture:
            command += ["--picture", os.path.abspath(args.picture)]
        proc = subprocess.run(command, env=env, timeout=BLENDER_TIMEOUT_SECONDS)
        leftovers = [name for name in os.listdir(env["TMPDIR"]) if name.startswith("isoform-")]
        window_failed = args.group == "modal" and not window_result_ok(tmp)
    if proc.returncode != 0 or window_failed:
        print(f"blender exited with {proc.returncode}")
        return 1
    if leftovers:
        print(f"temporary files left behind: {leftovers}")
        return 1
    if snapshot(real_config) != before:
        print(f"the real Blender configuration in {real_config} changed")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
