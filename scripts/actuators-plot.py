#!/usr/bin/env python3
"""The plot of `datomsim actuators compare` (docs/actuators.md, "The paper's experiment by
combination and size"): energy per motion, makespan and the ensemble's peak power against the
module's radius, one line per combination, both axes logarithmic.

    scripts/actuators-plot.py DIR/compare.csv -o DIR/compare.png

A run that failed is drawn as a red cross.
"""
import argparse
import csv
import os
import sys
import tempfile


def read_rows(path):
    try:
        with open(path, newline="") as handle:
            rows = list(csv.DictReader(handle))
    except OSError as error:
        raise SystemExit(f"actuators-plot: {path}: {error.strerror}")
    needed = {"combination", "radius_m", "makespan_s", "energy_per_motion_J", "peak_power_W",
              "failure"}
    if not rows or not needed <= set(rows[0]):
        raise SystemExit(f"actuators-plot: {path}: not a compare.csv of datomsim actuators compare "
                         f"(expected the columns {', '.join(sorted(needed))})")
    return rows


def plot(rows, path):
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        raise SystemExit("actuators-plot: needs matplotlib (Debian: python3-matplotlib; "
                         "scripts/install-deps.sh installs it)")
    figure, panels = plt.subplots(1, 3, figsize=(15, 4.5), dpi=120)
    columns = (("energy_per_motion_J", "energy per motion (J)", "Energy per motion"),
               ("makespan_s", "makespan (s)", "Makespan"),
               ("peak_power_W", "peak power (W)", "Peak power of the ensemble"))
    combinations = list(dict.fromkeys(r["combination"] for r in rows))
    for combination in combinations:
        mine = sorted((float(r["radius_m"]), r) for r in rows if r["combination"] == combination)
        radii = [radius for radius, _ in mine]
        for axes, (column, _, _) in zip(panels, columns):
            axes.plot(radii, [float(r[column]) for _, r in mine], marker="o", label=combination)
            failed = [(radius, float(r[column])) for radius, r in mine if r["failure"]]
            if failed:
                axes.scatter(*zip(*failed), marker="x", color="red", zorder=3)
    for axes, (_, label, title) in zip(panels, columns):
        axes.set_xscale("log")
        axes.set_yscale("log")
        axes.set_xlabel("module radius r (m)")
        axes.set_ylabel(label)
        axes.grid(True, which="both", alpha=0.3)
        axes.set_title(title)
    panels[1].legend(fontsize=7)
    figure.tight_layout()
    # Written whole or not at all.
    folder = os.path.dirname(os.path.abspath(path))
    descriptor, temporary = tempfile.mkstemp(suffix=".png", dir=folder)
    os.close(descriptor)
    try:
        figure.savefig(temporary)
        # mkstemp makes the file private (0600); a picture is as readable as any other file.
        umask = os.umask(0)
        os.umask(umask)
        os.chmod(temporary, 0o666 & ~umask)
        os.replace(temporary, path)
    except BaseException:
        os.unlink(temporary)
        raise
    print(f"wrote {path}", file=sys.stderr)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("csv")
    parser.add_argument("-o", "--output", required=True)
    options = parser.parse_args()
    if os.path.abspath(options.output) == os.path.abspath(options.csv):
        raise SystemExit(f"actuators-plot: -o {options.output} would overwrite the CSV it reads")
    plot(read_rows(options.csv), options.output)


if __name__ == "__main__":
    main()
