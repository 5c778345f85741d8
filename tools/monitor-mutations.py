#!/usr/bin/env python3
"""Mutation check of the invariant monitor (crates/physics/src/check).

For each check of the monitor: disable it in the source (one literal replacement), run the
test of `check/tests.rs` that breaks exactly that rule, and expect it to FAIL; then restore the
file. Also runs every test unmutated first, expecting it to pass. Exits non-zero if any
mutation survives (its test still passes) or the source no longer matches a pattern.

Not part of `.ci/run` (one release rebuild of billiards-physics per mutation, about ten
minutes in all on the 2-core machine). Run from the repository root:

    python3 tools/monitor-mutations.py            # every mutation
    python3 tools/monitor-mutations.py jump       # those whose name contains "jump"

Uses CARGO_TARGET_DIR if set. The source files are restored even if interrupted.
"""

import os
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
MOD = "crates/physics/src/check/mod.rs"
MEASURE = "crates/physics/src/check/measure.rs"

# (name, file, text, replacement, the test expected to fail with it)
MUTATIONS = [
    ("non-finite", MOD, "if !finite {", "if false {", "a_nan_in_a_state_is_non_finite"),
    (
        "time-back",
        MOD,
        "if t.is_nan() || t < self.last_time {",
        "if false {",
        "an_event_before_the_last_is_time_going_back",
    ),
    (
        "overlap",
        MOD,
        "if depth > self.tol.overlap {",
        "if false {",
        "balls_passing_through_each_other_between_events_overlap",
    ),
    (
        "outside",
        MOD,
        "if by > self.tol.outside {",
        "if false {",
        "a_ball_through_a_cushion_is_outside",
    ),
    (
        "jaw",
        MEASURE,
        "worst = worst.max(radius + rho - (p - j.centre).length());",
        "let _ = (j, rho);",
        "a_ball_inside_a_pocket_jaw_is_outside",
    ),
    (
        "jump",
        MOD,
        "if by > self.tol.jump && ",
        "if false && ",
        "an_event_that_moves_a_ball_is_a_jump",
    ),
    (
        "energy-at-event",
        MOD,
        "self.energy_check(e_before, e_after, rounding",
        "self.energy_check(e_before, e_before, rounding",
        "an_event_that_speeds_a_ball_up_gains_energy",
    ),
    (
        "energy-between-events",
        MOD,
        "self.energy_check(self.energy, e_before, rounding",
        "self.energy_check(e_before, e_before, rounding",
        "a_segment_that_speeds_a_ball_up_gains_energy_between_events",
    ),
    (
        "momentum",
        MOD,
        "if change > self.tol.momentum {",
        "if false {",
        "a_ball_contact_that_loses_momentum_breaks_momentum",
    ),
    (
        "event-cap",
        MOD,
        "if count == cap && sim.next_event_time().is_some() {",
        "if false {",
        "a_run_longer_than_the_cap_hits_the_event_cap",
    ),
    (
        "moving-forever",
        MOD,
        ".find(|&i| sim.ball(i).motion.is_moving())",
        ".find(|_| false)",
        "a_ball_moving_with_nothing_pending_moves_forever",
    ),
]


def run_test(name):
    """Runs one test of the monitor; True if it passed, False if it ran and failed. A build
    error or a missing test stops the script: neither says anything about the check."""
    cmd = [
        "cargo", "test", "--release", "-q", "-p", "billiards-physics", "--lib",
        f"check::tests::{name}", "--", "--exact",
    ]
    r = subprocess.run(cmd, cwd=ROOT, capture_output=True, text=True)
    if "running 1 test" not in r.stdout:
        sys.exit(f"test {name} did not run:\n{r.stderr[-3000:]}")
    if r.returncode != 0 and "test result: FAILED" not in r.stdout:
        sys.exit(f"test {name} broke without failing:\n{r.stdout[-3000:]}{r.stderr[-3000:]}")
    return r.returncode == 0


def main():
    wanted = sys.argv[1:]
    chosen = [m for m in MUTATIONS if not wanted or any(w in m[0] for w in wanted)]
    survived = []
    for name, path, text, repl, test in chosen:
        f = ROOT / path
        source = f.read_text()
        if source.count(text) != 1:
            sys.exit(f"{name}: `{text}` is not in {path} exactly once; update the mutation")
        if not run_test(f"{test}"):
            sys.exit(f"{name}: {test} fails unmutated")
        try:
            f.write_text(source.replace(text, repl))
            passed = run_test(test)
        finally:
            f.write_text(source)
        verdict = "SURVIVED (the test still passes)" if passed else "killed (the test fails)"
        print(f"{name:22} {test}: {verdict}", flush=True)
        if passed:
            survived.append(name)
    if survived:
        sys.exit(f"mutations not caught: {', '.join(survived)}")
    print(f"all {len(chosen)} mutations caught")


if __name__ == "__main__":
    os.environ.setdefault("CARGO_TERM_COLOR", "never")
    main()
