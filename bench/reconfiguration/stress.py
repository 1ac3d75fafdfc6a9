#!/usr/bin/env python3
"""Many random reconfiguration cases, to find the ones that are not built.

    bench/reconfiguration/stress.py --cases N [--seed S] [--movers LO,HI] [--heights LO,HI]
                                    [--workers W] [--out DIR]

Case i draws, from a stream seeded by S, a number of movers in [LO, HI], a floor about 2.2 cells
per mover wide and a bit more, a target height in the --heights range and a case seed, then
generates `datomsim generate reshape random` with them and runs `run --program reconfigure`. Each
case is one CSV row in DIR/stress.csv (its generate arguments, built or not, motions, makespan,
the reason); the cases not built are printed with the command that makes them again. The same S
gives the same cases.
"""
import argparse
import concurrent.futures
import csv
import json
import os
import random
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def pair(text):
    low, high = (int(v) for v in text.split(","))
    if not 1 <= low <= high:
        raise argparse.ArgumentTypeError(f"{text}: LO,HI with 1 <= LO <= HI")
    return low, high


def draw(stream, movers, heights):
    count = stream.randint(*movers)
    side = max(12, int((2.2 * count) ** 0.5) + 2 + stream.randint(0, 6))
    return ["--floor", f"{side},{side}", "--modules", str(count), "--height",
            str(stream.randint(*heights)), "--seed", str(stream.randint(1, 10**6))]


def run_case(datomsim, folder, index, arguments):
    scene = os.path.join(folder, f"case{index}.json")
    out = os.path.join(folder, f"run{index}.json")
    made = subprocess.run([datomsim, "generate", "reshape", "random", *arguments, "-o", scene],
                          capture_output=True, text=True)
    if made.returncode != 0:
        raise SystemExit(f"stress: case {index}: {made.stderr.strip()}")
    subprocess.run([datomsim, "run", scene, "--program", "reconfigure", "--out", out],
                   capture_output=True)
    result = json.load(open(out))
    return {"case": index, "generate": " ".join(arguments), "success": result["success"],
            "motions": result["motions"], "makespan_s": round(result["makespan_s"], 3),
            "reason": result.get("reason", "")}


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--datomsim", default=os.path.join(ROOT, "build/release/bin/datomsim"))
    parser.add_argument("--cases", type=int, required=True)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--movers", type=pair, default=(40, 400))
    parser.add_argument("--heights", type=pair, default=(3, 12))
    parser.add_argument("--workers", type=int, default=os.cpu_count() or 1)
    parser.add_argument("--out", default="stress-results")
    options = parser.parse_args()
    if options.cases < 1 or options.workers < 1:
        raise SystemExit("stress: --cases and --workers are 1 or more")
    stream = random.Random(options.seed)
    todo = [draw(stream, options.movers, options.heights) for _ in range(options.cases)]
    os.makedirs(options.out, exist_ok=True)
    with tempfile.TemporaryDirectory() as scratch, \
            concurrent.futures.ThreadPoolExecutor(options.workers) as pool:
        rows = list(pool.map(lambda job: run_case(options.datomsim, scratch, *job),
                             enumerate(todo)))
    path = os.path.join(options.out, "stress.csv")
    with open(path + ".partial", "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)
    os.replace(path + ".partial", path)
    lost = [r for r in rows if not r["success"]]
    for r in lost:
        print(f"not built: datomsim generate reshape random {r['generate']} -o c.json && "
              f"datomsim run c.json --program reconfigure  # {r['reason'][:160]}")
    print(f"{len(rows) - len(lost)} of {len(rows)} built; wrote {path}")
    sys.exit(1 if lost else 0)


if __name__ == "__main__":
    main()
