"""Ray in local mode (``ray.init(num_cpus=2)``): 8 shards merged equal one process bit for
bit (timing fields aside), a shard that fails or is killed is retried without changing the
result, and the merge refuses the wrong files.

Needs the release CLI: ``cargo build --release -p billiards-replay`` (found through
``$BILLIARDS_CLI``, ``$CARGO_TARGET_DIR`` or ``target/release``).
"""

from __future__ import annotations

import json
import os
import subprocess
from pathlib import Path

import pytest
import ray

from billiards_ray import RunError, find_cli, run

CLI = find_cli()

TOURNAMENT = ["--game", "nine-ball", "--players", "hard,greedy", "--games", "8", "--seed", "5"]
BREAKS = ["--breaks", "6", "--cue", "box,side", "--speed", "10:12,8", "--seed", "3"]
SOAK = ["--scenes", "40", "--first-seed", "7"]
STUDY = ["--grid", "8x4", "--samples", "6"]

#: Fields that time the run rather than record its result.
TIMING = {"decision_secs", "max_decision_secs"}


@pytest.fixture(scope="module", autouse=True)
def local_ray():
    ray.init(num_cpus=2, include_dashboard=False, log_to_driver=False)
    yield
    ray.shutdown()


@pytest.fixture(autouse=True)
def no_faults(monkeypatch):
    for k in [k for k in os.environ if k.startswith("BILLIARDS_") and k != "BILLIARDS_CLI"]:
        monkeypatch.delenv(k)


def one_process(command: str, args: list, tmp: Path) -> bytes:
    out = tmp / f"{command}-one.json"
    subprocess.run([CLI, command, *args, "--out", str(out)], check=True, capture_output=True)
    return out.read_bytes()


def without_timing(data: bytes):
    def strip(v):
        if isinstance(v, dict):
            return {k: strip(x) for k, x in v.items() if k not in TIMING}
        if isinstance(v, list):
            return [strip(x) for x in v]
        return v

    return strip(json.loads(data))


def on_ray(command: str, args: list, tmp: Path, **kw) -> bytes:
    data, report = run(command, args, 8, work_dir=str(tmp / f"{command}-shards"), progress=False, **kw)
    assert report
    return data


def test_tournament_on_8_shards_is_one_process(tmp_path):
    merged = on_ray("tournament", TOURNAMENT, tmp_path)
    whole = one_process("tournament", TOURNAMENT, tmp_path)
    assert without_timing(merged) == without_timing(whole)
    assert len(json.loads(merged)["matches"]) == 8


def test_breaks_on_8_shards_is_one_process_bit_for_bit(tmp_path):
    assert on_ray("breaks", BREAKS, tmp_path) == one_process("breaks", BREAKS, tmp_path)


def test_soak_and_study_on_8_shards_are_one_process_bit_for_bit(tmp_path):
    assert on_ray("soak", SOAK, tmp_path) == one_process("soak", SOAK, tmp_path)
    assert on_ray("study", STUDY, tmp_path) == one_process("study", STUDY, tmp_path)


def test_shards_that_fail_once_are_retried_and_the_result_is_unchanged(tmp_path, monkeypatch):
    marks = tmp_path / "failed"
    marks.mkdir()
    monkeypatch.setenv("BILLIARDS_FAIL_ONCE_DIR", str(marks))
    merged = on_ray("breaks", BREAKS, tmp_path, max_retries=1)
    # Every shard's CLI exited 1 once (its marker), then ran again.
    assert sorted(p.name for p in marks.iterdir()) == sorted(f"breaks-{k}-of-8" for k in range(1, 9))
    monkeypatch.delenv("BILLIARDS_FAIL_ONCE_DIR")
    assert merged == one_process("breaks", BREAKS, tmp_path)


