"""datomsim from Python: scenes, distance maps, motions and runs of Datoms in the FCC lattice.

The same C++ core as the ``datomsim`` command line (docs/python.md): a run gives the JSON
``datomsim run --out`` gives, a refusal raises :class:`Error` with the command line's message.

>>> import datomsim
>>> scene = datomsim.arch(hole=2)
>>> result = datomsim.reach(scene, goal=(6, 5, 2), start=(0, 0, 2))
>>> len(result.cells), result.start_distance
(145, 7)
"""

from __future__ import annotations

import json
import os
from dataclasses import dataclass
from typing import Any, Mapping, Optional, Sequence, Union

import numpy as np

from . import _core
from ._core import CheckFailed, Error, Scene, load_scene

__all__ = [
    "CheckFailed",
    "Error",
    "Reach",
    "Scene",
    "arch",
    "box",
    "geometry",
    "load_scene",
    "loads",
    "moves",
    "random_scene",
    "reach",
    "reshape",
    "run",
    "sweep",
]

Cell = Union[Sequence[int], str]

GOAL = (6, 5, 2)
"""The paper's goal cell G."""
START = (0, 0, 2)
"""The paper's start cell."""


def box(size: Cell, origin: Cell = (0, 0, 0), upright: bool = False) -> Scene:
    """A box of ``size`` (x, y, z) modules, as ``datomsim generate box``."""
    return _core.box(size, origin, upright)


def arch(hole: int = 2) -> Scene:
    """The paper's scene: a box with an arch whose hole is ``hole`` (2 or 1) layers high."""
    return _core.arch(hole)


def random_scene(count: int, seed: int = 1, grid: Optional[Cell] = None) -> Scene:
    """A random connected scene of ``count`` modules from ``seed``, as ``generate random``."""
    return _core.random_scene(count, seed, grid)


def reshape(
    case: str,
    *,
    length: int = 8,
    floor: Sequence[int] = (12, 12),
    modules: int = 20,
    seed: int = 1,
    side: int = 96,
    base: int = 0,
    height: int = 2,
) -> Scene:
    """A reconfiguration case, as ``generate reshape CASE``: arch2, arch1, line (``length``),
    heap (``floor``), random (``floor``, ``modules``, ``seed``, ``height``: the target's layers
    at most), pyramid or cube (``side``, ``base``: the pyramid's base, the cube's edge).
    The scene's first target is the shape ``run(scene, "reconfigure")`` builds."""
    return _core.reshape(case, length, floor, modules, seed, side, base, height)


@dataclass(frozen=True)
class Reach:
    """Distances in motions from every reachable cell to a goal (the paper's gradient)."""

    goal: tuple
    cells: np.ndarray  # (n, 3) int32, sorted by x, then y, then z
    distances: np.ndarray  # (n,) int32, motions from each cell to the goal
    path: np.ndarray  # (p, 3) int32: start to goal, empty without a start

    @property
    def start_distance(self) -> Optional[int]:
        """Motions from the start to the goal, or None without a start (or when unreachable)."""
        if len(self.path) == 0:
            return None
        return len(self.path) - 1

    def distance_at(self, cell: Sequence[int]) -> Optional[int]:
        """The distance of one cell, or None when it is not reachable."""
        hits = np.nonzero((self.cells == np.asarray(cell, dtype=np.int32)).all(axis=1))[0]
        return int(self.distances[hits[0]]) if len(hits) else None


def reach(
    scene: Scene,
    goal: Cell,
    start: Optional[Cell] = None,
    rules: str = "paper",
    attachment: bool = True,
    connectivity: bool = False,
    module: Optional[str] = None,
    rolling: str = "symmetric",
) -> Reach:
    """The distances to ``goal`` and, with a ``start``, the path, as ``datomsim reach``.

    The mobile is chosen as ``run`` chooses it (the module at the start, else the one at the goal
    moved to the start) and is not part of the fixed world. ``module`` ("datom" or "catom3d",
    default the scene's ``module``) says whose motions apply; ``rolling`` is the 3D Catom's rule
    set ("symmetric" or "visiblesim", docs/catom3d.md).
    """
    out = _core.reach(scene, goal, start, rules, attachment, connectivity, module, rolling)
    return Reach(out["goal"], out["cells"], out["distances"], out["path"])


def moves(
    scene: Scene,
    at: Cell,
    rules: str = "paper",
    attachment: bool = True,
    module: Optional[str] = None,
    rolling: str = "symmetric",
) -> list:
    """Every rule of every pivot around ``at`` (a 3D Catom's: every roll), valid or refused with
    its reason: the list of ``datomsim moves --out``'s "moves"."""
    return json.loads(_core.moves_json(scene, at, rules, attachment, module, rolling))["moves"]


