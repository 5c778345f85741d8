"""billiards_ray: billiards-cli's batch commands (tournament, breaks, soak, study) as Ray
tasks, one per shard, retried when they fail, merged bit for bit into one process's result.

``python -m billiards_ray tournament --games 100000 --shards 64`` on a laptop or, with
``--address auto``, on a Ray cluster. See tools/ray/README.md.
"""

from billiards_ray.runner import COMMANDS, RunError, ShardFailed, find_cli, run

__all__ = ["COMMANDS", "RunError", "ShardFailed", "find_cli", "run"]
