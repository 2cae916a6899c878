"""Plots of an `isoform compare` study, made with matplotlib.

usage: /usr/bin/python3 plot_study.py STUDY_DIR

Reads STUDY_DIR/report.json and STUDY_DIR/samples.csv and writes
  curvature-histograms.png  histograms of the mean curvature H per surface
                            (the flat triangles have H = 0 inside every face
                            and are left out), with the reference's H if known;
  deviation.png             the distribution of the deviation from the
                            reference (sorted samples, log scale), when there is one;
  metrics.png               the table's error measures side by side (log scale).
Exits 1 with a message when matplotlib or the files are missing.
"""
import csv
import json
import math
import os
import sys

try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
except ImportError as error:
    sys.exit(f"plot_study.py: matplotlib is not available ({error})")


def load(study):
    with open(os.path.join(study, "report.json")) as f:
        report = json.load(f)
    columns = {}
    with open(os.path.join(study, "samples.csv")) as f:
        reader = csv.reader(f)
        header = next(reader)
        for name in header:
            columns[name] = []
        for row in reader:
            for name, value in zip(header, row):
                columns[name].append(float(value))
    return report, columns


def finite(values):
    return [v for v in values if math.isfinite(v)]


def save(fig, study, name):
    path = os.path.join(study, name)
    tmp = path + ".tmp.png"
    fig.savefig(tmp, dpi=110)
    plt.close(fig)
    os.replace(tmp, path)


def curvature_histograms(report, columns, study):
    fig, ax = plt.subplots(figsize=(7, 4.2))
    drawn = 0
    shown = [s for s in report["surfaces"]
             if any(v != 0 for v in finite(columns.get(s["name"] + "_mean", [])))]
    # One range and one set of bins for every surface, so bar heights compare.
    lo = min((s["mean_curvature"]["p05"] for s in shown), default=-1.0)
    hi = max((s["mean_curvature"]["p95"] for s in shown), default=1.0)
    span = (hi - lo) or 1.0
    for s in shown:
        h = finite(columns[s["name"] + "_mean"])
        ax.hist(h, bins=120, range=(lo - 0.25 * span, hi + 0.25 * span), histtype="step", linewidth=1.5,
                label=f"{s['name']} (std {s['mean_curvature']['stddev']:.3g})")
        drawn += 1
    ref = report["reference"]
    if ref["kind"] == "sphere":
        radius = float(ref["description"].rsplit("radius", 1)[1])
        ax.axvline(1.0 / radius, color="k", linestyle="--", label="sphere H = 1/r")
    ax.set_xlabel("mean curvature H (1/world unit)")
    ax.set_ylabel("samples")
    ax.set_title(f"H at the lattice samples ({report['sample_table_rows']} per surface)")
    if drawn:
        ax.legend()
    save(fig, study, "curvature-histograms.png")


def deviation_plot(report, columns, study):
    if report["reference"]["kind"] == "none":
        return
    fig, ax = plt.subplots(figsize=(7, 4.2))
    for s in report["surfaces"]:
        d = sorted(finite(columns.get(s["name"] + "_deviation", [])))
        if not d:
            continue
        ax.plot([100.0 * i / max(1, len(d) - 1) for i in range(len(d))], [max(v, 1e-16) for v in d],
                label=f"{s['name']} (max {s['deviation']['max']:.3g}, RMS {s['deviation']['rms']:.3g})")
    ax.set_yscale("log")
    ax.set_xlabel("samples, percent (sorted by deviation)")
    ax.set_ylabel(f"deviation ({report['reference']['deviation_unit']})")
    ax.set_title("Deviation from " + report["reference"]["description"])
    ax.legend()
    save(fig, study, "deviation.png")


def metrics_plot(report, study):
    measures = [("deviation", "deviation RMS"), ("data_point_error", "error at data points RMS"),
                ("normal_gap_radians", "normal gap RMS (rad)"),
                ("mean_curvature_jump", "H jump across edges RMS")]
    fig, ax = plt.subplots(figsize=(8, 4.2))
    width = 0.8 / max(1, len(report["surfaces"]))
    for i, s in enumerate(report["surfaces"]):
        values = [max(s[key]["rms"] or 0.0, 1e-17) if s[key]["count"] else 1e-17 for key, _ in measures]
        ax.bar([j + i * width for j in range(len(measures))], values, width, label=s["name"])
    ax.set_yscale("log")
    ax.set_xticks([j + 0.4 - width / 2 for j in range(len(measures))])
    ax.set_xticklabels([label for _, label in measures], fontsize=8)
    ax.set_title("Error measures (bars at 1e-17 are zero or not measured)")
    ax.legend()
    fig.tight_layout()
    save(fig, study, "metrics.png")


def main(argv):
    if len(argv) != 2:
        sys.exit("usage: plot_study.py STUDY_DIR")
    study = argv[1]
    report, columns = load(study)
    curvature_histograms(report, columns, study)
    deviation_plot(report, columns, study)
    metrics_plot(report, study)


if __name__ == "__main__":
    main(sys.argv)
