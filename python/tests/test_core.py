"""The package against the command line: the same scenes, distances, moves and runs, the same
messages for the same mistakes; the paper's experiment in a few lines."""

import json

import numpy as np
import pytest

import datomsim


def test_the_papers_experiment_in_a_few_lines():
    found = {}
    for hole in (2, 1):
        result = datomsim.reach(datomsim.arch(hole), goal=datomsim.GOAL, start=datomsim.START)
        found[hole] = (len(result.cells), result.start_distance)
    assert found == {2: (145, 7), 1: (144, 9)}


def test_a_scenes_modules_are_numpy_arrays(scenes):
    scene = datomsim.load_scene(scenes / "paper-arch-hole1.json")
    # The paper's 130 modules and the mobile, which the file holds at G.
    assert len(scene) == 131
    assert scene.cells.shape == (131, 3) and scene.cells.dtype == np.int32
    assert tuple(scene.cells[0]) == datomsim.GOAL
    assert scene.ids.shape == (131,) and scene.colors.shape == (131, 3)
    assert scene.orientations.dtype == np.uint8
    assert scene.module_at(tuple(scene.cells[0])) == scene.ids[0]
    assert scene.module_at((40, 40, 40)) is None


def test_scenes_are_edited_and_saved_as_the_command_line_reads_them(tmp_path, cli):
    scene = datomsim.box((3, 2, 1))
    assert len(scene) == 6
    surface = scene.free_surface_cells()
    assert surface.shape[1] == 3 and len(surface) > 0
    # Every free surface cell is empty and next to a module; adding at one makes a module there.
    added = scene.add(tuple(surface[0]), orientation=0, color=(200, 10, 10))
    assert scene.module_at(tuple(surface[0])) == added
    assert tuple(scene.colors[-1]) == (200, 10, 10)
    scene.move(added, tuple(surface[1]))
    assert scene.module_at(tuple(surface[1])) == added
    with pytest.raises(datomsim.Error, match="occupied|holds"):
        scene.add(tuple(scene.cells[0]))
    scene.remove(added)
    assert len(scene) == 6
    with pytest.raises(datomsim.Error):
        scene.remove(added)

    for name in ("box.json", "box.xml"):
        scene.save(tmp_path / name)
        info = cli("info", name, "--json")
        assert info.returncode == 0, info.stderr
        assert json.loads(info.stdout)["modules"] == 6
        again = datomsim.load_scene(tmp_path / name)
        assert (again.cells == scene.cells).all()


def test_reach_gives_what_reach_out_writes(scenes, cli):
    path = scenes / "paper-arch-hole1.json"
    result = datomsim.reach(datomsim.load_scene(path), goal="6,5,2", start=(0, 0, 2))
    written = cli("reach", path, "--goal", "6,5,2", "--start", "0,0,2", "--out", "-")
    assert written.returncode == 0, written.stderr
    expected = json.loads(written.stdout)
    assert result.cells.tolist() == [d[:3] for d in expected["distances"]]
    assert result.distances.tolist() == [d[3] for d in expected["distances"]]
    assert result.path.tolist() == expected["path"]
    assert result.distance_at((0, 0, 2)) == 9


def test_moves_give_what_moves_out_writes(scenes, cli):
    path = scenes / "paper-arch-hole1.json"
    listed = datomsim.moves(datomsim.load_scene(path), at=(2, 2, 3))
    written = cli("moves", path, "--at", "2,2,3", "--format", "json")
    assert written.returncode == 0, written.stderr
    assert listed == json.loads(written.stdout)["moves"]
    assert any(move["valid"] for move in listed)
    assert any(move["refusal"] for move in listed)


def test_a_3d_catom_rolls_as_the_command_line_rolls_it(scenes, cli, tmp_path):
    path = scenes / "paper-arch-hole1.json"
    scene = datomsim.load_scene(path)
    assert scene.module == "datom"
    rolled = datomsim.reach(scene, goal=(6, 5, 2), start=(0, 0, 2), module="catom3d")
    written = cli("reach", path, "--goal", "6,5,2", "--start", "0,0,2", "--module", "catom3d",
                  "--out", "-")
    assert written.returncode == 0, written.stderr
    expected = json.loads(written.stdout)
    assert rolled.cells.tolist() == [d[:3] for d in expected["distances"]]
    assert rolled.path.tolist() == expected["path"]
    # A scene made of Catoms rolls without being told, and keeps its kind in its file.
    scene.module = "catom3d"
    assert datomsim.reach(scene, goal=(6, 5, 2)).cells.tolist() == rolled.cells.tolist()
    scene.save(tmp_path / "catoms.json")
    assert datomsim.load_scene(tmp_path / "catoms.json").module == "catom3d"
    listed = datomsim.moves(scene, at=(2, 2, 3))
    assert listed == json.loads(
        cli("moves", tmp_path / "catoms.json", "--at", "2,2,3", "--format", "json").stdout
    )["moves"]
    assert {move["face"] for move in listed} == {"hexagonal", "octagonal"}
    with pytest.raises(datomsim.Error, match="--module: sphere not in"):
        scene.module = "sphere"
    with pytest.raises(datomsim.Error, match="--rolling: exact not in"):
        datomsim.reach(scene, goal=(6, 5, 2), rolling="exact")
    # And it runs with rolls: the paper's Algorithm 1 follows reach's path.
    walked = datomsim.run(scene, "follow-gradient", goal=(6, 5, 2), start=(0, 0, 2))
    assert walked["arrived"] and walked["path"] == rolled.path.tolist()
    assert datomsim.run(datomsim.load_scene(path), "follow-gradient", goal=(6, 5, 2),
                        start=(0, 0, 2), module="catom3d")["path"] == walked["path"]


