"""`python -m billiards_ray COMMAND ... --shards N`: see billiards_ray.runner."""

import sys

from billiards_ray.runner import main

sys.exit(main())