def loads(
    scene: Scene,
    *,
    radius: Optional[float] = None,
    thickness: Optional[float] = None,
    density: Optional[float] = None,
    solid_fraction: Optional[float] = None,
    young_modulus: Optional[float] = None,
    poisson_ratio: Optional[float] = None,
    latch_force: Optional[float] = None,
    latch_moment: Optional[float] = None,
    gravity: Optional[Sequence[float]] = None,
    solver: Optional[str] = None,
    top: Optional[int] = None,
    view: Optional[str] = None,
    png: Optional[Union[str, os.PathLike]] = None,
    svg: Optional[Union[str, os.PathLike]] = None,
    name: Optional[str] = None,
) -> dict:
    """The loads on every latch of ``scene`` under gravity, as ``datomsim loads --out``
    (docs/mechanics.md): the parameters, the solver's figures, tipping, the most loaded latches
    and every latch's force, moment and safety factor. Every pair of neighbours is latched, as a
    scene file's rest state is. Parameters left out (None) take the command line's defaults, in
    SI units; ``png`` and ``svg`` write the safety map, seen from the ``view`` ("side" or "top"),
    titled with ``name`` (default: the scene's name).
    """
    options = {
        "radius": radius,
        "thickness": thickness,
        "density": density,
        "solid_fraction": solid_fraction,
        "young_modulus": young_modulus,
        "poisson_ratio": poisson_ratio,
        "latch_force": latch_force,
        "latch_moment": latch_moment,
        "gravity": gravity,
        "solver": solver,
        "top": top,
        "view": view,
        "png": None if png is None else os.fspath(png),
        "svg": None if svg is None else os.fspath(svg),
        "name": name,
    }
    return json.loads(_core.loads_json(scene, options))


def run(
    scene: Scene,
    program: str,
    *,
    trace: Union[None, bool, str, os.PathLike] = None,
    params: Optional[Mapping[str, Any]] = None,
    **options: Any,
) -> dict:
    """Runs a module program on ``scene`` and returns what ``datomsim run --out`` writes.

    Options are the command line's, with underscores: ``goal``, ``start``, ``seed``, ``rules``,
    ``attachment``, ``connectivity``, ``delay_ms``, ``jitter_ms``, ``max_motions``, ``target``
    (a scene file), ``timeout``, ``until`` (seconds), ``root`` (flood), ``gravity`` (True,
    "on" or three numbers: motions weighed under the load model, docs/mechanics.md),
    ``load_region`` and the load model's parameters as :func:`loads` takes them
    (``latch_force``, ``density``...); ``params`` are the program's parameters. ``trace`` is a file to write the trace to (its path is then in the
    result under "trace"), or True to have the trace's text there. ``actuators``
    ("DEFORMATION+LATCH", as ``--actuators``), ``size`` ("1cm"), ``designs`` (a folder) and
    ``power_csv`` (a file) are the modules' actuators (docs/actuators.md): the result then has
    the "energy" section ``run --out`` writes.

    A run that fails (the mobile does not arrive, the target is not built) is a result with its
    "reason", as ``run --out`` writes it; bad options raise :class:`Error`.
    """
    if params is not None:
        if not isinstance(params, Mapping):
            raise TypeError(f"run(): params must be a dict, got {type(params).__name__}")
        options["params"] = dict(params)
    if not (trace is None or isinstance(trace, (bool, str, os.PathLike))):
        raise TypeError(f"run(): trace must be a path, True or False, got {type(trace).__name__}")
    if isinstance(trace, os.PathLike) and not isinstance(os.fspath(trace), str):
        raise TypeError("run(): trace must be a path as text, got bytes")
    # A file is written by the core, as `run --trace` writes it: checked against the scene's file
    # and the target before the run, whole or not at all.
    path = os.fspath(trace) if isinstance(trace, (str, os.PathLike)) else None
    options["trace"] = path if path is not None else (trace is not None and trace is not False)
    text, trace_text, failure = _core.run(scene, program, options)
    result = json.loads(text)
    if path is not None:
        result["trace"] = path
    elif trace is True:
        result["trace"] = trace_text
    if failure is not None:
        result.setdefault("reason", failure)
    return result


def geometry(radius: float = 1.0, thickness: float = 0.0, fraction: Optional[float] = None) -> dict:
    """A Datom's dimensions (and its joint angles at a compression ``fraction``), as
    ``datomsim geometry --json``."""
    return json.loads(_core.geometry(radius, thickness, fraction))


def sweep(spec, out=None, **options) -> list:
    """Every combination of a spec's scenes, programs, parameters and seeds, one row per run
    (datomsim.sweeps.sweep; docs/python.md, "Sweeps")."""
    from .sweeps import sweep as run_sweep

    return run_sweep(spec, out, **options)
