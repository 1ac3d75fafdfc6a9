#!/usr/bin/env python3
"""Many random reconfiguration cases, to find the ones that are not built.

    bench/reconfiguration/stress.py --cases N [--seed S] [--movers LO,HI] [--heights LO,HI]
                                    [--families F,...] [--spread uniform|log]
                                    [--range FROM,TO] [--workers W] [--out DIR]
                                    [--param KEY=VALUE ...]

Case i draws, from a stream seeded by S, a family (in turn) and its case:

- mound: a number of movers in [LO, HI], a floor about 2.2 cells per mover wide and a bit more,
  a target height in the --heights range and a case seed: `generate reshape random ... --height H`;
- flat: the same with the default height (the target mostly on the slab's top);
- pyramid: a base of 2 to 13 (about 5 to 850 movers) on a floor about 8 bases wide;
- cube: an edge of 2 to 9 (8 to 650 movers) on a floor about 9 edges wide.

`--spread log` draws the movers and the sizes log-uniformly (as many small cases as large ones),
`uniform` (the default) uniformly. Each case is generated and run with `run --program
reconfigure --seed R` (R drawn too, and the `--param`s given, such as `claims=1`); it is one CSV row in DIR/stress.csv (family, generate
arguments, run seed, movers, built or not, motions, makespan, wall time, the reason), written as
the cases end (DIR/stress.csv.partial meanwhile); the cases not built are printed with the
command that makes them again, and their scene and run JSON stay in DIR/failed/. The same
arguments give the same cases; `--range FROM,TO` runs only cases FROM to TO-1 of them (to share
one draw between machines, or finish a run that was stopped).
"""
import argparse
import concurrent.futures
import csv
import json
import math
import os
import random
import subprocess
import sys
import tempfile
import threading
import time

FAMILIES = ("mound", "flat", "pyramid", "cube")
COLUMNS = ["case", "family", "generate", "run_seed", "modules", "movers", "success", "motions", "makespan_s",
           "wall_s", "reason"]
ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def pair(text):
    low, high = (int(v) for v in text.split(","))
    if not 1 <= low <= high:
        raise argparse.ArgumentTypeError(f"{text}: LO,HI with 1 <= LO <= HI")
    return low, high


def index_range(text):
    try:
        first, last = (int(v) for v in text.split(","))
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text}: FROM,TO, two case numbers") from None
    return first, last


def draw_size(stream, low, high, spread):
    if spread == "log":
        return int(round(math.exp(stream.uniform(math.log(low), math.log(high)))))
    return stream.randint(low, high)


def draw(stream, family, movers, heights, spread):
    """The `generate reshape` arguments of one case of the family."""
    if family in ("mound", "flat"):
        count = draw_size(stream, *movers, spread)
        side = max(12, int((2.2 * count) ** 0.5) + 2 + stream.randint(0, 6))
        height = stream.randint(*heights)
        arguments = ["random", "--floor", f"{side},{side}", "--modules", str(count)]
        if family == "mound":
            arguments += ["--height", str(height)]
        return arguments + ["--seed", str(stream.randint(1, 10**6))]
    if family == "pyramid":
        base = draw_size(stream, 2, 13, spread)
        return ["pyramid", "--side", str(max(16, 8 * base + stream.randint(0, 8))),
                "--base", str(base)]
    edge = draw_size(stream, 2, 9, spread)
    return ["cube", "--side", str(max(16, 9 * edge + stream.randint(0, 8))), "--base", str(edge)]


