"""Hostile sweeps (docs/python.md, "Sweeps"; docs/limits.md): sizes counted before anything is
built, every key and value refused before anything runs, messages naming the file rather than
tracebacks, and no results file left behind by a sweep that fails."""

import json

import pytest

import datomsim
from datomsim import sweeps

SPEC = {
    "scenes": [{"generate": "box", "size": [2, 2, 1]}],
    "programs": [{"program": "flood", "root": [0, 0, 1]}],
    "seeds": [1],
}


def test_a_sweep_of_a_billion_runs_is_refused_before_any_is_built():
    huge = {**SPEC, "parameters": {"delay_ms": list(range(1000)), "jitter_ms": list(range(1000))},
            "seeds": {"from": 1, "count": 1000}}
    with pytest.raises(sweeps.SpecError, match="1,000,000,000 runs, more than the 1,000,000"):
        sweeps.cases(huge)
    with pytest.raises(sweeps.SpecError, match="seeds: count 10000000000"):
        sweeps.cases({**SPEC, "seeds": {"from": 1, "count": 10**10}})


@pytest.mark.parametrize("change, says", [
    ({"programs": [{"program": "flood", "colour": "red"}]}, "programs: unknown key colour"),
    ({"parameters": {"max_motion": [1, 2]}}, "parameters: unknown key max_motion"),
    ({"scenes": [{"generate": "box", "size": [2, 2, 1], "hole": 2}]},
     "scenes: generate box takes no key hole"),
    ({"parameters": {"max_motions": ["x"]}}, "parameters: max_motions \"x\": an integer"),
    ({"parameters": {"max_motions": {"a": 1}}}, "parameters: max_motions {\"a\": 1}: an integer"),
    ({"parameters": {"attachment": [1]}}, "parameters: attachment 1: true or false"),
    ({"programs": [{"program": 5}]}, "programs: program 5: a string"),
    ({"parameters": {"trace": True}}, "parameters: unknown key trace"),
    ({"seeds": {"from": "a", "count": 2}}, "seeds:"),
    ({"seeds": [1.5]}, "seeds:"),
])
def test_a_bad_key_or_value_is_refused_before_anything_runs(tmp_path, change, says):
    out = tmp_path / "out.csv"
    with pytest.raises(sweeps.SpecError) as raised:
        datomsim.sweep({**SPEC, **change}, str(out), workers=1)
    assert says in str(raised.value)
    assert not out.exists()


def test_a_sweep_that_fails_leaves_no_results_file(tmp_path, monkeypatch):
    out = tmp_path / "out.csv"

    def broken(*arguments, **keywords):
        raise RuntimeError("a worker died")

    monkeypatch.setattr(sweeps, "_results", broken)
    with pytest.raises(RuntimeError):
        datomsim.sweep(SPEC, str(out), workers=1)
    assert not out.exists()
    assert not list(tmp_path.iterdir())


@pytest.mark.parametrize("content, says", [
    (b"[" * 100000, "nested too deeply"),
    (b'{"scenes": "\xff\xfe"}', "not UTF-8"),
], ids=["nested", "latin-1"])
def test_a_malformed_spec_file_is_named_not_a_traceback(tmp_path, cli, content, says):
    spec = tmp_path / "spec.json"
    spec.write_bytes(content)
    refused = cli("sweep", spec, "-o", "out.csv")
    assert refused.returncode == 1
    assert "Traceback" not in refused.stderr
    assert f"datomsim sweep: error: {spec}: " in refused.stderr and says in refused.stderr
    assert not (tmp_path / "out.csv").exists()


def test_workers_zero_is_refused_in_a_few_words(tmp_path, cli):
    spec = tmp_path / "spec.json"
    spec.write_text(json.dumps(SPEC))
    refused = cli("sweep", spec, "-o", "out.csv", "--workers", "0")
    assert refused.returncode == 1
    assert refused.stderr.splitlines()[0] == \
        "datomsim: error: --workers: must be an integer >= 1, got 0"
