"""Sweeps: every combination of a spec's scenes, programs, parameters and seeds, one run each,
one row each (docs/python.md, "Sweeps").

    python3 -m datomsim.sweeps SPEC.json -o results.csv [--workers N] [--scheduler ADDRESS]
    datomsim sweep SPEC.json -o results.csv ...          (the same, from the command line)

A spec (JSON):

    {
      "scenes": [
        {"generate": "reshape", "case": "random", "modules": [10, 20, 40], "floor": [12, 12]},
        {"file": "scenes/paper-arch-hole1.json"}
      ],
      "programs": [{"program": "reconfigure"}],
      "parameters": {"max_motions": [null, 1]},
      "seeds": {"from": 1, "count": 20}
    }

A list is a choice to sweep over, except for a cell (``size``, ``floor``, ``grid``, ``goal``,
``start``, ``root``, ``origin``), where a list of numbers is one cell and a list of cells the
choice. A generator's ``seed``, when the spec gives none, is the run's: each seed is then a new
scene and a new run. Runs go to all cores by default, or to a Dask cluster (``--scheduler``);
the rows are the same either way, but for their order and their wall time. A sweep that is
stopped and started again skips the cases its CSV file already holds.
"""

from __future__ import annotations

import argparse
import csv
import hashlib
import importlib.util
import itertools
import json
import os
import stat
import sys
import time
from concurrent.futures import ProcessPoolExecutor, as_completed
from typing import Any, Iterable, Iterator, Optional

CELL_KEYS = {"size", "floor", "grid", "goal", "start", "root", "origin"}
GENERATORS = {"box", "arch", "random", "reshape"}
# The most runs a spec may make: counted before any case is built (docs/limits.md).
MAX_CASES = 1_000_000
LARGEST_SEED = 2**64 - 1


def _integer(value: Any) -> bool:
    return isinstance(value, int) and not isinstance(value, bool)


def _number(value: Any) -> bool:
    return isinstance(value, (int, float)) and not isinstance(value, bool)


def _scalar(value: Any) -> bool:
    return isinstance(value, (str, int, float))


# run()'s keywords a spec may give, each with what its value must be (None is the default).
# The seed is the spec's "seeds"; a trace has no place in a row.
RUN_KEYWORDS = {
    **{key: (lambda v: _is_cell(v), "a cell x,y,z") for key in ("goal", "start", "root")},
    **{key: (lambda v: isinstance(v, str), "a string")
       for key in ("rules", "module", "rolling", "target")},
    **{key: (lambda v: isinstance(v, bool), "true or false")
       for key in ("attachment", "connectivity")},
    **{key: (_number, "a number")
       for key in ("delay_ms", "jitter_ms", "timeout", "until", "radius", "thickness",
                   "density", "solid_fraction", "young_modulus", "poisson_ratio",
                   "latch_force", "latch_moment")},
    **{key: (_integer, "an integer") for key in ("max_motions", "load_region")},
    "params": (lambda v: isinstance(v, dict) and all(isinstance(k, str) and _scalar(x)
                                                     for k, x in v.items()),
               "an object of numbers, strings and booleans"),
    "gravity": (lambda v: isinstance(v, (bool, str)), "true, false, \"on\" or \"off\""),
}
# What every row has after its inputs, in this order.
OUTCOME_COLUMNS = [
    "success",
    "reason",
    "modules",
    "motions",
    "makespan_s",
    "messages",
    "max_concurrent_motions",
    "mean_concurrent_motions",
    "events",
    "sim_time_s",
    "wall_s",
]


class SpecError(ValueError):
    """A spec that cannot be swept: the message names the key and the value."""


def _is_cell(value: Any) -> bool:
    return isinstance(value, str) or (
        isinstance(value, (list, tuple)) and 2 <= len(value) <= 3
        and all(isinstance(v, int) and not isinstance(v, bool) for v in value)
    )


def _choices(key: str, value: Any) -> list:
    """The values a spec entry sweeps over."""
    if key in CELL_KEYS:
        if _is_cell(value):
            return [value]
        if isinstance(value, list) and value and all(_is_cell(v) for v in value):
            return list(value)
        raise SpecError(f"{key}: {json.dumps(value)} is neither a cell (x,y,z) nor a list of cells")
    if isinstance(value, list):
        if not value:
            raise SpecError(f"{key}: an empty list sweeps over nothing")
        return list(value)
    return [value]


