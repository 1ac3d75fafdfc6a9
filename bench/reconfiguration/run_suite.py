#!/usr/bin/env python3
"""The reconfiguration benchmark suite (docs/reconfiguration.md, "Benchmark suite").

    bench/reconfiguration/run_suite.py [--out DIR] [--large] [--family F ...] [--workers N]
                                       [--param KEY=VALUE ...]

Each case of suite.json is generated with `datomsim generate reshape`, then run three ways: the
distributed program (`run --program reconfigure`), the same one motion at a time
(`--max-motions 1`, for the speed-up), and the centralised planner (`datomsim plan`, for the
motion count to compare with and a lower bound). `--param` is given to both runs of the
distributed program (`--param claims=1`: docs/reconfiguration.md, "Claims"). DIR (default reconfiguration-results) receives:

    results.csv    one row per case
    summary.md     the table, each family's figures and the quality goals, met or not
    makespan.png   makespan against movers, log-log, one line per family

The cases' scenes and every run's JSON output stay in DIR/cases and DIR/runs to be looked at.
Runs are seeded: the same build gives the same rows but for the wall times.
"""
import argparse
import concurrent.futures
import csv
import json
import math
import os
import platform
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))

COLUMNS = ["family", "case", "seed", "modules", "movers", "target_height", "success", "reason",
           "motions", "planner_motions", "motion_ratio", "lower_bound", "makespan_s",
           "sequential_makespan_s", "speedup", "messages", "max_concurrent_motions",
           "mean_concurrent_motions", "sequential_success", "wall_s"]


def command(datomsim, *args):
    """Runs datomsim; returns its exit status and what it printed on standard error."""
    done = subprocess.run([datomsim, *args], capture_output=True, text=True)
    return done.returncode, done.stderr.strip()


def read_json(path):
    with open(path) as f:
        return json.load(f)


def has_planner(datomsim):
    return subprocess.run([datomsim, "plan", "--help"], capture_output=True).returncode == 0


def cases(suite, families, large):
    for family in suite["families"]:
        if families and family["family"] not in families:
            continue
        for case in family["cases"]:
            if case.get("large") and not large:
                continue
            for seed in case.get("seeds", [1]):
                # The family, the case's own name when it differs, and its values.
                words = [a.lstrip("-") for a in case["args"]]
                if words[0] == family["family"]:
                    words = words[1:]
                name = "-".join([family["family"], *words])
                if "seeds" in case:
                    name += f"-seed{seed}"
                yield family["family"], name.replace(",", "x"), case["args"], seed


def run_case(datomsim, out, planner, params, family, name, args, seed):
    scene = os.path.join(out, "cases", name + ".json")
    runs = os.path.join(out, "runs", name)
    row = {"family": family, "case": name, "seed": seed}
    status, error = command(datomsim, "generate", "reshape", *args, "--seed", str(seed),
                            "-o", scene)
    if status != 0:
        raise SystemExit(f"suite case {name}: generate reshape failed: {error}")
    info = read_json_output(datomsim, scene)
    target = info["targets"][0]
    row["modules"] = info["modules"]
    row["movers"] = info["modules"] - target["filled"]

    parallel = runs + "-distributed.json"
    sequential = runs + "-sequential.json"
    given = [word for pair in params for word in ("--param", pair)]
    wall = run_timed(datomsim, scene, parallel, seed, given)
    run_timed(datomsim, scene, sequential, seed, [*given, "--max-motions", "1"])
    result, alone = read_json(parallel), read_json(sequential)
    # The target: the cells filled at the end but the extra ones, and those left empty.
    cells = [c for c in result["final"] if c not in result["extra"]] + result["missing"]
    row["target_height"] = max(c[2] for c in cells) if cells else 0
    row["success"] = result["success"]
    row["reason"] = result.get("reason", "")
    row["motions"] = result["motions"]
    row["makespan_s"] = round(result["makespan_s"], 3)
    row["sequential_makespan_s"] = round(alone["makespan_s"], 3)
    row["sequential_success"] = alone["success"]
    row["speedup"] = (round(alone["makespan_s"] / result["makespan_s"], 3)
                      if result["success"] and alone["success"] and result["makespan_s"] > 0
                      else "")
    row["messages"] = result["messages"]
    row["max_concurrent_motions"] = result["max_concurrent_motions"]
    row["mean_concurrent_motions"] = round(result["mean_concurrent_motions"], 3)
    row["wall_s"] = round(wall, 2)
    row["planner_motions"] = row["motion_ratio"] = row["lower_bound"] = ""
    if planner:
        plan_out = runs + "-plan.json"
        status, error = command(datomsim, "plan", scene, "--out", plan_out)
        if os.path.exists(plan_out):
            plan = read_json(plan_out)
            row["lower_bound"] = plan.get("lower_bound", "")
            if plan.get("success"):
                row["planner_motions"] = plan["motions"]
                if result["success"] and plan["motions"] > 0:
                    row["motion_ratio"] = round(result["motions"] / plan["motions"], 3)
    return row


