"""Runs one batch command of ``billiards-cli`` as shards on Ray and merges them.

Each shard is one Ray task that runs ``billiards-cli COMMAND ARGS --shard K/M --out FILE``
on a worker and returns the file's bytes through Ray's object store; the driver writes the
shard files into a work folder and runs ``billiards-cli COMMAND --merge`` on them. The CLI
refuses a merge of anything but exactly the M shards of one run, and the merged JSON equals
what one process writes (timing fields aside), so the cluster changes how long a run takes,
never its result.

Faults: a shard whose CLI exits non-zero (or is killed) raises in its task, and a task whose
worker process dies is lost; Ray runs either again, up to ``--max-retries`` times. A shard's
result only exists once its CLI finished: a retried shard starts from scratch, and a shard
counts once whatever its attempts.

Two environment variables inject faults for the tests, forwarded with every other
``BILLIARDS_*`` variable from the driver to the shards:

- ``BILLIARDS_FAIL_ONCE_DIR``: handled by the CLI: each shard's first run fails (exit 1);
- ``BILLIARDS_KILL_ONCE_DIR`` (with ``BILLIARDS_KILL_ONCE_SHARDS=K,K``, default every
  shard): the first attempt of a shard starts its CLI, then kills it and its own Ray worker
  with SIGKILL, as a machine lost mid-shard would.
"""

from __future__ import annotations

import argparse
import hashlib
import json
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import time
from pathlib import Path
from typing import Dict, List, Optional, Sequence, Tuple

COMMANDS = ("tournament", "breaks", "soak", "study")

#: Options of the CLI that belong to the merge, not to the shards (a shard's heat map would
#: be drawn on a worker and thrown away).
MERGE_ONLY = ("--svg",)

#: The CLI's name on PATH and in a shipped working folder.
CLI_NAME = "billiards-cli"


class ShardFailed(RuntimeError):
    """A shard's CLI exited non-zero or was killed."""


class RunError(RuntimeError):
    """The run cannot go on: bad arguments, no CLI, a shard out of retries, a refused merge."""


def find_cli(explicit: Optional[str] = None) -> str:
    """The CLI binary on this machine: ``explicit``, else ``$BILLIARDS_CLI``, else
    ``billiards-cli`` on PATH, else the repository's release build
    (``$CARGO_TARGET_DIR`` or ``target/``)."""
    candidates: List[Optional[str]] = [explicit, os.environ.get("BILLIARDS_CLI")]
    candidates.append(shutil.which(CLI_NAME))
    repo = Path(__file__).resolve().parents[3]
    target = os.environ.get("CARGO_TARGET_DIR")
    if target:
        candidates.append(str(Path(target) / "release" / CLI_NAME))
    candidates.append(str(repo / "target" / "release" / CLI_NAME))
    if explicit and os.path.isfile(explicit) and not os.access(explicit, os.X_OK):
        # A binary brought by a job's working_dir may arrive without its executable bit.
        os.chmod(explicit, os.stat(explicit).st_mode | 0o755)
    for c in candidates:
        if c and os.path.isfile(c) and os.access(c, os.X_OK):
            return os.path.abspath(c)
    if explicit:
        raise RunError(f"--cli {explicit}: not an executable file")
    raise RunError(
        f"no {CLI_NAME} found: give --cli PATH, set BILLIARDS_CLI, put it on PATH, or "
        "build it (cargo build --release -p billiards-replay)"
    )


def _kill_once(command: str, k: int, m: int, env: Dict[str, str]) -> bool:
    """Whether this attempt of shard k is the one the kill fault takes (first attempt only,
    marked by a file created atomically)."""
    folder = env.get("BILLIARDS_KILL_ONCE_DIR")
    if not folder:
        return False
    which = env.get("BILLIARDS_KILL_ONCE_SHARDS", "")
    if which and str(k) not in which.split(","):
        return False
    marker = os.path.join(folder, f"killed-{command}-{k}-of-{m}")
    try:
        os.close(os.open(marker, os.O_CREAT | os.O_EXCL | os.O_WRONLY))
    except FileExistsError:
        return False
    return True


