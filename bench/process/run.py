#!/usr/bin/python3
"""The whole-process bench: each job run as a user runs it, one fresh process
that reads a file, computes and writes a file, isoform and the peer's own
small program alternating, and bench/RESULTS.md written from the medians.

usage: run.py --build BUILD --data DATA --work WORK [--pairs N] [--only JOB ...]
              [--no-sphere] [--results FILE]

Jobs:
- contour-vdb: `isoform contour IN.vdb --iso V -o out.ply` against
  contour_openvdb (read the grid, volumeToMesh, write a PLY of triangles);
- contour-dense: `isoform contour IN.nhdr` (a NRRD header over the raw scan)
  against contour_vtk (the raw scan into a vtkImageData, vtkFlyingEdges3D
  with normals, vtkPLYWriter);
- reduce: `isoform reduce IN.ply --keep 10% -o out.ply` against
  reduce_meshopt and reduce_openmesh; the outputs are checked (share of
  triangles reached, folded edges, boundary and non-manifold edges);
- first-call: the library's first contour in a fresh process beside a
  second, warm one (first_call), what the Blender add-on pays.

Each pair's order alternates (isoform first, then the peer first); one
untimed run of each comes first so that both find the input in the page
cache. Wall time is taken around the child (under GNU time, which gives its
peak resident memory).
"""
import argparse
import datetime
import json
import os
import platform
import statistics
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import inputs  # noqa: E402
import mesh_checks  # noqa: E402
import report  # noqa: E402


def run_once(argv):
    """(wall seconds, peak resident MiB) of one fresh process; raises on failure.
    The peak comes from GNU time, a small parent: a child forked from this
    interpreter would count the interpreter's pages it held before exec."""
    with tempfile.NamedTemporaryFile("r", suffix=".rss") as rss:
        start = time.perf_counter()
        proc = subprocess.run(["/usr/bin/time", "-f", "%M", "-o", rss.name, *argv], stdout=subprocess.DEVNULL,
                              stderr=subprocess.PIPE, text=True)
        wall = time.perf_counter() - start
        if proc.returncode != 0:
            raise RuntimeError(f"{' '.join(argv)}: exit {proc.returncode}\n{proc.stderr}")
        peak_kb = int(rss.read().strip().splitlines()[-1])
    return wall, peak_kb / 1024.0


def alternate(commands, pairs):
    """commands: {name: argv}. Returns {name: [(wall, rss), ...]}, one per pair."""
    names = list(commands)
    for name in names:  # untimed: the page cache, the binaries' pages
        run_once(commands[name])
    samples = {name: [] for name in names}
    for i in range(pairs):
        order = names if i % 2 == 0 else list(reversed(names))
        for name in order:
            samples[name].append(run_once(commands[name]))
    return samples


def median(values):
    return statistics.median(values)


def summary(samples):
    return {"wall": median([w for w, _ in samples]), "rss": median([r for _, r in samples]),
            "walls": [round(w, 4) for w, _ in samples]}


def isoform_binary(build):
    return os.path.join(build, "cli", "isoform")


def peer(build, name):
    path = os.path.join(build, "bench", "process", name)
    return path if os.path.exists(path) else None


def contour_row(job, label, isoform_input, iso, peer_name, peer_argv, args, work):
    """One contour input: isoform on isoform_input against peer_argv (which
    ends with the peer's output file)."""
    out = os.path.join(work, "out-isoform.ply")
    commands = {"isoform": [isoform_binary(args.build), "contour", isoform_input, "--iso", str(iso), "-o", out, "-q"],
                peer_name: peer_argv}
    s = alternate(commands, args.pairs)
    row = {"input": label, "triangles": mesh_checks.triangle_count(out),
           "peer_triangles": mesh_checks.triangle_count(peer_argv[-1]),
           "isoform": summary(s["isoform"]), "peer": summary(s[peer_name])}
    print(f"{job} {label}: {row['isoform']['wall']:.3f} s / {row['peer']['wall']:.3f} s", flush=True)
    return row


def contour_vdb_jobs(args, work, prepared):
    program, out = peer(args.build, "contour_openvdb"), os.path.join(work, "out-openvdb.ply")
    return [contour_row("contour-vdb", case.label, case.path, case.iso, "OpenVDB",
                        [program, case.path, str(case.iso), out], args, work)
            for case in prepared.vdb_cases(args.no_sphere)]


def contour_dense_jobs(args, work, prepared):
    program, out = peer(args.build, "contour_vtk"), os.path.join(work, "out-vtk.ply")
    if not program:
        return []
    return [contour_row("contour-dense", case.label, case.nhdr, case.iso, "VTK",
                        [program, case.raw, *map(str, case.dims), case.type, *map(str, case.spacing),
                         str(case.iso), out], args, work)
            for case in prepared.dense_cases()]


