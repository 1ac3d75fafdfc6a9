#!/usr/bin/env python3
"""The reconfiguration suite's runner on its smallest family, twice: every case built, every
column filled as documented, the summary's goals judged, and the same rows both times but for the
wall time (the runs are seeded).

    reconfiguration_suite_test.py --datomsim BIN
"""
import argparse
import csv
import os
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
RUNNER = os.path.join(ROOT, "bench", "reconfiguration", "run_suite.py")


def run_suite(datomsim, out):
    done = subprocess.run([sys.executable, RUNNER, "--datomsim", datomsim, "--family", "line",
                           "--no-plot", "--workers", "2", "--out", out],
                          capture_output=True, text=True)
    if done.returncode != 0:
        sys.exit(f"the suite failed: {done.stderr}")
    with open(os.path.join(out, "results.csv")) as f:
        rows = list(csv.DictReader(f))
    with open(os.path.join(out, "summary.md")) as f:
        return rows, f.read()


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--datomsim", required=True)
    datomsim = parser.parse_args().datomsim
    problems = []
    with tempfile.TemporaryDirectory() as scratch:
        rows, summary = run_suite(datomsim, os.path.join(scratch, "a"))
        again, _ = run_suite(datomsim, os.path.join(scratch, "b"))
    if [r["case"] for r in rows] != ["line-length-8", "line-length-16", "line-length-32"]:
        problems.append(f"cases: {[r['case'] for r in rows]}")
    for row in rows:
        if row["success"] != "True" or row["sequential_success"] != "True":
            problems.append(f"{row['case']} not built: {row['reason']}")
        movers, motions = int(row["movers"]), int(row["motions"])
        if not 0 < movers <= int(row["modules"]) or motions < movers:
            problems.append(f"{row['case']}: {movers} movers, {motions} motions")
        if float(row["speedup"]) < 1 or int(row["max_concurrent_motions"]) < 1:
            problems.append(f"{row['case']}: speed-up {row['speedup']}")
    for first, second in zip(rows, again):
        first.pop("wall_s")
        second.pop("wall_s")
        if first != second:
            problems.append(f"{first['case']} differs between two runs: {first} {second}")
    if "- every case built: all, **met**" not in summary:
        problems.append("the summary does not judge the first goal:\n" + summary)
    if problems:
        sys.exit("\n".join(problems))
    print(f"{len(rows)} cases built, the same twice")


if __name__ == "__main__":
    main()
