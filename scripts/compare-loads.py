#!/usr/bin/env python3
"""How far the distributed load solver's loads are from the centralised solver's on one scene
(docs/mechanics.md, "The distributed solver"): the figures of its table.

    scripts/compare-loads.py SCENE.json DISTRIBUTED.json CENTRALISED.json

DISTRIBUTED.json is what `datomsim run SCENE --program loads --root X,Y,Z --out` wrote,
CENTRALISED.json what `datomsim loads SCENE --out` wrote. Every module reports the largest force
and moment of its latches and their smallest safety factor; the same are taken from the
centralised solver's latches. Printed: the iterations, the relative residual and the messages of
the distributed run (in all, and per iteration of the conjugate gradient), and the largest
differences: of the forces and of the moments as a fraction of the scene's largest, of the finite
safety factors as a fraction of each.
"""
import json
import math
import sys

PER_ITERATION = ["LoadStepMsg", "LoadDirectionMsg", "LoadCurvatureMsg", "LoadAlphaMsg",
                 "LoadResidualMsg"]


def main(scene_path, distributed_path, centralised_path):
    with open(scene_path) as f:
        scene = json.load(f)
    with open(distributed_path) as f:
        distributed = json.load(f)
    with open(centralised_path) as f:
        centralised = json.load(f)
    cell_of = {module["id"]: tuple(module["cell"]) for module in scene["modules"]}
    # [largest force, largest moment, smallest safety] by cell.
    expected = {cell: [0.0, 0.0, math.inf] for cell in cell_of.values()}
    for latch in centralised["loads"]:
        force = math.hypot(*latch["force_n"])
        moment = math.hypot(*latch["moment_n_m"])
        safety = math.inf if latch["safety"] is None else latch["safety"]
        for end in (latch["a"], latch["b"]):
            worst = expected[cell_of[end]]
            worst[0] = max(worst[0], force)
            worst[1] = max(worst[1], moment)
            worst[2] = min(worst[2], safety)
    found = {cell: [0.0, 0.0, math.inf] for cell in cell_of.values()}
    for index, key in enumerate(["force", "moment", "safety"]):
        for x, y, z, value in distributed.get(key, []):
            found[(x, y, z)][index] = value
    if not distributed.get("converged") or distributed["converged"][0][3] != 1:
        sys.exit("the distributed solver did not converge: no loads to compare")
    force_scale = max(worst[0] for worst in expected.values())
    moment_scale = max(worst[1] for worst in expected.values())
    force = moment = safety = 0.0
    for cell, want in expected.items():
        got = found[cell]
        force = max(force, abs(got[0] - want[0]) / force_scale)
        moment = max(moment, abs(got[1] - want[1]) / moment_scale)
        if math.isfinite(want[2]):
            safety = max(safety, abs(got[2] - want[2]) / want[2])
        elif math.isfinite(got[2]):
            safety = math.inf
    iterations = int(distributed["iterations"][0][3])
    by_type = distributed["messages_by_type"]
    per_iteration = sum(by_type.get(name, 0) for name in PER_ITERATION) / max(iterations, 1)
    print(f"modules {len(cell_of)}, latches {centralised['latches']}, iterations {iterations}, "
          f"residual {distributed['residual'][0][3]:.2g}, messages {distributed['messages']} "
          f"({per_iteration:.0f} per iteration); largest differences: force {force:.2g}, "
          f"moment {moment:.2g}, safety {safety:.2g}")


if __name__ == "__main__":
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    main(*sys.argv[1:])