def _expand(entry: dict) -> list[dict]:
    """Every combination of an entry's choices, keys in the entry's order."""
    keys = list(entry)
    return [dict(zip(keys, combination))
            for combination in itertools.product(*(_choices(k, entry[k]) for k in keys))]


def _count(entry: dict) -> int:
    """How many combinations _expand would make, without making them."""
    count = 1
    for key, value in entry.items():
        count *= len(_choices(key, value))
    return count


def _check_run_keywords(where: str, entry: dict, skip: tuple = ()) -> None:
    """Refuses a key run() does not take and a value not of its type, before anything runs."""
    for key, value in entry.items():
        if key in skip:
            continue
        if key not in RUN_KEYWORDS:
            raise SpecError(f"{where}: unknown key {key} (known: {', '.join(sorted(RUN_KEYWORDS))}"
                            "; the seed is the spec's \"seeds\")")
        accepts, expected = RUN_KEYWORDS[key]
        for choice in _choices(key, value):
            if choice is not None and not accepts(choice):
                raise SpecError(f"{where}: {key} {json.dumps(choice)}: {expected}")


def _check_generator_keys(entry: dict) -> None:
    import inspect

    import datomsim

    function = {"box": datomsim.box, "arch": datomsim.arch, "random": datomsim.random_scene,
                "reshape": datomsim.reshape}[entry["generate"]]
    taken = set(inspect.signature(function).parameters)
    for key in entry:
        if key != "generate" and key not in taken:
            raise SpecError(f"scenes: generate {entry['generate']} takes no key {key} (it takes "
                            f"{', '.join(sorted(taken))})")


def _seeds(spec: dict) -> list[int]:
    seeds = spec.get("seeds", [1])
    if isinstance(seeds, dict):
        unknown = set(seeds) - {"from", "count"}
        start = seeds.get("from", 1)
        count = seeds.get("count")
        if unknown or not _integer(count) or not _integer(start):
            raise SpecError(f'seeds: {json.dumps(seeds)}: write {{"from": 1, "count": N}} or a list')
        if count < 1 or count > MAX_CASES:
            raise SpecError(f"seeds: count {count}: 1 to {MAX_CASES:,}")
        if start < 0 or start + count - 1 > LARGEST_SEED:
            raise SpecError(f"seeds: from {start}: seeds are 0 to {LARGEST_SEED}")
        return list(range(start, start + count))
    if _integer(seeds) and 0 <= seeds <= LARGEST_SEED:
        return [seeds]
    if isinstance(seeds, list) and seeds and all(_integer(s) and 0 <= s <= LARGEST_SEED
                                                 for s in seeds):
        return seeds
    raise SpecError(f"seeds: {json.dumps(seeds)}: a list of integers 0 to {LARGEST_SEED}, or "
                    "from/count")


