"""Hypothesis over every public function of the package (docs/limits.md, "Fuzzing"): any value of
any type in any argument gives a result or a refusal (datomsim.Error, TypeError or ValueError)
with a message, never a signal, another exception nor pybind11's "Unable to cast".

The test suite runs a short, deterministic pass (derandomize: the same examples every time);
`scripts/fuzz.sh` runs a longer one (DATOMSIM_FUZZ_EXAMPLES examples per function, drawn afresh
unless DATOMSIM_FUZZ_SEED is given).
"""

import os

import numpy as np
import pytest
from hypothesis import HealthCheck, given, seed, settings
from hypothesis import strategies as st

import datomsim
from datomsim import sweeps

EXAMPLES = int(os.environ.get("DATOMSIM_FUZZ_EXAMPLES", "60"))
SEED = os.environ.get("DATOMSIM_FUZZ_SEED")
FUZZ = settings(max_examples=EXAMPLES, derandomize=EXAMPLES <= 100 and SEED is None,
                deadline=None, database=None,
                suppress_health_check=list(HealthCheck))

# Integers small enough that no call does much work, and boundaries that must be refused early.
INTEGERS = st.one_of(st.integers(-4, 14),
                     st.sampled_from([2**31, -2**31 - 1, 2**63, 2**64, -2**63, 10**30]))
FLOATS = st.floats(allow_nan=True, allow_infinity=True, width=64)
WORDS = st.sampled_from(["paper", "strict", "on", "off", "datom", "catom3d", "symmetric",
                         "visiblesim", "side", "top", "auto", "6,5,2", "(1,1,1)", "1,2", "",
                         "\udcff", "a\x00b", "random", "line", "arch1", "heap", "flood",
                         "follow-gradient"])
ODD = st.sampled_from([None, {}, {"a": 1}, [], [[1, 2, 3]], object(), b"6,5,2", np.int64(3),
                       np.float64(2.0), np.bool_(True), np.array([1, 2, 3], dtype=np.uint8),
                       np.array([[1, 2, 3]]), np.array(5), np.array([1.5, 2.0, 3.0]),
                       np.array(["a", "b", "c"]), 1 + 2j, float("nan")])
CELLS = st.tuples(INTEGERS, INTEGERS, INTEGERS)
VALUES = st.one_of(st.booleans(), INTEGERS, FLOATS, WORDS, st.text(max_size=10), ODD, CELLS,
                   st.lists(INTEGERS, max_size=4), st.tuples(FLOATS, FLOATS, FLOATS),
                   CELLS.map(np.array), st.dictionaries(st.text(max_size=4), INTEGERS, max_size=2))

RUN_KEYWORDS = ["goal", "start", "root", "rules", "attachment", "connectivity", "seed",
                "delay_ms", "jitter_ms", "max_motions", "target", "timeout", "until", "params",
                "module", "rolling", "gravity", "load_region", "latch_force", "density", "trace",
                "colour"]
LOADS_KEYWORDS = ["radius", "thickness", "density", "solid_fraction", "young_modulus",
                  "poisson_ratio", "latch_force", "latch_moment", "gravity", "solver", "top",
                  "view", "name"]
RESHAPE_KEYWORDS = ["length", "floor", "modules", "seed", "side", "base", "height"]


def refused_or_done(call):
    """Calls; a refusal must be one of the package's kinds, with a message that is not pybind11's
    cast error."""
    try:
        call()
    except (datomsim.Error, TypeError, ValueError) as error:
        text = str(error)
        assert text, f"{type(error).__name__} without a message"
        assert "Unable to cast" not in text and "incompatible function arguments" not in text, text


def small_scene():
    return datomsim.box((3, 2, 1))


def keywords(names):
    return st.dictionaries(st.sampled_from(names), VALUES, max_size=3)


@FUZZ
@given(VALUES, VALUES, VALUES)
def test_box(size, origin, upright):
    refused_or_done(lambda: datomsim.box(size, origin, upright))


@FUZZ
@given(VALUES)
def test_arch(hole):
    refused_or_done(lambda: datomsim.arch(hole))


@FUZZ
@given(VALUES, VALUES, VALUES)
def test_random_scene(count, seed_value, grid):
    refused_or_done(lambda: datomsim.random_scene(count, seed_value, grid))


@FUZZ
@given(VALUES, keywords(RESHAPE_KEYWORDS))
def test_reshape(case, options):
    refused_or_done(lambda: datomsim.reshape(case, **options))


@FUZZ
@given(VALUES, VALUES, VALUES, VALUES, VALUES, VALUES)
def test_reach_and_moves(goal, start, rules, attachment, module, rolling):
    scene = small_scene()
    refused_or_done(lambda: datomsim.reach(scene, goal, start, rules, attachment,
                                           module=module, rolling=rolling))
    refused_or_done(lambda: datomsim.moves(scene, goal, rules, attachment, module, rolling))


@FUZZ
@given(st.sampled_from(["flood", "follow-gradient", "gradient"]) | VALUES, keywords(RUN_KEYWORDS))
def test_run(program, options):
    options.pop("trace", None) if isinstance(options.get("trace"), str) else None
    refused_or_done(lambda: datomsim.run(small_scene(), program, **options))


@FUZZ
@given(keywords(LOADS_KEYWORDS))
def test_loads(options):
    refused_or_done(lambda: datomsim.loads(small_scene(), **options))


@FUZZ
@given(VALUES, VALUES, VALUES)
def test_geometry(radius, thickness, fraction):
    refused_or_done(lambda: datomsim.geometry(radius, thickness, fraction))


@FUZZ
@given(VALUES, VALUES, VALUES, VALUES)
def test_scene_edits(cell, orientation, color, identifier):
    scene = small_scene()
    refused_or_done(lambda: scene.add(cell, orientation, color))
    refused_or_done(lambda: scene.move(identifier, cell))
    refused_or_done(lambda: scene.module_at(cell))
    refused_or_done(lambda: scene.remove(identifier))
    refused_or_done(lambda: setattr(scene, "module", cell))


@FUZZ
@given(VALUES)
def test_load_scene(path):
    # Text only as a path under a folder that holds nothing: nothing is read by accident.
    if isinstance(path, str):
        path = os.path.join("/nonexistent-datomsim-fuzz", path.replace("\x00", ""))
    refused_or_done(lambda: datomsim.load_scene(path))


SPEC_KEYS = ["scenes", "programs", "parameters", "seeds", "colour"]


@FUZZ
@given(st.dictionaries(st.sampled_from(SPEC_KEYS),
                       st.one_of(VALUES, st.lists(st.dictionaries(
                           st.sampled_from(["generate", "file", "program", "size", "goal",
                                            "max_motions", "count", "case", "params"]),
                           VALUES, max_size=3), max_size=2),
                           st.dictionaries(st.sampled_from(RUN_KEYWORDS + ["from", "count"]),
                                           VALUES, max_size=3)),
                       max_size=4))
def test_sweep_specs(spec):
    # The cases only: what a sweep checks and builds before it runs anything.
    try:
        sweeps.cases(spec)
    except sweeps.SpecError as error:
        assert str(error)


if SEED is not None:
    for _name, _test in list(globals().items()):
        if _name.startswith("test_"):
            globals()[_name] = seed(int(SEED))(_test)

pytestmark = pytest.mark.filterwarnings("ignore::DeprecationWarning")
