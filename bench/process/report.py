"""bench/RESULTS.md from one run of the whole-process bench: one table per
job, each target judged in the run itself."""

TARGETS = {
    "contour-vdb": "wall time at least 1.25 times faster than the OpenVDB program, peak memory at most its",
    "contour-dense": "at least as fast as the Flying Edges program",
    "reduce": "`--keep 10%` reaches at most 10.5 %; at most 2x meshoptimizer's wall time on the smooth "
              "inputs and 3x on the scans' contours; folded edges at most the input's plus fewer new "
              "ones than meshoptimizer makes",
}


def yes(ok):
    return "yes" if ok else "**no**"


def contour_table(rows, peer, speed_target, memory_target):
    lines = [f"| input | triangles (isoform / {peer}) | wall isoform | wall {peer} | speed-up | met | "
             f"peak isoform | peak {peer} | memory ratio | met |",
             "|---|---:|---:|---:|---:|:-:|---:|---:|---:|:-:|"]
    for r in rows:
        i, p = r["isoform"], r["peer"]
        speed, memory = p["wall"] / i["wall"], i["rss"] / p["rss"]
        memory_met = "-" if memory_target is None else yes(memory <= memory_target)
        lines.append(f"| {r['input']} | {r['triangles']:,} / {r['peer_triangles']:,} | {i['wall']:.3f} s | "
                     f"{p['wall']:.3f} s | {speed:.2f} | {yes(speed >= speed_target)} | {i['rss']:.0f} MiB | "
                     f"{p['rss']:.0f} MiB | {memory:.2f} | {memory_met} |")
    return "\n".join(lines)


def reduce_table(rows):
    lines = ["| input | method | wall | vs meshoptimizer | peak | triangles left | folds > 2.5 rad (input) "
             "| > 90° | boundary / non-manifold edges | parts | met |",
             "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|:-:|"]
    for r in rows:
        methods = r["methods"]
        base = methods.get("meshoptimizer")
        for name, m in methods.items():
            ratio = m["wall"] / base["wall"] if base else float("nan")
            met = "-"
            if name == "isoform":
                limit = 2.0 if r["kind"] == "smooth" else 3.0
                new_folds = m["folds"] - r["input_folds"]
                peer_new = base["folds"] - r["input_folds"] if base else 0
                met = yes(m["share"] <= 0.105 and ratio <= limit and (new_folds <= 0 or new_folds < peer_new))
            lines.append(f"| {r['input']} ({r['triangles']:,}) | {name} | {m['wall']:.2f} s | {ratio:.2f} | "
                         f"{m['rss']:.0f} MiB | {100 * m['share']:.1f} % | {m['folds']} ({r['input_folds']}) | "
                         f"{m['folds_90']} | {m['boundary_edges']} / {m['nonmanifold_edges']} | {m['parts']} | "
                         f"{met} |")
    return "\n".join(lines)


def first_call_table(rows):
    lines = ["| input | open | first contour | second contour (warm, not judged) |",
             "|---|---:|---:|---:|"]
    for r in rows:
        lines.append(f"| {r['input']} | {r['open_ms']:.1f} ms | {r['first_ms']:.1f} ms | {r['second_ms']:.1f} ms |")
    return "\n".join(lines)


def markdown(context, results):
    out = ["# Whole-process bench results", "",
           f"Written by `{context['command']}` (bench/README.md), started {context['started']}, "
           f"commit {context['commit']}, on {context['machine']}; load average at the end "
           f"{context['load']}. Every run is a fresh process that reads the input file, computes and "
           f"writes a PLY; isoform and the peer alternate, {context['pairs']} pairs after one untimed "
           "run of each; medians of wall time and of peak resident memory. The previous run's file is "
           "replaced: git keeps the history.", ""]
    if results.get("contour-vdb"):
        out += ["## Contour of a .vdb: `isoform contour` against OpenVDB's volumeToMesh", "",
                f"Target: {TARGETS['contour-vdb']}. isoform also writes unit normals and a part per "
                "triangle; the OpenVDB program writes points and triangles (its quads split).", "",
                contour_table(results["contour-vdb"], "OpenVDB", 1.25, 1.0), ""]
    if results.get("contour-dense"):
        out += ["## Contour of a dense scan: `isoform contour` of a NRRD header against VTK's Flying Edges", "",
                f"Target: {TARGETS['contour-dense']} (memory shown, not judged).", "",
                contour_table(results["contour-dense"], "VTK", 1.0, None), ""]
    if results.get("reduce"):
        out += ["## Reduction to 10 %: `isoform reduce --keep 10%` against meshoptimizer and OpenMesh", "",
                f"Target: {TARGETS['reduce']}. The error against the original surface is measured by "
                "`bench/run-reduce.sh` (docs/reduce-bench.md), not here.", "",
                reduce_table(results["reduce"]), ""]
    if results.get("first-call"):
        out += ["## The library's first call in a fresh process", "",
                "What the Blender add-on pays for its first contour: `isoform_volume_open`, then "
                "`isoform_contour` twice in one process (bench/process/first_call.c); medians of "
                f"{context['pairs']} processes.", "", first_call_table(results["first-call"]), ""]
    return "\n".join(out)


def readme_table(context, results):
    """The README's short table: one line per input of each job."""
    lines = [f"From `bench/RESULTS.md`, which says when, where and at which commit it ran (medians of "
             f"{context['pairs']} fresh processes each; ratio > 1: isoform is faster):", "",
             "| job | input | isoform | peer | peer / isoform, wall | isoform / peer, memory |",
             "|---|---|---:|---:|---:|---:|"]
    for job, peer in (("contour-vdb", "OpenVDB"), ("contour-dense", "VTK")):
        for r in results.get(job, []):
            i, p = r["isoform"], r["peer"]
            lines.append(f"| contour | {r['input']} | {i['wall']:.2f} s | {peer} {p['wall']:.2f} s | "
                         f"{p['wall'] / i['wall']:.2f} | {i['rss'] / p['rss']:.2f} |")
    for r in results.get("reduce", []):
        i, p = r["methods"]["isoform"], r["methods"].get("meshoptimizer")
        if p:
            lines.append(f"| reduce to 10 % | {r['input']} | {i['wall']:.2f} s | meshoptimizer {p['wall']:.2f} s | "
                         f"{p['wall'] / i['wall']:.2f} | {i['rss'] / p['rss']:.2f} |")
    return "\n".join(lines)