def cases(spec: dict) -> list[dict]:
    """Every case of a spec: {"scene": {...}, "program": {...}, "parameters": {...}, "seed": n,
    "case": id}, in the spec's order."""
    if not isinstance(spec, dict):
        raise SpecError("a spec is a JSON object with scenes, programs, parameters and seeds")
    unknown = set(spec) - {"scenes", "programs", "parameters", "seeds"}
    if unknown:
        raise SpecError(f"unknown key(s) {', '.join(sorted(unknown))} (scenes, programs, "
                        "parameters, seeds)")
    for key in ("scenes", "programs"):
        if not isinstance(spec.get(key), list) or not spec[key]:
            raise SpecError(f"{key}: a non-empty list is needed")
    scene_count = 0
    for entry in spec["scenes"]:
        if not isinstance(entry, dict) or ("file" in entry) == ("generate" in entry):
            raise SpecError(f"scenes: {json.dumps(entry)} needs one of \"file\" or \"generate\"")
        if "generate" in entry:
            if not isinstance(entry["generate"], str) or entry["generate"] not in GENERATORS:
                raise SpecError(f"scenes: generate {json.dumps(entry['generate'])} is not one of "
                                f"{', '.join(sorted(GENERATORS))}")
            _check_generator_keys(entry)
        elif len(entry) > 1 or not isinstance(entry["file"], str):
            raise SpecError(f"scenes: {json.dumps(entry)}: a file is {{\"file\": PATH}} alone")
        scene_count += _count(entry)
    program_count = 0
    for entry in spec["programs"]:
        if not isinstance(entry, dict) or "program" not in entry:
            raise SpecError(f"programs: {json.dumps(entry)} needs a \"program\"")
        for name in _choices("program", entry["program"]):
            if not isinstance(name, str):
                raise SpecError(f"programs: program {json.dumps(name)}: a string")
        _check_run_keywords("programs", entry, skip=("program",))
        program_count += _count(entry)
    chosen_parameters = spec.get("parameters", {})
    if not isinstance(chosen_parameters, dict):
        raise SpecError("parameters: an object of run()'s keywords")
    _check_run_keywords("parameters", chosen_parameters)
    seeds = _seeds(spec)
    total = scene_count * program_count * _count(chosen_parameters) * len(seeds)
    if total > MAX_CASES:
        raise SpecError(f"the spec makes {total:,} runs, more than the {MAX_CASES:,} a sweep may "
                        "hold (docs/limits.md): split it")
    scenes = [scene for entry in spec["scenes"] for scene in _expand(entry)]
    programs = [program for entry in spec["programs"] for program in _expand(entry)]
    parameters = _expand(chosen_parameters)
    found = []
    for scene, program, chosen, seed in itertools.product(scenes, programs, parameters, seeds):
        case = {"scene": scene, "program": program, "parameters": chosen, "seed": seed}
        case["case"] = hashlib.sha1(json.dumps(case, sort_keys=True).encode()).hexdigest()[:12]
        found.append(case)
    return found


def _label(scene: dict) -> str:
    if "file" in scene:
        return os.path.basename(scene["file"])
    rest = " ".join(f"{k}={_text(v)}" for k, v in scene.items() if k != "generate")
    return f"{scene['generate']} {rest}".strip()


def _text(value: Any) -> str:
    if isinstance(value, (list, tuple)):
        return ",".join(str(v) for v in value)
    return "" if value is None else str(value)


def _make_scene(scene: dict, seed: int, base: str):
    import datomsim

    options = {k: v for k, v in scene.items() if k not in ("generate", "file")}
    if "file" in scene:
        path = scene["file"]
        return datomsim.load_scene(path if os.path.isabs(path) else os.path.join(base, path))
    kind = scene["generate"]
    if kind in ("random", "reshape"):
        options.setdefault("seed", seed)
    try:
        if kind == "box":
            return datomsim.box(**options)
        if kind == "arch":
            return datomsim.arch(**options)
        if kind == "random":
            return datomsim.random_scene(**options)
        return datomsim.reshape(**options)
    except TypeError as error:  # an option the generator does not take
        raise datomsim.Error(f"generate {kind}: {error}") from None


def run_case(case: dict, base: str = ".") -> dict:
    """Runs one case; its row (inputs, outcome, metrics, wall time). A case that cannot run (a
    goal that does not fit its scene, say) is a row with success false and the reason."""
    import datomsim

    row = {"case": case["case"], "scene": _label(case["scene"]),
           "program": case["program"]["program"], "seed": case["seed"]}
    for key, value in case["scene"].items():
        if key not in ("generate", "file"):
            row[f"scene.{key}"] = _text(value)
    for key, value in case["program"].items():
        if key != "program":
            row[f"program.{key}"] = _text(value)
    for key, value in case["parameters"].items():
        row[key] = _text(value)
    started = time.perf_counter()
    try:
        scene = _make_scene(case["scene"], case["seed"], base)
        row["modules"] = len(scene)
        options = {k: v for k, v in case["program"].items() if k != "program"}
        options.update({k: v for k, v in case["parameters"].items() if v is not None})
        result = datomsim.run(scene, case["program"]["program"], seed=case["seed"], **options)
        success = result.get("success", result.get("arrived", "reason" not in result))
        row["success"] = bool(success)
        row["reason"] = result.get("reason", "")
        for key in OUTCOME_COLUMNS:
            if key in result and key not in ("success", "reason"):
                row[key] = result[key]
    except datomsim.Error as error:
        row["success"] = False
        row["reason"] = str(error)
    row["wall_s"] = round(time.perf_counter() - started, 6)
    return row


