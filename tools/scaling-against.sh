#!/usr/bin/env bash
# Builds the physics crate's `scaling` example at another commit (default: c339665, main before
# issue 37's work) beside this checkout, then runs this checkout's `scaling` against it, each
# measurement alternating between the two builds.
#   tools/scaling-against.sh [COMMIT] [-- ARGS FOR scaling]
set -euo pipefail
cd "$(dirname "$0")/.."
commit="${1:-c339665}"
shift || true
[ "${1:-}" = "--" ] && shift
base="${TMPDIR:-/tmp}/billiards-scaling-$commit"
if [ ! -d "$base" ]; then
  git worktree add --detach "$base" "$commit" >/dev/null
fi
# The example reads only API the older commit has: copy it there.
cp crates/physics/examples/scaling.rs "$base/crates/physics/examples/scaling.rs"
(cd "$base" && CARGO_TARGET_DIR="$base/target" cargo build --release -q -p billiards-physics --example scaling)
cargo build --release -q -p billiards-physics --example scaling
target="${CARGO_TARGET_DIR:-target}"
"$target/release/examples/scaling" --against "$base/target/release/examples/scaling" "$@"
