#!/usr/bin/env python3
"""Whole commands as a user runs them, timed with /usr/bin/time: wall time and peak memory.

  scripts/bench-commands.py goals   [--repeat N] [--large]   the performance goals, met or not
  scripts/bench-commands.py table   [--large]                the table of docs/performance.md
  scripts/bench-commands.py smoke                            a small run of every measurement (CI)

Scenes are boxes made by `datomsim generate box` in a scratch folder (--work, default a temporary
folder; 100 million modules take 8 GB of disk). Figures are medians over --repeat runs. The
binary is build/release/bin/datomsim unless --datomsim says otherwise.
"""
import argparse
import json
import os
import shutil
import statistics
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

# VisibleSim's flooding example on Datoms boxes (-O2, same machine kind): 10.8 M messages for a
# million modules in 262 s, about 41 thousand messages a second and 19 KB a module. 10.8 M is what
# flooding a 100 x 100 x 100 box sends (every module tells its other latched neighbours), the
# case compared here; a box of two layers sends 7.0 M.
VISIBLESIM_MESSAGES_PER_SECOND = 41_000

# name -> box size (x, y, z): two layers, as the paper's scenes, except the largest.
BOXES = {
    "10k": (100, 50, 2),
    "100k": (250, 200, 2),
    "1M": (1000, 500, 2),
    "2M": (1000, 1000, 2),
    "100M": (10000, 10000, 1),
    "cube1M": (100, 100, 100),
}


def modules(box):
    x, y, z = BOXES[box]
    return x * y * z


