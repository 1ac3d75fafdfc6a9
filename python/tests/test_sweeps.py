"""Sweeps: a spec's cases, the same rows on all cores and on a Dask cluster, resumed after a stop,
the command line's `datomsim sweep`, and the plot of the rows."""

import csv
import importlib.util
import json
import os

import pytest

import datomsim
from datomsim import sweeps
from datomsim.plot import sweep_figure

SPEC = {
    "scenes": [{"generate": "reshape", "case": "random", "floor": [8, 8], "modules": [4, 8]}],
    "programs": [{"program": "reconfigure"}],
    "parameters": {"max_motions": [None, 1]},
    "seeds": {"from": 1, "count": 4},
}


def without_wall_time(rows):
    return sorted(({k: v for k, v in row.items() if k != "wall_s"} for row in rows),
                  key=lambda row: row["case"])


def test_a_spec_gives_every_combination_once():
    found = sweeps.cases(SPEC)
    assert len(found) == 2 * 2 * 4
    assert len({case["case"] for case in found}) == len(found)
    # A list of numbers is one cell for a cell's key, and a choice for any other key.
    assert {tuple(case["scene"]["floor"]) for case in found} == {(8, 8)}
    assert {case["scene"]["modules"] for case in found} == {4, 8}
    assert len(sweeps.cases({**SPEC, "scenes": [{"generate": "box", "size": [[2, 2, 1], [3, 2, 1]]}]})) == 2 * 2 * 4


@pytest.mark.parametrize("spec, says", [
    ({"scenes": [], "programs": [{"program": "flood"}]}, "scenes: a non-empty list is needed"),
    ({**SPEC, "colour": 1}, "unknown key(s) colour"),
    ({**SPEC, "seeds": {"start": 1}}, 'seeds: {"start": 1}'),
    ({**SPEC, "scenes": [{"generate": "cube"}]}, 'generate "cube" is not one of'),
    ({**SPEC, "scenes": [{"generate": "box", "size": [1, 2, 3, 4, 5]}]}, "size: [1, 2, 3, 4, 5] is neither a cell"),
    ({**SPEC, "parameters": {"jitter_ms": []}}, "jitter_ms: an empty list sweeps over nothing"),
    # Found by the fuzzing: a Python object where JSON is expected ended in json's TypeError.
    ({**SPEC, "scenes": [{"generate": object()}]}, "spec.scenes[0].generate: a object is not a JSON value"),
    ({**SPEC, "parameters": {1: 2}}, "spec.parameters: key 1 is not a string"),
])
def test_a_bad_spec_is_refused_naming_what_is_wrong(spec, says):
    with pytest.raises(sweeps.SpecError) as raised:
        sweeps.cases(spec)
    assert says in str(raised.value)


def test_a_row_is_its_run():
    rows = datomsim.sweep({**SPEC, "seeds": [3]}, workers=1)
    assert len(rows) == 4
    row = next(r for r in rows if r["scene.modules"] == "8" and r["max_motions"] == "1")
    scene = datomsim.reshape("random", floor=(8, 8), modules=8, seed=3)
    result = datomsim.run(scene, "reconfigure", seed=3, max_motions=1)
    assert row["success"] == result["success"]
    assert (row["motions"], row["makespan_s"], row["messages"]) == (
        result["motions"], result["makespan_s"], result["messages"])
    assert row["modules"] == len(scene)


def test_a_case_that_cannot_run_is_a_row_with_its_reason():
    rows = datomsim.sweep({"scenes": [{"generate": "arch", "hole": 1}],
                           "programs": [{"program": "follow-gradient", "goal": [0, 0, -1],
                                         "start": [0, 0, 2]}]}, workers=1)
    assert rows[0]["success"] is False
    assert "0,0,-1 is below the ground" in rows[0]["reason"]


def test_all_cores_and_a_dask_cluster_give_the_same_rows(tmp_path):
    from distributed import Client, LocalCluster

    local = datomsim.sweep(SPEC, str(tmp_path / "local.csv"), workers=2)
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                      dashboard_address=None) as cluster, Client(cluster) as client:
        on_dask = datomsim.sweep(SPEC, str(tmp_path / "dask.csv"),
                                 scheduler=client.scheduler.address)
        ran_on = set(client.run(os.getpid).values())
    assert len(local) == 16 and len(ran_on) == 2
    assert without_wall_time(local) == without_wall_time(on_dask)
    assert any(row["success"] for row in local)


def test_a_stopped_sweep_goes_on_where_it_stopped(tmp_path):
    out = tmp_path / "rows.csv"
    whole = datomsim.sweep(SPEC, str(out), workers=2)
    lines = out.read_text().splitlines()
    # Stopped after five rows: the file holds its header and those.
    out.write_text("\n".join(lines[:6]) + "\n")
    kept = {row["case"]: row for row in sweeps.read_rows(str(out))}
    again = datomsim.sweep(SPEC, str(out), workers=2)
    assert len(again) == len(whole) == 16
    assert len({row["case"] for row in again}) == 16
    for row in again:  # the five rows already there are not run again
        if row["case"] in kept:
            assert row == kept[row["case"]]
    assert without_wall_time(again) == without_wall_time(whole)
    with pytest.raises(sweeps.SpecError, match="holds the rows of another spec"):
        datomsim.sweep({**SPEC, "parameters": {}}, str(out), workers=1)


def test_the_command_line_runs_a_sweep(tmp_path, cli):
    spec = tmp_path / "spec.json"
    spec.write_text(json.dumps({**SPEC, "seeds": [1, 2]}))
    done = cli("sweep", spec, "-o", "rows.csv", "--workers", "2")
    assert done.returncode == 0, done.stderr
    with open(tmp_path / "rows.csv", newline="") as file:
        rows = list(csv.DictReader(file))
    assert len(rows) == 8
    bad = tmp_path / "bad.json"
    bad.write_text('{"scenes": [\n  {"file": }\n]}')
    refused = cli("sweep", bad, "-o", "bad.csv")
    assert refused.returncode == 1
    assert f"{bad}: line 2: Expecting value" in refused.stderr
    assert not (tmp_path / "bad.csv").exists()


def test_the_plot_draws_success_and_makespan_against_the_module_count(tmp_path):
    rows = datomsim.sweep(SPEC, workers=2)
    figure = sweep_figure(rows, x="scene.modules", group="max_motions")
    rates, values = figure.axes[:2]
    assert rates.get_ylabel() == "runs that succeeded (%)"
    assert len(rates.get_lines()) == 2  # max_motions none and 1
    figure.savefig(tmp_path / "sweep.png")
    assert (tmp_path / "sweep.png").stat().st_size > 10_000


def test_parquet_is_written_where_pyarrow_is_and_refused_clearly_where_not(tmp_path):
    out = tmp_path / "rows.parquet"
    if importlib.util.find_spec("pyarrow") is None:
        with pytest.raises(sweeps.SpecError, match="Parquet needs pyarrow"):
            datomsim.sweep({**SPEC, "seeds": [1]}, str(out), workers=1)
        assert not out.exists()
        return
    import pandas

    rows = datomsim.sweep({**SPEC, "seeds": [1]}, str(out), workers=1)
    assert len(pandas.read_parquet(out)) == len(rows) == 4
