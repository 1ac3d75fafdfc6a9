"""Hostile input from Python (docs/limits.md): no signal from any value, every wrong argument named
with what was expected, the command line's refusals with its messages, sizes bounded before the
work starts; then hypothesis over every public function."""


import numpy as np
import pytest

import datomsim

FLOOD = {"root": (6, 5, 2)}
WALK = {"goal": (6, 5, 2), "start": (0, 0, 2)}


@pytest.fixture(scope="module")
def arch():
    return datomsim.arch(2)


@pytest.mark.parametrize("call, says", [
    (lambda a: datomsim.box(np.array([3.0, 2.0, 1.0])), "box(): size must be three integers"),
    (lambda a: datomsim.reach(a, goal=np.array([6.0, 5.0, 2.0])),
     "reach(): goal must be three integers x,y,z, got array of float64"),
    (lambda a: datomsim.run(a, "flood", root=np.array([6.0, 5.0, 2.0])),
     "run(): root must be three integers x,y,z, got array of float64"),
    (lambda a: datomsim.moves(a, at=(6.5, 5, 2)), "moves(): at must be three integers"),
    (lambda a: datomsim.run(a, "follow-gradient", max_motions=10**30, **WALK),
     "run(): max_motions 1000000000000000000000000000000"),
    (lambda a: datomsim.run(a, "follow-gradient", max_motions=10**12, **WALK),
     "--max-motions: at most 2147483647, got 1000000000000"),
    (lambda a: datomsim.run(a, "follow-gradient", max_motions=1.5, **WALK),
     "run(): max_motions must be an integer, got float"),
    (lambda a: datomsim.run(a, "follow-gradient", max_motions="2", **WALK),
     "run(): max_motions must be an integer, got str"),
    (lambda a: datomsim.run(a, "follow-gradient", attachment="bogus", **WALK),
     "run(): attachment must be True or False, got str"),
    (lambda a: datomsim.run(a, "follow-gradient", rules=3, **WALK),
     "run(): rules must be a string, got int"),
    (lambda a: datomsim.run(a, "follow-gradient", trace=5, **WALK),
     "run(): trace must be a path, True or False, got int"),
    (lambda a: datomsim.run(a, "flood", params=[1], **FLOOD), "run(): params must be a dict"),
    (lambda a: datomsim.run(a, "flood", params={"k": {}}, **FLOOD),
     "run(): params' k must be a number, a string or a bool, got dict"),
    (lambda a: datomsim.run(a, 5), "run(): program must be a string, got int"),
    (lambda a: datomsim.run(a, "flood", seed=1.5, **FLOOD), "run(): seed must be an integer"),
    (lambda a: datomsim.run(a, "flood", until="1", **FLOOD), "run(): until must be a number"),
    (lambda a: datomsim.arch(3.5), "arch(): hole must be an integer, got float"),
    (lambda a: datomsim.random_scene(-1), "random_scene(): count -1"),
    (lambda a: datomsim.random_scene(5, seed=-1), '--seed "-1" must be an integer from 0'),
    (lambda a: datomsim.reshape("random", modules=10**10), "reshape(): modules 10000000000"),
    (lambda a: datomsim.reshape("random", modules=10**8), "--modules: Value 100000000"),
    (lambda a: datomsim.reshape(3), "reshape(): case must be a string, got int"),
    (lambda a: datomsim.geometry("x"), "geometry(): radius must be a number, got str"),
    (lambda a: datomsim.reach(a, goal=(6, 5, 2), attachment=None),
     "reach(): attachment must be True or False, got NoneType"),
    (lambda a: datomsim.load_scene(5), "load_scene(): path must be a path"),
    (lambda a: a.add((0, 0, 9), orientation=1.5), "add(): orientation must be an integer"),
    (lambda a: a.add((0, 0, 9), color=(1, 2)), "add(): color must be three integers"),
    (lambda a: a.remove("x"), "remove(): id must be an integer, got str"),
    (lambda a: a.remove(-1), "remove(): id -1"),
    (lambda a: setattr(a, "module", 5), "module must be a string, got int"),
    (lambda a: datomsim.loads(a, top=2**40), "loads(): top 1099511627776"),
])
def test_a_wrong_argument_is_named_with_what_was_expected(arch, call, says):
    with pytest.raises((datomsim.Error, TypeError)) as raised:
        call(arch.copy())
    assert says in str(raised.value)
    assert "Unable to cast" not in str(raised.value)


@pytest.mark.parametrize("keyword, value, option, text", [
    ("rules", "bogus", "--rules", "bogus"),
    ("max_motions", 0, "--max-motions", "0"),
    ("max_motions", -3, "--max-motions", "-3"),
    ("module", "cube", "--module", "cube"),
    ("rolling", "fast", "--rolling", "fast"),
])
def test_run_refuses_what_the_command_line_refuses(scenes, cli, keyword, value, option, text):
    path = scenes / "paper-arch-hole1.json"
    with pytest.raises(datomsim.Error) as raised:
        datomsim.run(datomsim.load_scene(path), "follow-gradient", **WALK, **{keyword: value})
    said = cli("run", path, "--program", "follow-gradient", "--goal", "6,5,2", "--start", "0,0,2",
               option, text)
    assert said.returncode == 1
    assert said.stderr.splitlines()[0] == f"datomsim: error: {raised.value}"


@pytest.mark.parametrize("function", ["reach", "moves"])
def test_unknown_rules_are_refused_by_reach_and_moves_too(scenes, cli, function):
    path = scenes / "paper-arch-hole1.json"
    scene = datomsim.load_scene(path)
    with pytest.raises(datomsim.Error) as raised:
        if function == "reach":
            datomsim.reach(scene, goal=(6, 5, 2), rules="bogus")
        else:
            datomsim.moves(scene, at=(6, 5, 2), rules="bogus")
    said = cli("reach", path, "--goal", "6,5,2", "--rules", "bogus")
    assert said.stderr.splitlines()[0] == f"datomsim: error: {raised.value}"


def test_whole_numbers_of_numpy_integer_types_are_cells(arch):
    assert len(datomsim.box(np.array([3, 2, 1], dtype=np.int64))) == 6
    assert datomsim.reach(arch, goal=np.array([6, 5, 2], dtype=np.int16)).goal == (6, 5, 2)


def test_a_wide_csg_target_is_refused_before_it_is_scanned(tmp_path):
    # A cube of 16 million candidate cells less 400 spheres: 6.4e9 containment tests, over a minute.
    spheres = " ".join("sphere(1);" for _ in range(400))
    scene = tmp_path / "wide.json"
    scene.write_text(
        '{"format": "datomsim-scene", "version": 1, "modules": [{"id": 1, "cell": [0, 0, 0]}],'
        ' "targets": [{"format": "csg", "content": "difference() { cube([4000,4000,1]); '
        + spheres + ' }"}]}')
    with pytest.raises(datomsim.Error, match="containment tests"):
        datomsim.load_scene(scene).targets


def test_a_long_repr_is_cut_between_characters():
    # Found by hypothesis: a repr cut inside a character of four UTF-8 bytes left a TypeError
    # without a message.
    origin = {"\x1f\n\U00010b92\U00018cd6": 2**64, "0\x1f\u0100": 2**31}
    with pytest.raises(TypeError, match="origin must be three integers"):
        datomsim.box((1, 1, 1), origin)
