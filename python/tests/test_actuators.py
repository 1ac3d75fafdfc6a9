"""run() with the modules' actuators (docs/actuators.md, "In the simulator"): the same run, the same
energy section and power CSV as `datomsim run --actuators`, and the same refusals."""

import json

import pytest

import datomsim

KEYWORDS = dict(goal=(6, 5, 2), start=(0, 0, 2))
ARGUMENTS = ["--goal", "6,5,2", "--start", "0,0,2"]


def test_a_run_with_actuators_is_the_command_lines(scenes, cli, tmp_path):
    path = scenes / "paper-arch-hole2.json"
    scene = datomsim.load_scene(path)
    ours = datomsim.run(scene, "follow-gradient", actuators="sma-spring+electrostatic", size="1cm",
                        power_csv=tmp_path / "ours.csv", **KEYWORDS)
    written = cli("run", path, "--program", "follow-gradient", *ARGUMENTS, "--actuators",
                  "sma-spring+electrostatic", "--size", "1cm", "--power-csv", "theirs.csv",
                  "--out", "-")
    assert written.returncode == 0, written.stderr
    assert ours == json.loads(written.stdout)
    assert (tmp_path / "ours.csv").read_text() == (tmp_path / "theirs.csv").read_text()
    energy = ours["energy"]
    assert energy["actuators"] == "sma-spring+electrostatic-latch"
    assert energy["radius_m"] == 0.01
    # The bookkeeping holds in Python's values too: the modules' energies sum to the total.
    assert sum(m["total_J"] for m in energy["modules"]) == pytest.approx(energy["total_J"])
    last = (tmp_path / "ours.csv").read_text().splitlines()[-1]
    assert float(last.split(",")[2]) == pytest.approx(energy["total_J"], rel=1e-6)


def test_a_run_without_actuators_has_no_energy(scenes):
    scene = datomsim.load_scene(scenes / "paper-arch-hole2.json")
    assert "energy" not in datomsim.run(scene, "follow-gradient", **KEYWORDS)


def test_the_designs_of_a_folder_given(scenes, tmp_path):
    scene = datomsim.load_scene(scenes / "paper-arch-hole2.json")
    designs = scenes.parent / "data" / "actuators"
    given = datomsim.run(scene, "follow-gradient", actuators="electro-ribbon+mechanical",
                         size="10cm", designs=designs, **KEYWORDS)
    shipped = datomsim.run(scene, "follow-gradient", actuators="electro-ribbon+mechanical",
                           size="10cm", **KEYWORDS)
    assert given == shipped
    assert given["energy"]["radius_m"] == 0.1


def test_bad_actuator_options_raise_the_command_lines_message(scenes, cli):
    path = scenes / "paper-arch-hole2.json"
    scene = datomsim.load_scene(path)
    for python, command in [
        (dict(size="1cm"), ["--size", "1cm"]),
        (dict(power_csv="p.csv"), ["--power-csv", "p.csv"]),
        (dict(actuators="sma-sprng+electrostatic"), ["--actuators", "sma-sprng+electrostatic"]),
        (dict(actuators="sma-spring+electro-ribbon"), ["--actuators", "sma-spring+electro-ribbon"]),
        (dict(actuators="sma-spring+electrostatic", size="1km"),
         ["--actuators", "sma-spring+electrostatic", "--size", "1km"]),
        (dict(actuators="sma-spring+electrostatic", designs="none"),
         ["--actuators", "sma-spring+electrostatic", "--designs", "none"]),
    ]:
        with pytest.raises(datomsim.Error) as raised:
            datomsim.run(scene, "follow-gradient", **python, **KEYWORDS)
        said = cli("run", path, "--program", "follow-gradient", *ARGUMENTS, *command)
        assert said.returncode == 1
        assert said.stderr.strip() == f"datomsim: error: {raised.value}", python
    with pytest.raises(TypeError, match="actuators must be a string, got int"):
        datomsim.run(scene, "follow-gradient", actuators=3, **KEYWORDS)
    with pytest.raises(TypeError, match="designs must be a path"):
        datomsim.run(scene, "follow-gradient", actuators="sma-spring+electrostatic", designs=1,
                     **KEYWORDS)


def test_a_power_csv_over_the_scene_is_refused_and_nothing_written(scenes, tmp_path):
    copy = tmp_path / "scene.json"
    copy.write_text((scenes / "paper-arch-hole2.json").read_text())
    scene = datomsim.load_scene(copy)
    before = copy.read_text()
    with pytest.raises(datomsim.Error, match="power_csv"):
        datomsim.run(scene, "follow-gradient", actuators="sma-spring+electrostatic",
                     power_csv=copy, **KEYWORDS)
    assert copy.read_text() == before