def run_shard_here(
    cli: str,
    command: str,
    args: Sequence[str],
    k: int,
    m: int,
    env_extra: Dict[str, str],
    threads: int,
    shipped: Optional[bytes] = None,
) -> bytes:
    """Runs shard k of m with the CLI at ``cli`` and returns its JSON. A relative ``cli``
    is looked up in the working folder (where a job's ``runtime_env`` working_dir unpacks);
    with ``shipped`` (the binary's bytes, from the object store) ``cli`` is its digest and
    the binary is written once per machine into the temporary folder. Raises ShardFailed
    when the CLI does not finish cleanly."""
    if shipped is not None:
        cli = _unpack(shipped, cli)
    elif not os.path.isabs(cli) and os.path.exists(cli):
        cli = os.path.abspath(cli)
        # A shipped file may lose its executable bit on the way.
        os.chmod(cli, os.stat(cli).st_mode | 0o755)
    env = dict(os.environ)
    env.update(env_extra)
    # One CLI per task and `threads` CPUs per task: its thread pool matches.
    env["RAYON_NUM_THREADS"] = str(threads)
    with tempfile.TemporaryDirectory(prefix=f"billiards-{command}-{k}-") as d:
        out = os.path.join(d, f"{command}-{k}-of-{m}.json")
        argv = [cli, command, *args, "--shard", f"{k}/{m}", "--out", out]
        proc = subprocess.Popen(
            argv, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, env=env
        )
        if _kill_once(command, k, m, env):
            # Give the CLI a moment to get going (the result does not depend on how long),
            # then lose it and this worker, as a machine that dies mid-shard.
            try:
                proc.wait(timeout=0.2)
            except subprocess.TimeoutExpired:
                pass
            proc.kill()
            os.kill(os.getpid(), signal.SIGKILL)
        _, err = proc.communicate()
        if proc.returncode != 0:
            why = (
                f"killed by signal {-proc.returncode}"
                if proc.returncode < 0
                else f"exit status {proc.returncode}"
            )
            tail = err.decode(errors="replace").strip()[-2000:]
            raise ShardFailed(f"shard {k}/{m} of {command}: {why}: {tail}")
        with open(out, "rb") as f:
            return f.read()


def _unpack(binary: bytes, digest: str) -> str:
    """The shipped CLI on this machine: written once (atomically) under its digest."""
    path = os.path.join(tempfile.gettempdir(), f"{CLI_NAME}-{digest[:16]}")
    if not os.path.exists(path):
        fd, tmp = tempfile.mkstemp(dir=tempfile.gettempdir(), prefix=f"{CLI_NAME}-")
        with os.fdopen(fd, "wb") as f:
            f.write(binary)
        os.chmod(tmp, 0o755)
        os.replace(tmp, path)
    return path


def split_args(argv: Sequence[str]) -> Tuple[argparse.Namespace, List[str], List[str]]:
    """The runner's own options, the CLI arguments for the shards and those for the merge.

    Everything after COMMAND that is not one of the runner's options goes to the CLI as it
    is (so the CLI's own options and values pass through untouched)."""
    p = parser()
    own_flags = {a.option_strings[0]: a for a in p._actions if a.option_strings}
    if not argv or argv[0] in ("-h", "--help"):
        p.print_help()
        raise SystemExit(0)
    command, rest = argv[0], list(argv[1:])
    mine: List[str] = [command]
    shard_args: List[str] = []
    merge_args: List[str] = []
    i = 0
    while i < len(rest):
        tok = rest[i]
        name = tok.split("=", 1)[0]
        if name in own_flags:
            mine.append(tok)
            takes_value = own_flags[name].nargs != 0
            if takes_value and "=" not in tok:
                if i + 1 >= len(rest):
                    raise RunError(f"{tok} needs a value")
                mine.append(rest[i + 1])
                i += 1
        elif name in MERGE_ONLY:
            if "=" in tok:
                merge_args.extend(tok.split("=", 1))
            else:
                if i + 1 >= len(rest):
                    raise RunError(f"{tok} needs a value")
                merge_args.extend([tok, rest[i + 1]])
                i += 1
        elif name in ("--shard", "--merge"):
            raise RunError(f"{name}: the runner splits and merges; give --shards N")
        else:
            shard_args.append(tok)
        i += 1
    return p.parse_args(mine), shard_args, merge_args