def _columns(all_cases: list[dict]) -> list[str]:
    inputs = ["case", "scene", "program", "seed"]
    for case in all_cases:
        for key in (*(f"scene.{k}" for k in case["scene"] if k not in ("generate", "file")),
                    *(f"program.{k}" for k in case["program"] if k != "program"),
                    *case["parameters"]):
            if key not in inputs:
                inputs.append(key)
    return inputs + OUTCOME_COLUMNS


def _done_cases(path: str) -> set[str]:
    if not os.path.exists(path):
        return set()
    with open(path, newline="", encoding="utf-8") as file:
        return {row["case"] for row in csv.DictReader(file) if row.get("case")}


def _progress(total: int, done: int, quiet: bool):
    """A progress bar (tqdm) on a terminal, else None."""
    if quiet or not sys.stderr.isatty():
        return None
    try:
        from tqdm import tqdm
    except ImportError:
        return None
    return tqdm(total=total, initial=done, unit="run", file=sys.stderr)


def _results(todo: list[dict], workers: Optional[int], scheduler: Optional[str],
             base: str) -> Iterator[dict]:
    if scheduler:
        from distributed import Client, as_completed as completed

        with Client(scheduler) as client:
            futures = client.map(run_case, todo, base=base, pure=False)
            for future in completed(futures):
                yield future.result()
        return
    with ProcessPoolExecutor(max_workers=workers or os.cpu_count()) as pool:
        futures = [pool.submit(run_case, case, base) for case in todo]
        for future in as_completed(futures):
            yield future.result()


def read_spec(path: str) -> Any:
    """The JSON value of a spec file; SpecError naming the file (and line) when it is not one."""
    try:
        if not stat.S_ISREG(os.stat(path).st_mode):
            raise SpecError(f"{path}: not a regular file")
        with open(path, encoding="utf-8") as file:
            return json.load(file)
    except OSError as error:
        raise SpecError(f"{path}: {error.strerror}") from None
    except json.JSONDecodeError as error:
        raise SpecError(f"{path}: line {error.lineno}: {error.msg}") from None
    except UnicodeDecodeError as error:
        raise SpecError(f"{path}: not UTF-8 text (byte {error.start}: {error.reason})") from None
    except RecursionError:
        raise SpecError(f"{path}: nested too deeply for a spec") from None
    except MemoryError:
        raise SpecError(f"{path}: too large to read") from None