def reduce_jobs(args, work, prepared):
    rows = []
    peers = {name: peer(args.build, program) for name, program in
             (("meshoptimizer", "reduce_meshopt"), ("OpenMesh", "reduce_openmesh"))}
    peers = {k: v for k, v in peers.items() if v}
    for case in prepared.reduce_cases():
        outs = {"isoform": os.path.join(work, "red-isoform.ply")}
        commands = {"isoform": [isoform_binary(args.build), "reduce", case.path, "--keep", "10%",
                                "-o", outs["isoform"], "-q"]}
        for name, program in peers.items():
            outs[name] = os.path.join(work, f"red-{name}.ply")
            commands[name] = [program, case.path, "0.1", outs[name]]
        s = alternate(commands, args.pairs)
        source = mesh_checks.load_ply(case.path)
        before = mesh_checks.check(source)
        row = {"input": case.label, "kind": case.kind, "triangles": before["triangles"],
               "input_folds": before["folds"], "methods": {}}
        for name, out in outs.items():
            facts = mesh_checks.check(mesh_checks.load_ply(out))
            facts["share"] = facts["triangles"] / before["triangles"]
            row["methods"][name] = {**summary(s[name]), **facts}
        rows.append(row)
        print(f"reduce {case.label}: " + ", ".join(
            f"{n} {m['wall']:.2f} s {100 * m['share']:.1f} %" for n, m in row["methods"].items()), flush=True)
    return rows


def first_call_jobs(args, work, prepared):
    rows = []
    program = peer(args.build, "first_call")
    for case in prepared.vdb_cases(args.no_sphere):
        results = []
        for _ in range(args.pairs):
            out = subprocess.run([program, case.path, str(case.iso)], capture_output=True, text=True, check=True)
            results.append(json.loads(out.stdout))
        rows.append({"input": case.label,
                     **{k: median([r[k] for r in results]) for k in ("open_ms", "first_ms", "second_ms")}})
    return rows


def machine():
    cpu = "unknown"
    with open("/proc/cpuinfo") as f:
        for line in f:
            if line.startswith("model name"):
                cpu = line.split(":", 1)[1].strip()
                break
    with open("/proc/meminfo") as f:
        mem_kb = int(f.readline().split()[1])
    return f"{cpu}, {os.cpu_count()} cores, {mem_kb / 2**20:.0f} GiB, {platform.platform()}"


def commit():
    try:
        out = subprocess.run(["git", "-C", HERE, "rev-parse", "--short", "HEAD"], capture_output=True, text=True)
        dirty = subprocess.run(["git", "-C", HERE, "status", "--porcelain", "--untracked-files=no"],
                               capture_output=True, text=True).stdout.strip()
        return out.stdout.strip() + (" with uncommitted changes" if dirty else "")
    except OSError:
        return "unknown"


README = os.path.join(HERE, "..", "..", "README.md")
RESULTS = os.path.join(HERE, "..", "RESULTS.md")
START, END = "<!-- whole-process bench: start -->", "<!-- whole-process bench: end -->"


def update_readme(table):
    """Puts the short table between the README's markers, if it has them."""
    with open(README) as f:
        text = f.read()
    if START not in text or END not in text:
        return
    head, rest = text.split(START, 1)
    _, tail = rest.split(END, 1)
    with open(README + ".tmp", "w") as f:
        f.write(head + START + "\n" + table + "\n" + END + tail)
    os.replace(README + ".tmp", README)


def user_arguments(argv):
    """The options a user gave bench/run-process.sh: without the folders it passes itself."""
    out, skip = [], False
    for a in argv:
        if skip:
            skip = False
        elif a in ("--build", "--data", "--work"):
            skip = True
        else:
            out.append(a)
    return out


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--build", required=True)
    parser.add_argument("--data", required=True)
    parser.add_argument("--work", required=True)
    parser.add_argument("--pairs", type=int, default=5)
    parser.add_argument("--only", nargs="*", default=["contour-vdb", "contour-dense", "reduce", "first-call"])
    parser.add_argument("--no-sphere", action="store_true")
    parser.add_argument("--results", default=RESULTS, help="results file (the README's table is written "
                        "only with the default, bench/RESULTS.md)")
    args = parser.parse_args()
    os.makedirs(args.work, exist_ok=True)
    started = datetime.datetime.now(datetime.timezone.utc)
    prepared = inputs.prepare(args.build, args.data, args.work, args.no_sphere)
    results = {}
    jobs = {"contour-vdb": contour_vdb_jobs, "contour-dense": contour_dense_jobs,
            "reduce": reduce_jobs, "first-call": first_call_jobs}
    for name in args.only:
        results[name] = jobs[name](args, args.work, prepared)
    load = os.getloadavg()
    context = {"started": started.strftime("%Y-%m-%d %H:%M UTC"), "machine": machine(), "commit": commit(),
               "pairs": args.pairs, "command": " ".join(["bench/run-process.sh", *user_arguments(sys.argv[1:])]),
               "load": f"{load[0]:.2f} {load[1]:.2f} {load[2]:.2f}"}
    text = report.markdown(context, results)
    temporary = args.results + ".tmp"
    with open(temporary, "w") as f:
        f.write(text)
    os.replace(temporary, args.results)
    if os.path.abspath(args.results) == os.path.abspath(RESULTS):
        update_readme(report.readme_table(context, results))
    with open(os.path.join(args.work, "results.json"), "w") as f:
        json.dump({"context": context, "results": results}, f, indent=1)
    print(text)


if __name__ == "__main__":
    main()