def parser() -> argparse.ArgumentParser:
    """The runner's own options (every other argument goes to the CLI)."""
    p = argparse.ArgumentParser(
        prog="python -m billiards_ray",
        description=(
            "Run a billiards-cli batch command as shards on Ray, retry the ones that fail, "
            "merge them. Every argument that is not listed here goes to the CLI."
        ),
        allow_abbrev=False,
    )
    p.add_argument("command", choices=COMMANDS)
    p.add_argument("--shards", type=int, default=8, help="shards (Ray tasks), default 8")
    p.add_argument(
        "--out", help="write the merged JSON here (default: WORK_DIR/COMMAND.json)"
    )
    p.add_argument(
        "--cli",
        help="the CLI on this machine (default: $BILLIARDS_CLI, PATH, target/release)",
    )
    p.add_argument(
        "--worker-cli",
        help="the CLI's path on the workers (a shared folder; default: the same as --cli)",
    )
    p.add_argument(
        "--ship",
        action="store_true",
        help="ship the CLI to the workers through Ray's object store",
    )
    p.add_argument(
        "--runtime-env",
        help=(
            "the tasks' Ray runtime_env as JSON, e.g. "
            '\'{"working_dir": "s3://bucket/cli.zip"}\' with --worker-cli ./billiards-cli'
        ),
    )
    p.add_argument(
        "--address",
        help="a Ray cluster to join (e.g. auto, ray://head:10001); default: a local Ray",
    )
    p.add_argument(
        "--num-cpus", type=int, help="CPUs of the local Ray (default: all of them)"
    )
    p.add_argument("--cpus-per-task", type=int, default=1, help="CPUs a shard uses")
    p.add_argument(
        "--max-retries", type=int, default=3, help="retries of a failed shard (default 3)"
    )
    p.add_argument(
        "--work-dir", help="keep the shard files here (default: a temporary folder)"
    )
    p.add_argument(
        "--no-progress", action="store_true", help="no progress bar over the shards"
    )
    return p


