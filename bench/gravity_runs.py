#!/usr/bin/env python3
"""What gravity costs a run: the same reconfiguration with `--gravity off` and `on`, timed as a
user runs it (docs/mechanics.md, "Gravity in a run").

For each case it prints the modules, the motions, the wall time of both runs, the changes the
load judge weighed and the modules it solved, and the cost of the checks per motion against the
cost of a motion's own simulation (wall time without gravity / motions). With --timeout the
runs stop at that simulated time: the early part of a long case.

    python3 bench/gravity_runs.py --datomsim build/release/bin/datomsim --out DIR
"""
import argparse
import json
import os
import subprocess
import sys
import time

# Reconfiguration cases: scenes/ files, or `generate reshape` arguments.
CASES = [
    ("arch-hole2", ["scene", "scenes/reshape-arch-hole2.json"]),
    ("line-16", ["generate", "line", "--length", "16"]),
    ("random-12x12-60", ["generate", "random", "--floor", "12,12", "--modules", "60", "--height", "4"]),
    ("pyramid-48", ["generate", "pyramid", "--side", "48", "--base", "6"]),
    ("pyramid-96", ["generate", "pyramid", "--side", "96", "--base", "12"]),
]


def run(command):
    started = time.monotonic()
    done = subprocess.run(command, capture_output=True, text=True)
    return done, time.monotonic() - started


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--datomsim", required=True)
    parser.add_argument("--out", required=True, help="folder for the scenes and outputs")
    parser.add_argument("--cases", default=",".join(name for name, _ in CASES),
                        help="comma-separated case names")
    parser.add_argument("--timeout", type=float, default=0,
                        help="simulated seconds after which each run stops (0: to the end)")
    parser.add_argument("--load-region", type=int, default=0)
    args = parser.parse_args()
    known = dict(CASES)
    names = args.cases.split(",")
    for name in names:
        if name not in known:
            sys.exit(f"gravity_runs.py: unknown case {name!r}; known: {', '.join(known)}")
    os.makedirs(args.out, exist_ok=True)
    print("| case | modules | motions off / on | wall off / on (s) | changes judged | "
          "modules per solve | checks per motion (ms) | motion's simulation (ms) |")
    print("|---|---|---|---|---|---|---|---|")
    for name in names:
        spec = known[name]
        if spec[0] == "scene":
            scene = spec[1]
        else:
            scene = os.path.join(args.out, name + ".json")
            subprocess.run([args.datomsim, "generate", "reshape", *spec[1:], "-o", scene],
                           check=True, capture_output=True)
        results = {}
        for gravity in ("off", "on"):
            out = os.path.join(args.out, f"{name}-{gravity}.json")
            command = [args.datomsim, "run", scene, "--program", "reconfigure", "--gravity", gravity,
                       "--out", out]
            if gravity == "on":
                command += ["--load-region", str(args.load_region)]
            if args.timeout > 0:
                command += ["--timeout", str(args.timeout)]
            done, seconds = run(command)
            if not os.path.exists(out):
                sys.exit(f"gravity_runs.py: {name} with gravity {gravity} wrote nothing:\n"
                         f"{done.stderr}")
            with open(out) as file:
                results[gravity] = (json.load(file), seconds)
        off, off_s = results["off"]
        on, on_s = results["on"]
        info = subprocess.run([args.datomsim, "info", scene], capture_output=True, text=True).stdout
        modules = next(line.split()[1] for line in info.splitlines() if line.startswith("modules"))
        judge = on.get("gravity", {})
        solves = max(judge.get("pieces_solved", 0), 1)
        motion_ms = 1000 * off_s / max(off["motions"], 1)
        check_ms = 1000 * max(on_s - off_s * on["motions"] / max(off["motions"], 1), 0) / max(
            on["motions"], 1)
        print(f"| {name} | {modules} | {off['motions']} / {on['motions']} | {off_s:.2f} / {on_s:.2f} | "
              f"{judge.get('changes_judged', 0)} | {judge.get('modules_solved', 0) / solves:.0f} | "
              f"{check_ms:.2f} | {motion_ms:.2f} |", flush=True)


if __name__ == "__main__":
    main()
