"""A sweep's spec: its JSON read, every key and value checked, its runs counted and then made,
before anything runs (docs/python.md, "Sweeps"; docs/limits.md). datomsim.sweeps runs them."""

from __future__ import annotations

import hashlib
import itertools
import json
import os
import stat
from typing import Any


CELL_KEYS = {"size", "floor", "grid", "goal", "start", "root", "origin"}
GENERATORS = {"box", "arch", "random", "reshape"}
# The most runs a spec may make: counted before any case is built (docs/limits.md).
MAX_CASES = 1_000_000
LARGEST_SEED = 2**64 - 1


def is_integer(value: Any) -> bool:
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
    **{key: (is_integer, "an integer") for key in ("max_motions", "load_region")},
    "params": (lambda v: isinstance(v, dict) and all(isinstance(k, str) and _scalar(x)
                                                     for k, x in v.items()),
               "an object of numbers, strings and booleans"),
    "gravity": (lambda v: isinstance(v, (bool, str)), "true, false, \"on\" or \"off\""),
}


class SpecError(ValueError):
    """A spec that cannot be swept: the message names the key and the value."""


def _check_json_values(spec: Any) -> None:
    """Refuses a spec given from Python that holds what no JSON file could (an object, a set,
    a key that is not a string), naming where: the messages and the cases' ids are JSON."""
    pending = [("spec", spec)]
    while pending:
        where, value = pending.pop()
        if isinstance(value, dict):
            for key, item in value.items():
                if not isinstance(key, str):
                    raise SpecError(f"{where}: key {key!r} is not a string (a spec is JSON)")
                pending.append((f"{where}.{key}", item))
        elif isinstance(value, (list, tuple)):
            pending.extend((f"{where}[{index}]", item) for index, item in enumerate(value))
        elif value is not None and not isinstance(value, (str, int, float, bool)):
            raise SpecError(f"{where}: a {type(value).__name__} is not a JSON value (a spec holds "
                            "objects, lists, strings, numbers, booleans and null)")


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
        if unknown or not is_integer(count) or not is_integer(start):
            raise SpecError(f'seeds: {json.dumps(seeds)}: write {{"from": 1, "count": N}} or a list')
        if count < 1 or count > MAX_CASES:
            raise SpecError(f"seeds: count {count}: 1 to {MAX_CASES:,}")
        if start < 0 or start + count - 1 > LARGEST_SEED:
            raise SpecError(f"seeds: from {start}: seeds are 0 to {LARGEST_SEED}")
        return list(range(start, start + count))
    if is_integer(seeds) and 0 <= seeds <= LARGEST_SEED:
        return [seeds]
    if isinstance(seeds, list) and seeds and all(is_integer(s) and 0 <= s <= LARGEST_SEED
                                                 for s in seeds):
        return seeds
    raise SpecError(f"seeds: {json.dumps(seeds)}: a list of integers 0 to {LARGEST_SEED}, or "
                    "from/count")


def cases(spec: dict) -> list[dict]:
    """Every case of a spec: {"scene": {...}, "program": {...}, "parameters": {...}, "seed": n,
    "case": id}, in the spec's order."""
    if not isinstance(spec, dict):
        raise SpecError("a spec is a JSON object with scenes, programs, parameters and seeds")
    _check_json_values(spec)
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