def sweep(spec: Any, out: Optional[str] = None, *, workers: Optional[int] = None,
          scheduler: Optional[str] = None, base: Optional[str] = None,
          quiet: bool = True) -> list[dict]:
    """Runs every case of ``spec`` (a dict, or the path of a JSON file) and returns the rows.

    With ``out`` (a .csv file) each row is appended as it comes, and cases the file already holds
    are skipped (a sweep stopped and started again goes on); the rows returned are then the file's
    rows, old and new. ``workers``: processes on this machine (default: every core);
    ``scheduler``: the address of a Dask scheduler to run the cases on instead. Scene files are
    found relative to ``base`` (default: the spec file's folder, or the current one).
    """
    if isinstance(spec, (str, os.PathLike)):
        path = os.fspath(spec)
        spec = read_spec(path)
        base = base or os.path.dirname(os.path.abspath(path))
    base = base or os.getcwd()
    if workers is not None and (not _integer(workers) or workers < 1):
        raise SpecError(f"workers {workers!r}: a number of processes, 1 or more")
    all_cases = cases(spec)
    columns = _columns(all_cases)
    parquet = None
    if out is not None and out.endswith(".parquet"):
        # Parquet is written whole at the end; the rows go to a CSV file beside it as they come,
        # which is what a stopped sweep goes on from.
        # pandas writes Parquet through pyarrow.
        if importlib.util.find_spec("pyarrow") is None or importlib.util.find_spec("pandas") is None:
            raise SpecError(f"{out}: Parquet needs pyarrow and pandas, which are not installed "
                            "(Debian 12 has no pyarrow): write a .csv file")
        parquet, out = out, out + ".csv"
    if out is not None and not out.endswith(".csv"):
        raise SpecError(f"{out}: the results are a .csv file (or .parquet with pyarrow)")
    done = _done_cases(out) if out else set()
    todo = [case for case in all_cases if case["case"] not in done]
    rows: list[dict] = []
    bar = _progress(len(all_cases), len(all_cases) - len(todo), quiet)
    writer = None
    file = None
    created = False
    if out is not None:
        created = not os.path.exists(out)
        fresh = created or os.path.getsize(out) == 0
        if not fresh:
            with open(out, newline="", encoding="utf-8") as existing:
                header = next(csv.reader(existing), [])
            if header != columns:
                raise SpecError(f"{out} holds the rows of another spec (its columns differ): "
                                "choose another file")
        file = open(out, "a", newline="", encoding="utf-8")
        writer = csv.DictWriter(file, fieldnames=columns)
        if fresh:
            writer.writeheader()
            file.flush()
    try:
        for row in _results(todo, workers, scheduler, base):
            if writer is not None:
                writer.writerow(row)
                file.flush()
            rows.append(row)
            if bar is not None:
                bar.update()
    except Exception:
        # A sweep that fails leaves no file of its own behind; one stopped (Ctrl-C) keeps its
        # rows, to go on from.
        if file is not None:
            file.close()
            file = None
            if created:
                os.remove(out)
        raise
    finally:
        if bar is not None:
            bar.close()
        if file is not None:
            file.close()
    if out is not None:
        rows = read_rows(out)
    if parquet is not None:
        import pandas

        partial = parquet + ".partial"
        try:
            pandas.DataFrame(rows, columns=columns).to_parquet(partial, index=False)
        except BaseException:
            if os.path.exists(partial):
                os.remove(partial)
            raise
        os.replace(partial, parquet)
    return rows


def read_rows(path: str) -> list[dict]:
    """The rows of a sweep's CSV file, numbers as numbers and success as a bool."""
    def value(text: str) -> Any:
        if text in ("True", "False"):
            return text == "True"
        for kind in (int, float):
            try:
                return kind(text)
            except ValueError:
                pass
        return text

    with open(path, newline="", encoding="utf-8") as file:
        return [{k: value(v) for k, v in row.items()} for row in csv.DictReader(file)]


def main(argv: Optional[Iterable[str]] = None) -> int:
    parser = argparse.ArgumentParser(
        prog="datomsim sweep",
        description="Run every combination of a spec's scenes, programs, parameters and seeds; "
                    "one CSV row per run (docs/python.md)")
    parser.add_argument("spec", help="the sweep's spec, a JSON file")
    parser.add_argument("-o", "--out", required=True, help="the results, a .csv file (resumed "
                        "when it exists), or .parquet where pyarrow is installed")
    parser.add_argument("--workers", type=int, help="processes on this machine (default: every "
                        "core)")
    parser.add_argument("--scheduler", help="a Dask scheduler's address (tcp://host:8786) to run "
                        "the cases on")
    parser.add_argument("-q", "--quiet", action="store_true", help="no progress bar")
    arguments = parser.parse_args(list(argv) if argv is not None else None)
    if arguments.workers is not None and arguments.workers < 1:
        # The command line's message (datomsim sweep --workers).
        print(f"datomsim sweep: error: --workers: must be a finite number > 0, got "
              f"{arguments.workers}", file=sys.stderr)
        return 1
    try:
        rows = sweep(arguments.spec, arguments.out, workers=arguments.workers,
                     scheduler=arguments.scheduler, quiet=arguments.quiet)
    except (SpecError, OSError) as error:
        print(f"datomsim sweep: error: {error}", file=sys.stderr)
        return 1
    except (ValueError, TypeError, RecursionError, MemoryError) as error:
        # What the spec made happen (datomsim.Error is a ValueError): named, not a traceback.
        print(f"datomsim sweep: error: {arguments.spec}: {type(error).__name__}: {error}",
              file=sys.stderr)
        return 1
    failed = sum(1 for row in rows if not row.get("success"))
    if not arguments.quiet:
        print(f"wrote {arguments.out} ({len(rows)} runs, {len(rows) - failed} succeeded)",
              file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