def run(
    command: str,
    shard_args: Sequence[str],
    shards: int,
    *,
    merge_args: Sequence[str] = (),
    out: Optional[str] = None,
    cli: Optional[str] = None,
    worker_cli: Optional[str] = None,
    ship: bool = False,
    runtime_env: Optional[Dict[str, object]] = None,
    cpus_per_task: int = 1,
    max_retries: int = 3,
    work_dir: Optional[str] = None,
    progress: bool = True,
) -> Tuple[bytes, str]:
    """Runs ``command`` with ``shard_args`` as ``shards`` Ray tasks on the Ray this process
    is connected to (``ray.init`` first), merges them with the local CLI and returns the
    merged JSON and the CLI's report. ``runtime_env`` is the tasks' Ray runtime environment
    (a zipped working_dir holding the CLI, environment variables...). Raises RunError when a
    shard is out of retries or the merge is refused."""
    import ray
    from tqdm import tqdm

    if command not in COMMANDS:
        raise RunError(f"{command!r}: expected one of {', '.join(COMMANDS)}")
    if shards < 1:
        raise RunError("--shards must be at least 1")
    local_cli = find_cli(cli)
    options: Dict[str, object] = {
        "num_cpus": cpus_per_task,
        "max_retries": max_retries,
        "retry_exceptions": True,
    }
    if runtime_env:
        options["runtime_env"] = runtime_env
    shipped = None
    if ship:
        # The binary goes into the object store once; each machine's first task writes it
        # to its temporary folder under its digest (about 4 MB).
        binary = Path(local_cli).read_bytes()
        shipped = ray.put(binary)
        remote_cli = hashlib.sha256(binary).hexdigest()
    else:
        remote_cli = worker_cli or local_cli
    env_extra = {k: v for k, v in os.environ.items() if k.startswith("BILLIARDS_")}
    task = ray.remote(run_shard_here).options(**options)
    refs = {
        task.remote(
            remote_cli,
            command,
            list(shard_args),
            k,
            shards,
            env_extra,
            cpus_per_task,
            shipped,
        ): k
        for k in range(1, shards + 1)
    }
    folder = Path(work_dir or tempfile.mkdtemp(prefix=f"billiards-{command}-"))
    folder.mkdir(parents=True, exist_ok=True)
    files: List[str] = []
    pending = list(refs)
    bar = tqdm(
        total=shards, unit="shard", desc=command, disable=not progress, file=sys.stderr
    )
    try:
        while pending:
            done, pending = ray.wait(pending, num_returns=1)
            for ref in done:
                k = refs[ref]
                try:
                    data = ray.get(ref)
                except Exception as e:  # noqa: BLE001 - Ray wraps the task's error
                    for r in pending:
                        ray.cancel(r, force=True)
                    raise RunError(
                        f"shard {k}/{shards} failed after {max_retries} retries: {e}"
                    ) from e
                name = f"{command}-{k}-of-{shards}.json"
                (folder / name).write_bytes(data)
                files.append(name)
                bar.update(1)
    finally:
        bar.close()
    merged = (Path(out) if out else folder / f"{command}.json").resolve()
    merge_extra = list(merge_args)
    for i, arg in enumerate(merge_extra[:-1]):
        if arg in MERGE_ONLY:
            merge_extra[i + 1] = str(Path(merge_extra[i + 1]).resolve())
    # The shard files by their names in the work folder, so that thousands of them fit on
    # one command line.
    proc = subprocess.run(
        [local_cli, command, "--merge", *sorted(files), "--out", str(merged), *merge_extra],
        capture_output=True,
        text=True,
        cwd=folder,
    )
    if proc.returncode != 0:
        raise RunError(f"merge refused: {proc.stderr.strip()}")
    return merged.read_bytes(), proc.stdout


def main(argv: Optional[Sequence[str]] = None) -> int:
    """The command line: ``python -m billiards_ray COMMAND [CLI ARGS] --shards N ...``."""
    import ray

    try:
        a, shard_args, merge_args = split_args(
            list(sys.argv[1:] if argv is None else argv)
        )
    except RunError as e:
        print(f"error: {e}", file=sys.stderr)
        return 2
    try:
        runtime_env = json.loads(a.runtime_env) if a.runtime_env else None
    except json.JSONDecodeError as e:
        print(f"error: --runtime-env: not JSON: {e}", file=sys.stderr)
        return 2
    start = time.monotonic()
    if a.address:
        ray.init(address=a.address)
    else:
        ray.init(num_cpus=a.num_cpus)
    try:
        _, report = run(
            a.command,
            shard_args,
            a.shards,
            merge_args=merge_args,
            out=a.out,
            cli=a.cli,
            worker_cli=a.worker_cli,
            ship=a.ship,
            runtime_env=runtime_env,
            cpus_per_task=a.cpus_per_task,
            max_retries=a.max_retries,
            work_dir=a.work_dir,
            progress=not a.no_progress,
        )
    except RunError as e:
        print(f"error: {e}", file=sys.stderr)
        return 1
    finally:
        ray.shutdown()
    sys.stdout.write(report)
    print(
        f"{a.shards} shards in {time.monotonic() - start:.1f} s", file=sys.stderr
    )
    return 0
