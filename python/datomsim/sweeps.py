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
import importlib.util
import os
import sys
import time
from concurrent.futures import ProcessPoolExecutor, as_completed
from typing import Any, Iterable, Iterator, Optional

from .sweep_spec import SpecError, cases, is_integer, read_spec

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
    if out is not None:
        if not isinstance(out, (str, os.PathLike)):
            raise SpecError(f"out {out!r}: a path to a .csv file")
        out = os.fspath(out)
    if workers is not None and (not is_integer(workers) or workers < 1):
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
