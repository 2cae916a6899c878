"""Collects the report.json files of docs/make_compare_study.sh into the
tables of docs/compare.md (markdown on stdout).

usage: /usr/bin/python3 docs/compare_tables.py WORK_DIR HAVE_REDUCE"""
import json
import os
import sys

CASES = [("sphere", "sphere (analytic, radius 1)"), ("torus", "torus (radii 1, 0.4)"),
         ("cube", "cube.vdb (sharp edges)"), ("skull", "headsq skull at 1150.5")]


def g(x, digits=3):
    return "-" if x is None else f"{x:.{digits}g}"


def main(work, have_reduce):
    print("Base meshes: " + ("`isoform reduce` to 20% and 5% of the contour's triangles."
                             if have_reduce == "1" else
                             "coarse contours standing in for reduction (isoform reduce was not in the build): "
                             "the analytic volumes at 0.45 and 0.22 of the fine resolution, the cube as an "
                             "analytic box, headsq averaged over 2^3 and 4^3 blocks.") + "\n")
    print("| case | removed | triangles | surface | deviation max | deviation RMS | error at data points max "
          "| normal gap max (rad) | H jump RMS | H error RMS | H std | s per 10^6 samples |")
    print("|---|---:|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|")
    for key, label in CASES:
        for removed in ("80", "95"):
            path = os.path.join(work, f"{key}-{removed}", "report.json")
            if not os.path.isfile(path):
                continue
            with open(path) as f:
                r = json.load(f)
            unit = r["reference"]["deviation_unit"]
            for s in r["surfaces"]:
                dev = s["deviation"]
                print(f"| {label} | {removed}% | {r['base_triangles']} | {s['name']} | {g(dev['max'])} {unit} "
                      f"| {g(dev['rms'])} | {g(s['data_point_error']['max'])} | {g(s['normal_gap_radians']['max'])} "
                      f"| {g(s['mean_curvature_jump']['rms'])} "
                      f"| {g(s['mean_curvature_error']['rms']) if s['mean_curvature_error']['count'] else '-'} "
                      f"| {g(s['mean_curvature']['stddev'])} | {g(s['seconds_per_million_samples'])} |")


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
