"""What Ray costs per shard: ``python -m billiards_ray.bench [--tasks N] [--num-cpus C]``.

Runs N shards of an empty soak (`--scenes 0`: the CLI starts, writes its JSON and exits)
three ways and prints the wall times: the CLI run N times in a row here, the same N shards
as Ray tasks on a local Ray of C CPUs (the runner's whole path: task, subprocess, result
through the object store, shard file, merge), and N empty Ray tasks. The runner's overhead
per shard is its time per shard times C, less the CLI's own start.
"""

from __future__ import annotations

import argparse
import subprocess
import time

import ray

from billiards_ray.runner import find_cli, run


@ray.remote
def _nothing() -> int:
    return 0


def main() -> None:
    p = argparse.ArgumentParser(prog="python -m billiards_ray.bench")
    p.add_argument("--tasks", type=int, default=64)
    p.add_argument("--num-cpus", type=int, default=2)
    p.add_argument("--cli")
    a = p.parse_args()
    cli = find_cli(a.cli)
    n, c = a.tasks, a.num_cpus

    t = time.monotonic()
    for k in range(1, n + 1):
        subprocess.run(
            [cli, "soak", "--scenes", "0", "--shard", f"{k}/{n}"],
            check=True,
            capture_output=True,
        )
    cli_each = (time.monotonic() - t) / n

    t = time.monotonic()
    ray.init(num_cpus=c, include_dashboard=False, log_to_driver=False)
    init = time.monotonic() - t
    # A first round warms the worker pool (workers start on demand).
    ray.get([_nothing.remote() for _ in range(4 * c)])
    t = time.monotonic()
    ray.get([_nothing.remote() for _ in range(n)])
    empty = (time.monotonic() - t) / n
    t = time.monotonic()
    run("soak", ["--scenes", "0"], n, cli=cli, progress=False)
    shard = (time.monotonic() - t) / n
    ray.shutdown()

    print(f"ray.init (local, {c} CPUs): {init:.2f} s")
    print(f"CLI start to exit, empty shard: {1e3 * cli_each:.1f} ms")
    print(f"empty Ray task: {1e3 * empty:.2f} ms wall each ({1e3 * empty * c:.2f} ms of a CPU)")
    print(
        f"runner, empty shard (task + CLI + object store + file + merge share): "
        f"{1e3 * shard:.1f} ms wall each, {1e3 * shard * c:.1f} ms of a CPU, "
        f"{1e3 * (shard * c - cli_each):.1f} ms beyond the CLI's own start"
    )


if __name__ == "__main__":
    main()
