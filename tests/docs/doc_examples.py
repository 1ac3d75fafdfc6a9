#!/usr/bin/env python3
"""The command outputs the documentation shows, made by the commands themselves: a doc's example
cannot drift from what datomsim prints.

    doc_examples.py --datomsim BIN --check DOC.md [DOC.md ...]   fails on any example that differs
    doc_examples.py --datomsim BIN --write DOC.md [DOC.md ...]   rewrites them from the commands

An example is the fenced block right after a line

    <!-- output of: datomsim ARGUMENTS -->

ARGUMENTS are run from the repository's root in a scratch folder's company: `@NAME` in them is a
file of that folder (an output, or a scene made first by a line `<!-- scene: NAME = datomsim
ARGUMENTS -->` anywhere before). What the command prints on standard output is the example: JSON
is written compactly with long lists cut to their first entries and "...", and folded at commas to
lines of at most 100 characters; any other text stands as printed.

A ```sh block right after a line `<!-- commands: run -->` is run line by line, in a scratch folder
that sees the repository's scenes/, and each of its `datomsim` lines must succeed: the page's
commands keep working as written.
"""
import argparse
import json
import os
import re
import shlex
import subprocess
import sys
import tempfile

EXAMPLE = re.compile(r"<!-- output of: datomsim (.+) -->")
COMMANDS = "<!-- commands: run -->"
SCENE = re.compile(r"<!-- scene: (\w[\w.-]*) = datomsim (.+) -->")
ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
KEEP = 2      # entries a long list keeps
LONG = 6      # a list longer than this is long (a cell and its value, [x,y,z,d], is not)
WIDTH = 100   # the longest line of an example
ELLIPSIS = "\u2026elided\u2026"


def cut(value):
    """Long lists cut to their first KEEP entries and an ellipsis, all the way down."""
    if isinstance(value, list):
        kept = [cut(v) for v in value[:KEEP]]
        return kept + [ELLIPSIS] if len(value) > LONG else kept + [cut(v) for v in value[KEEP:]]
    if isinstance(value, dict):
        return {k: cut(v) for k, v in value.items()}
    return value


def fold(text):
    """Compact JSON folded after commas outside strings, no line longer than WIDTH."""
    lines, line, depth, in_string, escaped = [], "", 0, False, False
    pieces, start = [], 0
    for i, c in enumerate(text):
        if in_string:
            if escaped:
                escaped = False
            elif c == "\\":
                escaped = True
            elif c == '"':
                in_string = False
            continue
        if c == '"':
            in_string = True
        elif c == ",":
            pieces.append(text[start:i + 1])
            start = i + 1
    pieces.append(text[start:])
    for piece in pieces:
        if line and len(line) + len(piece) > WIDTH:
            lines.append(line)
            line = " " + piece
        else:
            line += piece
    lines.append(line)
    return "\n".join(lines)


def render(output):
    try:
        value = json.loads(output)
    except ValueError:
        return output.rstrip("\n")
    text = json.dumps(cut(value), separators=(",", ":"), ensure_ascii=False)
    return fold(text.replace(f'"{ELLIPSIS}"', "..."))


def run(datomsim, arguments, scratch):
    words = [word.replace("@", scratch + os.sep, 1) if word.startswith("@") else word
             for word in shlex.split(arguments)]
    done = subprocess.run([datomsim, "--quiet"] + words, cwd=ROOT, capture_output=True, text=True)
    # A command that fails on purpose (a failed run exits 1) still shows its output.
    if done.returncode not in (0, 1) or not done.stdout:
        sys.exit(f"doc_examples: `datomsim {arguments}` gave status {done.returncode}:\n"
                 f"{done.stderr}")
    return done.stdout


def run_commands(path, at, lines, datomsim, scratch):
    """Runs the sh block after line `at`; the commands that failed, as differences."""
    if at >= len(lines) or lines[at] != "```sh":
        sys.exit(f"doc_examples: {path}:{at}: the commands have no ```sh block after them")
    if not os.path.exists(os.path.join(scratch, "scenes")):
        os.symlink(os.path.join(ROOT, "scenes"), os.path.join(scratch, "scenes"))
    failed = []
    for k in range(at + 1, len(lines)):
        command = lines[k].strip()
        if command == "```":
            break
        if not command.startswith("datomsim "):
            sys.exit(f"doc_examples: {path}:{k + 1}: not a datomsim command: {command}")
        done = subprocess.run([datomsim] + shlex.split(command)[1:], cwd=scratch,
                              capture_output=True, text=True)
        if done.returncode != 0:
            failed.append(f"{path}:{k + 1}: `{command}` failed with status {done.returncode}:\n"
                          f"{done.stderr.strip()}\n")
    return failed


def process(path, datomsim, write):
    with open(path) as f:
        lines = f.read().split("\n")
    scratch = tempfile.mkdtemp(prefix="datomsim-doc-")
    out, i, differences, examples = [], 0, [], 0
    while i < len(lines):
        line = lines[i]
        out.append(line)
        scene = SCENE.fullmatch(line.strip())
        if scene:
            words = shlex.split(scene.group(2)) + ["-o", os.path.join(scratch, scene.group(1))]
            done = subprocess.run([datomsim, "--quiet"] + words, cwd=ROOT, capture_output=True,
                                  text=True)
            if done.returncode != 0:
                sys.exit(f"doc_examples: {path}: making {scene.group(1)} failed:\n{done.stderr}")
        if line.strip() == COMMANDS:
            examples += 1
            differences += run_commands(path, i + 1, lines, datomsim, scratch)
        example = EXAMPLE.fullmatch(line.strip())
        if example:
            if i + 1 >= len(lines) or not lines[i + 1].startswith("```"):
                sys.exit(f"doc_examples: {path}:{i + 1}: the example has no fenced block after it")
            end = i + 2
            while end < len(lines) and lines[end] != "```":
                end += 1
            shown = "\n".join(lines[i + 2:end])
            made = render(run(datomsim, example.group(1), scratch))
            examples += 1
            if shown != made:
                differences.append(f"{path}:{i + 1}: the output of `datomsim {example.group(1)}` "
                                   f"is now:\n{made}\nthe page shows:\n{shown}\n")
            out.append(lines[i + 1])
            out.extend(made.split("\n"))
            out.append("```")
            i = end + 1
            continue
        i += 1
    if write:
        with open(path, "w") as f:
            f.write("\n".join(out))
        print(f"doc_examples: {path}: {examples} examples written")
        return 0
    for difference in differences:
        print(difference)
    if differences:
        print(f"doc_examples: {len(differences)} differences in {path}'s {examples} examples; "
              "rewrite the outputs with tests/docs/doc_examples.py --write, fix the commands")
        return 1
    if examples == 0:
        print(f"doc_examples: {path} has no example")
        return 1
    print(f"doc_examples: {path}: its {examples} examples are what datomsim does")
    return 0


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--datomsim", required=True)
    mode = parser.add_mutually_exclusive_group(required=True)
    mode.add_argument("--check", action="store_true")
    mode.add_argument("--write", action="store_true")
    parser.add_argument("docs", nargs="+")
    args = parser.parse_args()
    status = 0
    for doc in args.docs:
        status |= process(doc, os.path.abspath(args.datomsim), args.write)
    sys.exit(status)


if __name__ == "__main__":
    main()
