#!/usr/bin/env python3
"""The outputs of the runs that matter most, kept as SHA-256 digests: a change to the simulator that
claims to keep its behaviour must keep every one of these bytes.

    golden_runs.py --datomsim BIN --check tests/golden/runs.sha256    fails on any digest that differs
    golden_runs.py --datomsim BIN --write tests/golden/runs.sha256    records them anew

The runs: the paper's experiment (`demo --no-video`: the distance maps, Algorithm 1 on both arch
scenes, the arch built by self-reconfiguration and its one-motion-at-a-time baseline), the
distributed gradient and the flood on the paper's scene, the walkers, reconfigurations of the heap
case by Datoms and by 3D Catoms, a random reconfiguration case with many motions at once, and the
outputs of reach, moves and verify for both module kinds. Each output file is digested as written;
a run whose command fails is reported with its message.

Rewrite the digests only for a change meant to alter behaviour, and say so in its commit.
"""
import argparse
import hashlib
import os
import shutil
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SCENES = os.path.join(ROOT, "scenes")

# (name, arguments, outputs): `@NAME` in arguments is a file of the scratch folder; the outputs
# are digested in the order given. A name starting with "stdout:" is what the command prints.
RUNS = [
    ("demo", ["demo", "--no-video", "-o", "@demo"],
     ["demo/summary.json", "demo/arch-hole2-distances.svg", "demo/arch-hole1-distances.svg",
      "demo/arch-hole2-trace.jsonl", "demo/arch-hole2-run.json",
      "demo/arch-hole1-trace.jsonl", "demo/arch-hole1-run.json",
      "demo/arch-build-trace.jsonl", "demo/arch-build-run.json"]),
    ("gradient", ["run", "scenes/paper-arch-hole2.json", "--program", "gradient",
                  "--goal", "6,5,2", "--seed", "2", "--jitter-ms", "3",
                  "--trace", "@gradient.jsonl", "--out", "@gradient.json"],
     ["gradient.jsonl", "gradient.json"]),
    ("follow-gradient", ["run", "scenes/paper-arch-hole1.json", "--program",
                         "follow-gradient", "--goal", "6,5,2", "--start", "0,0,2", "--seed", "3",
                         "--jitter-ms", "5", "--trace", "@follow.jsonl", "--out", "@follow.json"],
     ["follow.jsonl", "follow.json"]),
    ("flood", ["run", "scenes/paper-arch-hole2.json", "--program", "flood",
               "--root", "3,3,1", "--trace", "@flood.jsonl", "--out", "@flood.json"],
     ["flood.jsonl", "flood.json"]),
    ("walkers", ["run", "scenes/walkers.json", "--program", "walkers", "--seed", "5",
                 "--trace", "@walkers.jsonl", "--out", "@walkers.json"],
     ["walkers.jsonl", "walkers.json"]),
    ("reconfigure-heap", ["run", "scenes/reshape-heap.json", "--program", "reconfigure",
                          "--seed", "7", "--trace", "@heap.jsonl", "--out", "@heap.json"],
     ["heap.jsonl", "heap.json"]),
    ("reconfigure-heap-catoms", ["run", "scenes/reshape-heap.json", "--program",
                                 "reconfigure", "--seed", "7", "--module", "catom3d",
                                 "--trace", "@catoms.jsonl", "--out", "@catoms.json"],
     ["catoms.jsonl", "catoms.json"]),
    ("generate-random-case", ["generate", "reshape", "random", "--modules", "30",
                              "--seed", "11", "-o", "@random-case.json"],
     ["random-case.json"]),
    ("reconfigure-random", ["run", "@random-case.json", "--program", "reconfigure", "--seed", "4",
                            "--max-motions", "8", "--trace", "@random.jsonl",
                            "--out", "@random.json"],
     ["random.jsonl", "random.json"]),
    ("reach-datom", ["reach", "scenes/paper-arch-hole1.json", "--goal", "6,5,2",
                     "--start", "0,0,2", "--out", "@reach.json"],
     ["reach.json"]),
    ("reach-catom", ["reach", "scenes/paper-arch-hole1.json", "--goal", "6,5,2",
                     "--start", "0,0,2", "--module", "catom3d", "--out", "@reach-catom.json"],
     ["reach-catom.json"]),
    ("moves", ["moves", "scenes/paper-arch-hole2.json", "--at", "0,0,2", "--format", "json"],
     ["stdout:moves"]),
    ("moves-strict", ["moves", "scenes/paper-arch-hole2.json", "--at", "3,3,2",
                      "--format", "json", "--rules", "strict", "--connectivity", "on"],
     ["stdout:moves-strict"]),
    ("verify", ["verify", "scenes/paper-arch-hole2.json"], ["stdout:verify"]),
    ("verify-catom", ["verify", "scenes/paper-arch-hole2.json", "--module", "catom3d"],
     ["stdout:verify-catom"]),
]


def digests(datomsim, scratch):
    """Every output's digest, in order: a list of (name, sha256)."""
    out = []
    for name, arguments, outputs in RUNS:
        command = [datomsim, "--quiet"] + [
            a[1:] if a.startswith("@") else a for a in arguments]
        done = subprocess.run(command, cwd=scratch, capture_output=True)
        if done.returncode != 0:
            sys.exit(f"golden run '{name}' failed ({done.returncode}): "
                     f"{' '.join(command)}\n{done.stderr.decode(errors='replace')}")
        for output in outputs:
            if output.startswith("stdout:"):
                data = done.stdout
            else:
                with open(os.path.join(scratch, output), "rb") as f:
                    data = f.read()
            out.append((output, hashlib.sha256(data).hexdigest()))
    return out


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--datomsim", required=True)
    mode = parser.add_mutually_exclusive_group(required=True)
    mode.add_argument("--check", metavar="FILE")
    mode.add_argument("--write", metavar="FILE")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as scratch:
        # Scenes by a relative name: a run's description names its scene, and must not name the
        # folder the repository happens to be in.
        shutil.copytree(SCENES, os.path.join(scratch, "scenes"))
        made = digests(os.path.abspath(args.datomsim), scratch)
    lines = [f"{digest}  {name}\n" for name, digest in made]
    if args.write:
        with open(args.write, "w") as f:
            f.writelines(lines)
        print(f"wrote {args.write} ({len(lines)} digests)")
        return
    with open(args.check) as f:
        kept = f.readlines()
    if kept == lines:
        print(f"{len(lines)} outputs identical to {args.check}")
        return
    kept_by_name = {line.split()[1]: line.split()[0] for line in kept if line.strip()}
    for name, digest in made:
        if kept_by_name.get(name) != digest:
            print(f"differs: {name} (now {digest[:12]}, kept "
                  f"{(kept_by_name.get(name) or 'none')[:12]})", file=sys.stderr)
    missing = set(kept_by_name) - {name for name, _ in made}
    for name in sorted(missing):
        print(f"no longer made: {name}", file=sys.stderr)
    sys.exit(f"golden runs: outputs differ from {args.check}; rewrite it only for a change meant "
             f"to alter behaviour (--write)")


if __name__ == "__main__":
    main()
