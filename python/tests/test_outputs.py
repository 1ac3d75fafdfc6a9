"""The files Python writes, opened as the commands open theirs (docs/limits.md, "Files"): a trace
never overwrites the scene's file or the target, and a run refused leaves no file behind."""

import os
import shutil

import pytest

import datomsim

from conftest import REPOSITORY

ARCH = REPOSITORY / "scenes" / "paper-arch-hole1.json"
FOLLOW = {"goal": (6, 5, 2), "start": (0, 0, 2)}


def test_a_trace_onto_the_target_is_refused_and_the_target_kept(tmp_path):
    target = tmp_path / "t.json"
    shutil.copy(REPOSITORY / "scenes" / "reshape-heap.json", target)
    before = target.read_bytes()
    scene = datomsim.load_scene(str(REPOSITORY / "scenes" / "reshape-heap.json"))
    with pytest.raises(datomsim.Error, match="would overwrite the target it reads"):
        datomsim.run(scene, "reconfigure", target=str(target), trace=str(target))
    assert target.read_bytes() == before


def test_a_trace_onto_the_file_the_scene_was_loaded_from_is_refused(tmp_path):
    scene_file = tmp_path / "arch.json"
    shutil.copy(ARCH, scene_file)
    before = scene_file.read_bytes()
    scene = datomsim.load_scene(str(scene_file))
    with pytest.raises(datomsim.Error, match="would overwrite the scene it reads"):
        datomsim.run(scene, "follow-gradient", trace=str(scene_file), **FOLLOW)
    assert scene_file.read_bytes() == before


def test_an_empty_trace_name_is_refused_and_leaves_nothing(tmp_path):
    os.chdir(tmp_path)
    scene = datomsim.load_scene(str(ARCH))
    with pytest.raises(datomsim.Error, match="trace is an empty file name"):
        datomsim.run(scene, "follow-gradient", trace="", **FOLLOW)
    assert list(tmp_path.iterdir()) == []


def test_a_trace_is_written_whole(tmp_path):
    scene = datomsim.load_scene(str(ARCH))
    trace = tmp_path / "run.jsonl"
    result = datomsim.run(scene, "follow-gradient", trace=trace, **FOLLOW)
    assert result["trace"] == str(trace)
    assert '"datomsim-trace"' in trace.read_text().splitlines()[0]
    assert [p.name for p in tmp_path.iterdir()] == ["run.jsonl"]
