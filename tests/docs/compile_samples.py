#!/usr/bin/env python3
"""Compiles every C++ sample of a tutorial page against the public API and links it with the
library; runs the samples marked "(run)" on a generated scene.

    compile_samples.py --doc docs/writing-programs.md --compiler c++ --include include/
                       --library build/release/lib/libdatomsim.so [--flags "..."]

A sample is a ```cpp block right after a line `<!-- sample: NAME -->` (or `<!-- sample: NAME
(run) -->`). A ```cpp block without that line fails the check: every sample is compiled.
"""
import argparse
import json
import os
import re
import shlex
import subprocess
import sys
import tempfile

MARKER = re.compile(r"<!-- sample: ([a-z0-9-]+)( \(run\))? -->")


def samples(text):
    lines = text.split("\n")
    found = []
    for i, line in enumerate(lines):
        if line.strip() != "```cpp":
            continue
        marker = MARKER.fullmatch(lines[i - 1].strip()) if i > 0 else None
        if not marker:
            sys.exit(f"line {i + 1}: a ```cpp block without a <!-- sample: NAME --> line before it")
        end = lines.index("```", i + 1)
        found.append((marker.group(1), bool(marker.group(2)), "\n".join(lines[i + 1:end]) + "\n"))
    return found


def run(command, expect_ok=True):
    done = subprocess.run(command, capture_output=True, text=True)
    if (done.returncode == 0) != expect_ok:
        sys.exit(f"{' '.join(command)}: exit {done.returncode}\n{done.stdout}\n{done.stderr}")
    return done


def check_run(executable, folder):
    """The first program: the built-in flood's hop counts on a box, and a bad parameter named."""
    scene = os.path.join(folder, "box.json")
    run([executable, "generate", "box", "--size", "4,3,2", "-o", scene])
    hops = {}
    for program, root in (("hops", ["--param", "root=1,1,0"]), ("flood", ["--root", "1,1,0"])):
        out = os.path.join(folder, program + ".json")
        run([executable, "run", scene, "--program", program, *root, "--out", out])
        hops[program] = json.load(open(out))["hops"]
    assert len(hops["hops"]) == 24 and hops["hops"] == hops["flood"], hops
    refused = run([executable, "run", scene, "--program", "hops", "--param", "root=9,9,0"], False)
    expected = "parameter root of program hops: cell 9,9,0 holds no module"
    assert expected in refused.stderr, refused.stderr
    print(f"  ran: the built-in flood's {len(hops['hops'])} hop counts; an empty root refused")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--doc", required=True)
    parser.add_argument("--compiler", required=True)
    parser.add_argument("--include", required=True)
    parser.add_argument("--library", required=True)
    parser.add_argument("--flags", default="")
    args = parser.parse_args()
    found = samples(open(args.doc).read())
    if not found:
        sys.exit(f"{args.doc} has no samples")
    library_dir = os.path.dirname(os.path.abspath(args.library))
    with tempfile.TemporaryDirectory() as folder:
        for name, runs, code in found:
            source = os.path.join(folder, name + ".cpp")
            executable = os.path.join(folder, name)
            with open(source, "w") as file:
                file.write(code)
            run([args.compiler, "-std=c++20", "-Wall", "-Wextra", "-Wpedantic", "-Werror",
                 *shlex.split(args.flags), "-I", args.include, source, "-o", executable,
                 args.library, f"-Wl,-rpath,{library_dir}"])
            print(f"compiled and linked sample {name} ({code.count(chr(10))} lines)")
            if runs:
                check_run(executable, folder)
    print(f"{len(found)} samples of {args.doc}")


if __name__ == "__main__":
    main()