def run_case(datomsim, folder, kept, params, index, family, arguments, seed):
    scene = os.path.join(folder, f"case{index}.json")
    out = os.path.join(folder, f"run{index}.json")
    made = subprocess.run([datomsim, "generate", "reshape", *arguments, "-o", scene],
                          capture_output=True, text=True)
    if made.returncode != 0:
        raise SystemExit(f"stress: case {index}: {made.stderr.strip()}")
    info = json.loads(subprocess.run([datomsim, "info", scene, "--json"], capture_output=True,
                                     text=True, check=True).stdout)
    start = time.monotonic()
    given = [word for pair in params for word in ("--param", pair)]
    subprocess.run([datomsim, "run", scene, "--program", "reconfigure", "--seed", str(seed),
                    "--out", out, *given],
                   capture_output=True)
    wall = time.monotonic() - start
    result = json.load(open(out))
    for path in (scene, out):
        if result["success"]:
            os.remove(path)
        else:
            os.replace(path, os.path.join(kept, os.path.basename(path)))
    return {"case": index, "family": family, "generate": " ".join(arguments), "run_seed": seed,
            "modules": info["modules"], "movers": info["modules"] - info["targets"][0]["filled"],
            "success": result["success"], "motions": result["motions"],
            "makespan_s": round(result["makespan_s"], 3), "wall_s": round(wall, 1),
            "reason": result.get("reason", "")}


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--datomsim", default=os.path.join(ROOT, "build/release/bin/datomsim"))
    parser.add_argument("--cases", type=int, required=True)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--movers", type=pair, default=(40, 400))
    parser.add_argument("--heights", type=pair, default=(3, 12))
    parser.add_argument("--families", default="mound",
                        type=lambda text: text.split(","))
    parser.add_argument("--spread", choices=("uniform", "log"), default="uniform")
    parser.add_argument("--range", type=index_range, dest="case_range")
    parser.add_argument("--workers", type=int, default=os.cpu_count() or 1)
    parser.add_argument("--out", default="stress-results")
    parser.add_argument("--param", action="append", default=[], metavar="KEY=VALUE",
                        help="a parameter of the program (repeatable)")
    options = parser.parse_args()
    if options.cases < 1 or options.workers < 1:
        raise SystemExit("stress: --cases and --workers are 1 or more")
    for given in options.param:
        if "=" not in given or given.startswith("="):
            raise SystemExit(f"stress: --param {given}: expected KEY=VALUE")
    unknown = set(options.families) - set(FAMILIES)
    if unknown:
        raise SystemExit(f"stress: unknown families {sorted(unknown)}: choose among {FAMILIES}")
    stream = random.Random(options.seed)
    todo = []
    for index in range(options.cases):
        family = options.families[index % len(options.families)]
        arguments = draw(stream, family, options.movers, options.heights, options.spread)
        todo.append((index, family, arguments, stream.randint(1, 10**6)))
    if options.case_range:
        first, last = options.case_range
        if not 0 <= first < last <= options.cases:
            raise SystemExit(f"stress: --range {first},{last}: 0 <= FROM < TO <= --cases")
        todo = todo[first:last]
    os.makedirs(options.out, exist_ok=True)
    path = os.path.join(options.out, "stress.csv")
    kept = os.path.join(options.out, "failed")
    os.makedirs(kept, exist_ok=True)
    rows, lock = [], threading.Lock()
    with open(path + ".partial", "w", newline="") as progress, \
            tempfile.TemporaryDirectory() as scratch, \
            concurrent.futures.ThreadPoolExecutor(options.workers) as pool:
        writer = csv.DictWriter(progress, fieldnames=COLUMNS)
        writer.writeheader()

        def one(job):
            row = run_case(options.datomsim, scratch, kept, options.param, *job)
            with lock:
                rows.append(row)
                writer.writerow(row)
                progress.flush()

        list(pool.map(one, todo))
    rows.sort(key=lambda r: r["case"])
    with open(path + ".partial", "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=COLUMNS)
        writer.writeheader()
        writer.writerows(rows)
    os.replace(path + ".partial", path)
    lost = [r for r in rows if not r["success"]]
    params = "".join(f" --param {given}" for given in options.param)
    for r in lost:
        print(f"not built: datomsim generate reshape {r['generate']} -o c.json && "
              f"datomsim run c.json --program reconfigure --seed {r['run_seed']}{params}  "
              f"# {r['reason'][:160]}")
    print(f"{len(rows) - len(lost)} of {len(rows)} built; wrote {path}")
    sys.exit(1 if lost else 0)


if __name__ == "__main__":
    main()