class Bench:
    def __init__(self, datomsim, work, repeat):
        self.datomsim = datomsim
        self.work = work
        self.repeat = repeat

    def path(self, name):
        return os.path.join(self.work, name)

    def measure(self, args, repeat=None):
        """Runs `datomsim args` and returns (seconds, peak kilobytes), medians over the runs; the
        fastest run's seconds are kept in self.best: on a shared machine a run now and then takes
        half as long again, and the best shows what the command itself costs."""
        times, peaks = [], []
        for _ in range(repeat or self.repeat):
            timing = self.path("time.txt")
            command = ["/usr/bin/time", "-f", "%e %M", "-o", timing, self.datomsim] + args
            done = subprocess.run(command, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
            if done.returncode != 0:
                sys.exit(f"bench-commands: `datomsim {' '.join(args)}` failed:\n{done.stderr}")
            with open(timing) as f:
                seconds, kilobytes = f.read().split()[-2:]
            times.append(float(seconds))
            peaks.append(int(kilobytes))
        self.best = min(times)
        return statistics.median(times), statistics.median(peaks)

    def scene(self, box, extension="json"):
        name = self.path(f"box-{box}.{extension}")
        if not os.path.exists(name):
            size = ",".join(map(str, BOXES[box]))
            self.measure(["generate", "box", "--size", size, "-o", name], repeat=1)
        return name

    @staticmethod
    def goal(box):
        x, y, z = BOXES[box]
        return f"{x // 2},{y // 2},{z}"

    @staticmethod
    def root(box):
        x, y, z = BOXES[box]
        return f"{x // 2},{y // 2},{z // 2 if z > 2 else 0}"

    def commands(self, box):
        """The commands of the table, as (label, arguments)."""
        json_scene = self.scene(box)
        out = self.path("out.json")
        rows = [
            ("generate box", ["generate", "box", "--size", ",".join(map(str, BOXES[box])),
                              "-o", self.path("generated.json")]),
            ("info", ["info", json_scene]),
            ("reach", ["reach", json_scene, "--goal", self.goal(box), "--out", out]),
        ]
        if box != "100M":
            rows += [
                ("run gradient", ["run", json_scene, "--program", "gradient", "--goal",
                                  self.goal(box), "--out", out]),
                ("run flood", ["run", json_scene, "--program", "flood", "--root", self.root(box),
                               "--out", out]),
            ]
        return rows


def megabytes(kilobytes):
    return kilobytes / 1024


def print_goal(name, figure, goal, met):
    print(f"  {name:<58} {figure:<36} goal {goal:<22} {'met' if met else 'NOT MET'}")


def goals(bench, large):
    print("Performance goals (whole commands, one process; median of "
          f"{bench.repeat} runs, the fastest in brackets; goals judged on the median):")
    out = bench.path("out.json")
    two = bench.scene("2M")
    seconds, peak = bench.measure(["reach", two, "--goal", bench.goal("2M"), "--out", out])
    print_goal("reach, 2 M modules, from JSON",
               f"{seconds:.2f} s ({bench.best:.2f}), {megabytes(peak):.0f} MB",
               "< 1 s, < 200 MB", seconds < 1 and megabytes(peak) < 200)
    xml = bench.scene("2M", "xml")
    seconds, peak = bench.measure(["reach", xml, "--goal", bench.goal("2M"), "--out", out])
    print_goal("reach, 2 M modules, from VisibleSim XML",
               f"{seconds:.2f} s ({bench.best:.2f}), {megabytes(peak):.0f} MB",
               "< 2 s, < 400 MB", seconds < 2 and megabytes(peak) < 400)

    seconds, peak = bench.measure(["run", two, "--program", "gradient", "--goal", bench.goal("2M"),
                                   "--out", out])
    per_module = peak * 1024 / modules("2M")
    print_goal("distributed gradient, 2 M modules",
               f"{seconds:.2f} s ({bench.best:.2f}), {per_module:.0f} B/module",
               "< 2 s, < 150 B/module", seconds < 2 and per_module < 150)

    for box, label in [("cube1M", "flood, 1 M modules, 100 x 100 x 100 (VisibleSim's case)"),
                       ("1M", "flood, 1 M modules, 1000 x 500 x 2")]:
        scene = bench.scene(box)
        seconds, peak = bench.measure(["run", scene, "--program", "flood", "--root",
                                       bench.root(box), "--out", out])
        with open(out) as f:
            messages = json.load(f)["messages"]
        rate, best_rate = messages / seconds, messages / bench.best
        per_module = peak * 1024 / modules(box)
        print_goal(label, f"{seconds:.2f} s ({bench.best:.2f}), {per_module:.0f} B/module",
                   "< 1 s, < 100 B/module", seconds < 1 and per_module < 100)
        print_goal(f"  its messages ({messages / 1e6:.1f} M) per second of the command",
                   f"{rate / 1e6:.1f} M/s ({best_rate / 1e6:.1f}) = "
                   f"{rate / VISIBLESIM_MESSAGES_PER_SECOND:.0f}x VisibleSim",
                   "> 10 M/s, >= 250x", rate > 10e6)

    picture_scene = bench.path("box-180k.json")
    if not os.path.exists(picture_scene):
        bench.measure(["generate", "box", "--size", "300,300,2", "-o", picture_scene], repeat=1)
    png = bench.path("map.png")
    seconds, peak = bench.measure(["reach", picture_scene, "--goal", "150,150,2", "--out", out,
                                   "--png", png])
    width = png_width(png)
    print_goal("reach --png, 180 k modules", f"{seconds:.2f} s ({bench.best:.2f}), {width} px wide",
               "< 2 s, <= 4096 px", seconds < 2 and width <= 4096)

    if large:
        hundred = bench.scene("100M")
        for label, args in bench.commands("100M"):
            seconds, peak = bench.measure(args, repeat=1)
            print_goal(f"{label}, 100 M modules", f"{seconds:.0f} s, {megabytes(peak) / 1024:.1f} GB",
                       "fits in 24 GB", megabytes(peak) < 24 * 1024)
        del hundred
    else:
        print("  (100 M modules: run with --large; it takes minutes and 8 GB of disk)")


def png_width(path):
    with open(path, "rb") as f:
        header = f.read(24)
    return int.from_bytes(header[16:20], "big")


def table(bench, large):
    boxes = ["10k", "100k", "1M", "2M"] + (["100M"] if large else [])
    print("| command | " + " | ".join(f"{box} ({modules(box):,} modules)" for box in boxes) + " |")
    print("|---|" + "---|" * len(boxes))
    results = {}
    for box in boxes:
        for label, args in bench.commands(box):
            results[(label, box)] = bench.measure(args, repeat=1 if box == "100M" else bench.repeat)
    labels = [label for label, _ in bench.commands("10k")]
    for label in labels:
        cells = []
        for box in boxes:
            if (label, box) not in results:
                cells.append("")
                continue
            seconds, peak = results[(label, box)]
            memory = f"{megabytes(peak) / 1024:.1f} GB" if peak > 1024 * 1024 else f"{megabytes(peak):.0f} MB"
            cells.append(f"{seconds:.2f} s, {memory}")
        print(f"| `{label}` | " + " | ".join(cells) + " |")


def smoke(bench):
    # Every kind of measurement once on a small box: the script keeps working.
    out = bench.path("out.json")
    for label, args in bench.commands("10k"):
        seconds, peak = bench.measure(args, repeat=1)
        print(f"  {label:<14} 10k modules: {seconds:.2f} s, {megabytes(peak):.0f} MB")
    bench.measure(["reach", bench.scene("10k", "xml"), "--goal", bench.goal("10k"), "--out", out,
                   "--png", bench.path("map.png")], repeat=1)
    print(f"  reach --png    10k modules from XML: {png_width(bench.path('map.png'))} px wide")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("what", choices=["goals", "table", "smoke"])
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--large", action="store_true", help="also 100 million modules")
    parser.add_argument("--work", help="scratch folder for scenes (kept)")
    parser.add_argument("--datomsim", default=os.path.join(ROOT, "build/release/bin/datomsim"))
    args = parser.parse_args()
    if not os.path.exists(args.datomsim):
        sys.exit(f"bench-commands: no {args.datomsim}; build first (scripts/build.sh)")
    if not os.path.exists("/usr/bin/time"):
        sys.exit("bench-commands: /usr/bin/time is missing (Debian package: time)")
    work = args.work or tempfile.mkdtemp(prefix="datomsim-bench-")
    os.makedirs(work, exist_ok=True)
    try:
        bench = Bench(args.datomsim, work, args.repeat)
        {"goals": lambda: goals(bench, args.large), "table": lambda: table(bench, args.large),
         "smoke": lambda: smoke(bench)}[args.what]()
    finally:
        if not args.work:
            shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    main()