def test_a_shard_killed_with_its_worker_is_retried_and_the_result_is_unchanged(tmp_path, monkeypatch):
    marks = tmp_path / "killed"
    marks.mkdir()
    monkeypatch.setenv("BILLIARDS_KILL_ONCE_DIR", str(marks))
    monkeypatch.setenv("BILLIARDS_KILL_ONCE_SHARDS", "3,6")
    merged = on_ray("tournament", TOURNAMENT, tmp_path, max_retries=2)
    assert sorted(p.name for p in marks.iterdir()) == ["killed-tournament-3-of-8", "killed-tournament-6-of-8"]
    monkeypatch.delenv("BILLIARDS_KILL_ONCE_DIR")
    assert without_timing(merged) == without_timing(one_process("tournament", TOURNAMENT, tmp_path))


def test_without_retries_a_killed_shard_fails_the_run(tmp_path, monkeypatch):
    marks = tmp_path / "killed"
    marks.mkdir()
    monkeypatch.setenv("BILLIARDS_KILL_ONCE_DIR", str(marks))
    monkeypatch.setenv("BILLIARDS_KILL_ONCE_SHARDS", "2")
    with pytest.raises(RunError, match="shard 2/8 failed after 0 retries"):
        on_ray("soak", SOAK, tmp_path, max_retries=0)


def test_the_cli_shipped_in_the_runtime_env_runs_the_shards(tmp_path):
    merged = on_ray("soak", SOAK, tmp_path, ship=True)
    assert merged == one_process("soak", SOAK, tmp_path)


def test_the_tasks_runtime_env_reaches_the_cli(tmp_path):
    # The fail-once hook set through the tasks' runtime_env, not the driver's environment.
    marks = tmp_path / "failed"
    marks.mkdir()
    env = {"env_vars": {"BILLIARDS_FAIL_ONCE_DIR": str(marks)}}
    merged = on_ray("soak", SOAK, tmp_path, runtime_env=env, max_retries=1)
    assert len(list(marks.iterdir())) == 8
    assert merged == one_process("soak", SOAK, tmp_path)


def test_the_merge_refuses_a_truncated_shard_another_command_or_another_seed_range(tmp_path):
    on_ray("breaks", BREAKS, tmp_path)
    shards = sorted((tmp_path / "breaks-shards").glob("breaks-*-of-8.json"))
    assert len(shards) == 8

    def merge(files):
        return subprocess.run([CLI, "breaks", "--merge", *map(str, files)], capture_output=True, text=True)

    cut = tmp_path / "cut.json"
    cut.write_bytes(shards[1].read_bytes()[:100])
    r = merge([cut if f == shards[1] else f for f in shards])
    assert r.returncode == 2 and "cut.json: truncated" in r.stderr

    soak = tmp_path / "soak.json"
    subprocess.run([CLI, "soak", *SOAK, "--shard", "2/8", "--out", str(soak)], check=True, capture_output=True)
    r = merge([soak if f == shards[1] else f for f in shards])
    assert r.returncode == 2 and "a result of `soak`, not of `breaks`" in r.stderr

    other = tmp_path / "other.json"
    args = [a if a != "3" else "4" for a in BREAKS]  # another seed: other seeds
    subprocess.run([CLI, "breaks", *args, "--shard", "2/8", "--out", str(other)], check=True, capture_output=True)
    r = merge([other if f == shards[1] else f for f in shards])
    assert r.returncode == 2 and "another run" in r.stderr and "seed" in r.stderr

    r = merge(shards[:-1] + [shards[0]])
    assert r.returncode == 2 and "the seeds overlap" in r.stderr
    r = merge(shards[:-1])
    assert r.returncode == 2 and "missing" in r.stderr
    assert merge(shards).returncode == 0


def test_the_runners_options_are_split_from_the_clis():
    from billiards_ray.runner import split_args

    a, shard_args, merge_args = split_args(
        ["study", "--samples", "5", "--shards=4", "--svg", "m.svg", "--tip", "-0.2:0", "--max-retries", "1"]
    )
    assert (a.command, a.shards, a.max_retries) == ("study", 4, 1)
    assert shard_args == ["--samples", "5", "--tip", "-0.2:0"]
    assert merge_args == ["--svg", "m.svg"]
    with pytest.raises(RunError, match="--shard: the runner splits"):
        split_args(["soak", "--shard", "1/2"])
