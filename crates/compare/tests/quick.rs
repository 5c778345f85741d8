//! The quick mode of the benchmark, as CI runs it: every solver kind runs; the exact solver
//! stays within 1e-9 m of the closed form in the analytic scenes, and in every scene it
//! resolves each contact within 1e-9 m of touching, never tunnels, overlaps or loses a ball.
//!
//! What the chaotic scenes ("billiard", "break", "elastic-break") can and cannot show: they
//! have no closed form, so their position "error" is the spread of runs started one rounding
//! error apart, and the horizon is chosen where that spread is still under
//! `bench::HORIZON_ERROR` (1e-10 m): below the limit by construction. Their contact counts
//! are matched against a rerun of the exact solver itself (a determinism check, not an
//! accuracy one). What can fail in them: the distance from touching at which each collision is
//! resolved, the diagnostics over the whole run (tunnelling, overlaps, balls off the table),
//! and, in the frictionless ones, half the error of running to the horizon and back again.

use billiards_compare::bench::{self, Settings, Solver};
use billiards_compare::scene::Reference;

#[test]
fn quick_mode_runs_every_solver_and_the_exact_solver_meets_the_closed_forms_to_a_nanometre() {
    let report = bench::run(&Settings::quick(), |_| {}).expect("the quick benchmark runs");
    for solver in Solver::ALL {
        assert!(
            report.rows.iter().any(|r| r.solver == solver),
            "{} did not run",
            solver.name()
        );
    }
    let names: Vec<&str> = report.scenes.iter().map(|s| s.name).collect();
    assert_eq!(names, ["stop", "cut", "billiard", "break", "elastic-break"]);
    // The analytic scenes, by name: the exact solver against the closed form, to 1e-9 m.
    let analytic: Vec<&str> = bench::scenes(true)
        .iter()
        .filter(|s| s.reference == Reference::Analytic)
        .map(|s| s.name)
        .collect();
    assert_eq!(analytic, ["stop", "cut"]);
    for name in analytic {
        let rows: Vec<_> = report
            .rows
            .iter()
            .filter(|r| r.solver == Solver::Exact && r.scene == name)
            .collect();
        // One call, measured against the closed form; per-frame calls, the same error plus
        // their difference from one call.
        let parameters: Vec<&str> = rows.iter().map(|r| r.parameter.as_str()).collect();
        assert_eq!(parameters, ["one call", "frames 1/60"], "{name}");
        assert_eq!(rows[0].note, "error against the closed form", "{name}");
        for r in rows {
            assert!(
                r.errors.position <= bench::EXACT_ERROR_LIMIT,
                "{name} ({}): {:e} m from the closed form",
                r.parameter,
                r.errors.position
            );
        }
    }
    // Every scene: the largest of the errors above, the chaotic scenes' estimates and the
    // distance from touching at which a collision was resolved.
    let worst = report.exact_max_error();
    assert!(
        worst <= bench::EXACT_ERROR_LIMIT,
        "exact solver error {worst:e} m"
    );
    for r in report.rows.iter().filter(|r| r.solver == Solver::Exact) {
        // Against a rerun of itself: the solver is deterministic and its diagnostics do not
        // change its contacts.
        assert_eq!(
            r.contacts.missed, 0,
            "{}: exact solver missed a contact of its own rerun",
            r.scene
        );
        assert_eq!(
            r.diagnostics.tunnelled, 0,
            "{}: exact solver tunnelled",
            r.scene
        );
        assert_eq!(
            r.diagnostics.overlaps, 0,
            "{}: exact solver overlapped",
            r.scene
        );
        assert_eq!(
            r.diagnostics.off_table, 0,
            "{}: exact solver lost a ball",
            r.scene
        );
    }
    // At a game's 1/60 s step, discrete detection lets break-speed balls pass through each
    // other; swept detection and the exact solver never do.
    let at_60 = |solver: Solver| {
        report
            .rows
            .iter()
            .filter(move |r| r.solver == solver && r.dt == Some(1.0 / 60.0))
    };
    assert!(at_60(Solver::EulerDiscrete).any(|r| r.diagnostics.tunnelled > 0));
    assert!(at_60(Solver::EulerSwept).all(|r| r.diagnostics.tunnelled == 0));
    let csv = billiards_compare::report::csv(&report);
    assert_eq!(csv.lines().count(), report.rows.len() + 1);
}