def read_json_output(datomsim, scene):
    done = subprocess.run([datomsim, "info", scene, "--json"], capture_output=True, text=True)
    if done.returncode != 0:
        raise SystemExit(f"suite: info {scene} failed: {done.stderr.strip()}")
    return json.loads(done.stdout)


def run_timed(datomsim, scene, out, seed, extra):
    """A run as a user runs it; a target not built is a result (exit 1 with its JSON written)."""
    start = time.monotonic()
    status, error = command(datomsim, "run", scene, "--program", "reconfigure", "--seed",
                            str(seed), "--out", out, *extra)
    if not os.path.exists(out):
        raise SystemExit(f"suite: run {scene} wrote nothing: {error}")
    return time.monotonic() - start


def exponent(rows):
    """The slope of log makespan against log movers over the successful rows (least squares)."""
    points = [(math.log(r["movers"]), math.log(r["makespan_s"])) for r in rows
              if r["success"] and r["movers"] > 0 and r["makespan_s"] > 0]
    if len(points) < 3:
        return None
    mx = sum(x for x, _ in points) / len(points)
    my = sum(y for _, y in points) / len(points)
    sxx = sum((x - mx) ** 2 for x, _ in points)
    return sum((x - mx) * (y - my) for x, y in points) / sxx if sxx > 0 else None


def median(values):
    values = sorted(values)
    if not values:
        return None
    middle = len(values) // 2
    return values[middle] if len(values) % 2 else (values[middle - 1] + values[middle]) / 2


def summary(suite, rows, planner, version, params):
    given = ", ".join(f"`--param {p}`" for p in params) or "the program's defaults"
    lines = [f"# {suite['name']}, version {suite['version']}", "",
             f"datomsim {version}; {platform.machine()}, {os.cpu_count()} cores; "
             f"reconfigure with {given}. "
             f"{len(rows)} cases, {sum(r['success'] for r in rows)} built.", ""]
    if not planner:
        lines += ["The centralised planner (`datomsim plan`) is not in this build: the planner "
                  "columns are empty.", ""]
    lines += ["| case | movers | height | built | motions | planner | ratio | lower bound | "
              "makespan s | speed-up | peak / mean motions | reason |",
              "|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        lines.append(
            f"| {r['case']} | {r['movers']} | {r['target_height']} | "
            f"{'yes' if r['success'] else '**no**'} | {r['motions']} | {r['planner_motions']} | "
            f"{r['motion_ratio']} | {r['lower_bound']} | {r['makespan_s']} | {r['speedup']} | "
            f"{r['max_concurrent_motions']} / {r['mean_concurrent_motions']} | "
            f"{r['reason'][:120]} |")
    lines += ["", "## Families", "", "| family | built | median ratio to the planner | "
              "median speed-up | makespan ~ movers^k |", "|---|---|---|---|---|"]
    by_family = {}
    for r in rows:
        by_family.setdefault(r["family"], []).append(r)
    for family, members in by_family.items():
        ratios = [r["motion_ratio"] for r in members if r["motion_ratio"] != ""]
        speedups = [r["speedup"] for r in members if r["speedup"] != ""]
        k = exponent(members)
        lines.append(f"| {family} | {sum(r['success'] for r in members)} of {len(members)} | "
                     f"{fmt(median(ratios))} | {fmt(median(speedups))} | "
                     f"{'' if k is None else f'{k:.2f}'} |")
    lines += ["", "## Quality goals", ""]
    failed = [r["case"] for r in rows if not r["success"]]
    lines.append(goal("every case built", not failed,
                      "all" if not failed else "not built: " + ", ".join(failed)))
    random_ratios = [r["motion_ratio"] for r in by_family.get("random", [])
                     if r["motion_ratio"] != ""]
    worst = max(random_ratios) if random_ratios else None
    lines.append(goal("motions within 1.3x of the planner (random)",
                      worst is not None and worst <= 1.3,
                      "no planner figures" if worst is None else f"worst {worst:.2f}x"))
    arch = [r["speedup"] for r in by_family.get("arch", []) if r["speedup"] != ""]
    lines.append(goal("speed-up over one motion at a time >= 3 (arch)",
                      bool(arch) and min(arch) >= 3,
                      "no arch case" if not arch else f"least {min(arch):.2f}x"))
    for family in ("pyramid", "cube"):
        k = exponent(by_family.get(family, []))
        lines.append(goal(f"makespan ~ movers^k with k <= 0.5 ({family})",
                          k is not None and k <= 0.5,
                          "too few cases" if k is None else f"k = {k:.2f}"))
    return "\n".join(lines) + "\n"