@pytest.mark.parametrize(
    "program, options, arguments",
    [
        ("follow-gradient", {"goal": (6, 5, 2), "start": (0, 0, 2), "seed": 3, "jitter_ms": 5},
         ["--goal", "6,5,2", "--start", "0,0,2", "--seed", "3", "--jitter-ms", "5"]),
        ("gradient", {"goal": (6, 5, 2)}, ["--goal", "6,5,2"]),
        ("flood", {"root": (1, 1, 0)}, ["--root", "1,1,0"]),
    ],
)
def test_run_gives_what_run_out_writes(scenes, cli, tmp_path, program, options, arguments):
    path = scenes / "paper-arch-hole1.json"
    trace = tmp_path / "python.jsonl"
    result = datomsim.run(datomsim.load_scene(path), program, trace=trace, **options)
    written = cli("run", path, "--program", program, *arguments, "--out", "-", "--trace", "cli.jsonl")
    assert written.returncode == 0, written.stderr
    expected = json.loads(written.stdout)
    assert result.pop("trace") == str(trace)
    assert result == expected
    # The trace is the command line's but for its description, which names the scene.
    ours, theirs = trace.read_text().splitlines(), (tmp_path / "cli.jsonl").read_text().splitlines()
    assert ours[1:] == theirs[1:]


def test_a_failed_run_is_a_result_with_its_reason():
    # A mobile put in the air at 0,0,6 is latched to no module: it cannot follow the gradient.
    result = datomsim.run(datomsim.arch(2), "follow-gradient", goal=(6, 5, 2), start=(0, 0, 6))
    assert result["arrived"] is False
    assert "latched to no module" in result["reason"]
    assert result["path"][0] == [0, 0, 6]


def test_loads_give_what_loads_out_writes(scenes, cli, tmp_path):
    path = scenes / "paper-arch-hole2.json"
    scene = datomsim.load_scene(path)
    ours = datomsim.loads(scene, latch_moment=2e-5, latch_force=0.05, top=3, view="top",
                          png=tmp_path / "ours.png", name=str(path))
    written = cli("loads", path, "--latch-moment", "2e-5", "--latch-force", "0.05", "--top", "3",
                  "--view", "top", "--png", "theirs.png", "--out", "-")
    assert written.returncode == 0, written.stderr
    assert ours == json.loads(written.stdout)
    assert ours["overloaded"] == 4
    assert (tmp_path / "ours.png").read_bytes() == (tmp_path / "theirs.png").read_bytes()
    with pytest.raises(datomsim.Error) as raised:
        datomsim.loads(scene, gravity=(0, 0, float("nan")))
    said = cli("loads", path, "--gravity", "0,0,nan")
    assert said.stderr.strip() == f"datomsim: error: {raised.value}"
    with pytest.raises(datomsim.Error) as raised:
        datomsim.loads(scene, density=-1)
    said = cli("loads", path, "--density", "-1")
    assert said.stderr.strip() == f"datomsim: error: {raised.value}"
    with pytest.raises(TypeError, match="density must be a number, got str"):
        datomsim.loads(scene, density="dense")
    with pytest.raises(TypeError, match="gravity must be three numbers"):
        datomsim.loads(scene, gravity=(0, -9.81))


def test_run_with_gravity_refuses_what_the_command_line_refuses(scenes, cli):
    path = scenes / "paper-arch-hole2.json"
    scene = datomsim.load_scene(path)
    keywords = dict(goal=(6, 5, 2), start=(0, 0, 2))
    arguments = ["--goal", "6,5,2", "--start", "0,0,2"]
    # A motion refused under gravity: the same failure, the same figures.
    ours = datomsim.run(scene, "follow-gradient", gravity=True, latch_force=0.03, **keywords)
    written = cli("run", path, "--program", "follow-gradient", *arguments, "--gravity", "on",
                  "--latch-force", "0.03", "--out", "-")
    assert written.returncode == 1
    assert ours == json.loads(written.stdout)
    assert "latch 49-97 would carry 30.1 mN (limit 30 mN)" in ours["reason"]
    assert ours["gravity"]["refused"] == 1
    for python, command in [
        (dict(gravity="on", latch_force=0.02), ["--gravity", "on", "--latch-force", "0.02"]),
        (dict(latch_moment=0.5), ["--latch-moment", "0.5"]),
        (dict(gravity=(0, 0, 0)), ["--gravity", "0,0,0"]),
        (dict(gravity="sideways"), ["--gravity", "sideways"]),
        (dict(gravity=True, load_region=-1), ["--gravity", "on", "--load-region", "-1"]),
    ]:
        with pytest.raises(datomsim.Error) as raised:
            datomsim.run(scene, "follow-gradient", **python, **keywords)
        said = cli("run", path, "--program", "follow-gradient", *arguments, *command)
        assert said.returncode == 1
        assert said.stderr.strip() == f"datomsim: error: {raised.value}", python
    with pytest.raises(TypeError, match="load_region must be an integer"):
        datomsim.run(scene, "follow-gradient", gravity=True, load_region=2.5, **keywords)


