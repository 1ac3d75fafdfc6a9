#!/usr/bin/env python3
"""Runs `datomsim run --program reconfigure` over generated cases and prints what it measured.

    scripts/reshape-sweep.py random [--sizes 10,20,50,100,200] [--seeds 20]
        random cases (a floor with N modules at random on it, to a random connected target of N
        cells): success rate by N, the makespan's median, and every failure's reason.
    scripts/reshape-sweep.py pyramid [--sides 32,48,64,80,100] [--seeds 1] [--sequential]
        corner blocks into pyramids: modules, movers, motions, makespan and wall time per side,
        and with --sequential the same with --max-motions 1 and the speed-up.

The tables of docs/reconfiguration.md come from these two commands. Scenes and outputs go to a
temporary folder, removed at the end unless --keep names one.
"""
import argparse
import json
import math
import os
import statistics
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BINARY = os.path.join(ROOT, "build", "release", "bin", "datomsim")


def datomsim(*arguments):
    started = time.monotonic()
    done = subprocess.run([BINARY, *arguments], capture_output=True, text=True)
    return done, time.monotonic() - started


def run(scene, out, seed, extra=()):
    """Runs one reconfiguration; the JSON it wrote (also when it failed) and the wall time."""
    done, wall = datomsim("run", scene, "--program", "reconfigure", "--seed", str(seed),
                          "--out", out, *extra)
    if done.returncode not in (0, 1) or not os.path.exists(out):
        sys.exit(f"datomsim failed on {scene}:\n{done.stderr}")
    with open(out) as file:
        return json.load(file), wall


def generate(folder, name, *arguments):
    scene = os.path.join(folder, name + ".json")
    done, _ = datomsim("generate", "reshape", *arguments, "-o", scene)
    if done.returncode != 0:
        sys.exit(f"datomsim generate reshape {' '.join(arguments)} failed:\n{done.stderr}")
    return scene


def random_cases(folder, sizes, seeds):
    print("| N | floor | built | makespan median (s) | motions median | max at once median |")
    print("|---|---|---|---|---|---|")
    failures = []
    for n in sizes:
        side = max(8, math.ceil(math.sqrt(4 * n)) + 1)  # about a quarter of the floor covered
        results = []
        for seed in range(1, seeds + 1):
            scene = generate(folder, f"random-{n}-{seed}", "random", "--floor", f"{side},{side}",
                             "--modules", str(n), "--seed", str(seed))
            result, _ = run(scene, scene + ".out", seed)
            results.append(result)
            if not result["success"]:
                failures.append((n, seed, result["reason"]))
        built = [r for r in results if r["success"]]
        median = lambda key: statistics.median(r[key] for r in built) if built else float("nan")
        print(f"| {n} | {side}x{side} | {len(built)}/{len(results)} | {median('makespan_s'):.0f} "
              f"| {median('motions'):.0f} | {median('max_concurrent_motions'):.0f} |")
    for n, seed, reason in failures:
        print(f"failed: N={n} seed={seed}: {reason[:400]}")


def pyramids(folder, sides, seeds, sequential):
    header = "| side | modules | movers | built | motions | makespan (s) | max at once | wall (s) |"
    if sequential:
        header += " sequential makespan (s) | sequential motions | speed-up |"
    print(header)
    print("|" + "---|" * (header.count("|") - 1))
    for side in sides:
        scene = generate(folder, f"pyramid-{side}", "pyramid", "--side", str(side))
        with open(scene) as file:
            cells = json.load(file)["targets"][0]["cells"]
        for seed in range(1, seeds + 1):
            result, wall = run(scene, scene + f".{seed}.out", seed)
            modules = len(result["final"])
            movers = sum(1 for cell in cells if cell[2] > 0)
            row = (f"| {side} | {modules} | {movers} | {'yes' if result['success'] else 'no'} | "
                   f"{result['motions']} | {result['makespan_s']:.0f} | "
                   f"{result['max_concurrent_motions']} | {wall:.1f} |")
            if sequential:
                one, _ = run(scene, scene + f".{seed}.one.out", seed, ("--max-motions", "1"))
                row += (f" {one['makespan_s']:.0f} | {one['motions']} | "
                        f"{one['makespan_s'] / result['makespan_s']:.1f} |")
            print(row, flush=True)
            if not result["success"]:
                print(f"failed: side={side} seed={seed}: {result['reason'][:400]}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("kind", choices=["random", "pyramid"])
    parser.add_argument("--sizes", default="10,20,50,100,200")
    parser.add_argument("--sides", default="32,48,64,80,100")
    parser.add_argument("--seeds", type=int, default=None)
    parser.add_argument("--sequential", action="store_true")
    parser.add_argument("--keep", help="a folder to keep the scenes and outputs in")
    args = parser.parse_args()
    if not os.access(BINARY, os.X_OK):
        sys.exit(f"{BINARY} is missing: build first (scripts/build.sh)")
    with tempfile.TemporaryDirectory() as temporary:
        folder = args.keep or temporary
        os.makedirs(folder, exist_ok=True)
        if args.kind == "random":
            random_cases(folder, [int(n) for n in args.sizes.split(",")], args.seeds or 20)
        else:
            pyramids(folder, [int(s) for s in args.sides.split(",")], args.seeds or 1,
                     args.sequential)


if __name__ == "__main__":
    main()