def fmt(value):
    return "" if value is None else f"{value:.2f}"


def goal(what, met, figure):
    return f"- {what}: {figure}, **{'met' if met else 'not met'}**"


def plot(rows, path):
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        raise SystemExit("suite: the plot needs matplotlib (Debian: python3-matplotlib; "
                         "scripts/install-deps.sh installs it), or pass --no-plot")
    figure, axes = plt.subplots(figsize=(7, 4.5), dpi=120)
    families = sorted({r["family"] for r in rows})
    for family in families:
        built = sorted((r["movers"], r["makespan_s"]) for r in rows
                       if r["family"] == family and r["success"] and r["movers"] > 0)
        if built:
            axes.plot([m for m, _ in built], [s for _, s in built], marker="o", label=family)
        lost = [(r["movers"], r["makespan_s"]) for r in rows
                if r["family"] == family and not r["success"]]
        if lost:
            axes.scatter([m for m, _ in lost], [s for _, s in lost], marker="x", color="red")
    axes.set_xscale("log")
    axes.set_yscale("log")
    axes.set_xlabel("movers (modules not on a target cell at the start)")
    axes.set_ylabel("makespan (s of simulated time)")
    axes.set_title("Self-reconfiguration: makespan against movers (x: not built)")
    axes.grid(True, which="both", alpha=0.3)
    axes.legend()
    figure.tight_layout()
    figure.savefig(path)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--datomsim", default=os.path.join(ROOT, "build/release/bin/datomsim"))
    parser.add_argument("--suite", default=os.path.join(HERE, "suite.json"))
    parser.add_argument("--out", default="reconfiguration-results")
    parser.add_argument("--large", action="store_true", help="the large cases too")
    parser.add_argument("--family", action="append", help="only this family (repeatable)")
    parser.add_argument("--workers", type=int, default=os.cpu_count() or 1)
    parser.add_argument("--no-plot", action="store_true")
    parser.add_argument("--param", action="append", default=[], metavar="KEY=VALUE",
                        help="a parameter of the distributed program (repeatable)")
    options = parser.parse_args()
    if not os.access(options.datomsim, os.X_OK):
        raise SystemExit(f"suite: no datomsim at {options.datomsim} (build it, or --datomsim)")
    for pair in options.param:
        if "=" not in pair or pair.startswith("="):
            raise SystemExit(f"suite: --param {pair}: expected KEY=VALUE")
    if options.workers < 1:
        raise SystemExit(f"suite: --workers {options.workers}: 1 or more")
    suite = read_json(options.suite)
    known = {f["family"] for f in suite["families"]}
    for family in options.family or []:
        if family not in known:
            raise SystemExit(f"suite: --family {family}: not in {{{','.join(sorted(known))}}}")
    os.makedirs(os.path.join(options.out, "cases"), exist_ok=True)
    os.makedirs(os.path.join(options.out, "runs"), exist_ok=True)
    planner = has_planner(options.datomsim)
    version = subprocess.run([options.datomsim, "--version"], capture_output=True,
                             text=True).stdout.strip()
    todo = list(cases(suite, options.family, options.large))
    with concurrent.futures.ThreadPoolExecutor(options.workers) as pool:
        futures = [pool.submit(run_case, options.datomsim, options.out, planner, options.param,
                               *case)
                   for case in todo]
        rows = []
        for future, case in zip(futures, todo):
            rows.append(future.result())
            r = rows[-1]
            print(f"{r['case']}: {'built' if r['success'] else 'NOT built'}, {r['motions']} "
                  f"motions, {r['makespan_s']} s", file=sys.stderr, flush=True)
    results = os.path.join(options.out, "results.csv")
    with open(results + ".partial", "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=COLUMNS)
        writer.writeheader()
        writer.writerows(rows)
    os.replace(results + ".partial", results)
    with open(os.path.join(options.out, "summary.md"), "w") as f:
        f.write(summary(suite, rows, planner, version, options.param))
    if not options.no_plot:
        plot(rows, os.path.join(options.out, "makespan.png"))
    print(f"wrote {results}, summary.md{'' if options.no_plot else ', makespan.png'} in "
          f"{options.out}")


if __name__ == "__main__":
    main()