def test_mistakes_raise_the_command_lines_message(scenes, cli):
    path = scenes / "paper-arch-hole1.json"
    scene = datomsim.load_scene(path)
    cases = [
        (lambda: datomsim.reach(scene, goal=(0, 0, 8)), ["reach", path, "--goal", "0,0,8"]),
        (lambda: datomsim.reach(scene, goal=(0, 0, -1)), ["reach", path, "--goal", "0,0,-1"]),
        (lambda: datomsim.reach(scene, goal="6,5"), ["reach", path, "--goal", "6,5"]),
        (lambda: datomsim.run(scene, "follow-gradient", goal=(6, 5, 2)),
         ["run", path, "--program", "follow-gradient", "--goal", "6,5,2"]),
        (lambda: datomsim.run(scene, "flood", params={"speed": "1"}),
         ["run", path, "--program", "flood", "--param", "speed=1"]),
        (lambda: datomsim.load_scene(path.parent / "no-such-scene.json"),
         ["info", path.parent / "no-such-scene.json"]),
    ]
    for call, arguments in cases:
        with pytest.raises(datomsim.Error) as raised:
            call()
        said = cli(*arguments)
        assert said.returncode == 1
        assert said.stderr.strip() == f"datomsim: error: {raised.value}", arguments
    with pytest.raises(datomsim.Error, match="unknown option colour"):
        datomsim.run(scene, "gradient", goal=(6, 5, 2), colour="red")


@pytest.mark.parametrize("keyword, value, option, text", [
    ("until", 1e13, "--until", "1e13"),
    ("until", float("nan"), "--until", "nan"),
    ("until", -1.0, "--until", "-1"),
    ("until", 0.0, "--until", "0"),
    ("delay_ms", 1e16, "--delay-ms", "1e16"),
    ("delay_ms", float("-inf"), "--delay-ms", "-inf"),
    ("jitter_ms", 1e16, "--jitter-ms", "1e16"),
    ("jitter_ms", -0.5, "--jitter-ms", "-0.5"),
])
def test_times_are_refused_as_the_command_line_refuses_them(scenes, cli, keyword, value, option,
                                                            text):
    path = scenes / "paper-arch-hole1.json"
    scene = datomsim.load_scene(path)
    with pytest.raises(datomsim.Error) as raised:
        datomsim.run(scene, "flood", root=(6, 5, 2), **{keyword: value})
    said = cli("run", path, "--program", "flood", "--root", "6,5,2", option, text)
    assert said.returncode == 1
    assert said.stderr.strip() == f"datomsim: error: {raised.value}"
    assert option in str(raised.value)


@pytest.mark.parametrize("value, text", [(1e13, "1e13"), (float("nan"), "nan"), (-5.0, "-5")])
def test_a_timeout_is_refused_as_the_command_line_refuses_it(scenes, cli, value, text):
    path = scenes / "reshape-line.json"
    with pytest.raises(datomsim.Error) as raised:
        datomsim.run(datomsim.load_scene(path), "reconfigure", timeout=value)
    said = cli("run", path, "--program", "reconfigure", "--timeout", text)
    assert said.returncode == 1
    assert said.stderr.strip() == f"datomsim: error: {raised.value}"
    assert str(raised.value).startswith("--timeout ")


def test_geometry_is_the_papers(cli):
    ours = datomsim.geometry(radius=1.0, thickness=0.1, fraction=0.5)
    written = cli("geometry", "--radius", "1", "--thickness", "0.1", "--fraction", "0.5", "--json")
    assert ours == pytest.approx(json.loads(written.stdout))
    assert ours["c"] == pytest.approx(2 / (3 * 2**0.5 - 1))


@pytest.mark.parametrize("case, keywords, arguments", [
    ("random", {"floor": (16, 16), "modules": 60, "seed": 4, "height": 7},
     ["--floor", "16,16", "--modules", "60", "--seed", "4", "--height", "7"]),
    ("cube", {"side": 24, "base": 3}, ["--side", "24", "--base", "3"]),
])
def test_reshape_cases_are_the_command_lines(cli, tmp_path, case, keywords, arguments):
    scene = datomsim.reshape(case, **keywords)
    scene.save(tmp_path / "python.json")
    made = cli("generate", "reshape", case, *arguments, "-o", "cli.json")
    assert made.returncode == 0, made.stderr
    assert (tmp_path / "python.json").read_text() == (tmp_path / "cli.json").read_text()
    with pytest.raises(datomsim.Error, match="layers high"):
        datomsim.reshape("random", height=0)
