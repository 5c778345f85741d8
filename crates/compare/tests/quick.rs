//! The quick mode of the benchmark, as CI runs it: every solver kind runs, and the exact
//! solver's error stays below 1e-9 m on every scene.

use billiards_compare::bench::{self, Settings, Solver};

#[test]
fn quick_mode_runs_every_solver_and_the_exact_solver_stays_below_a_nanometre() {
    let report = bench::run(&Settings::quick(), |_| {}).expect("the quick benchmark runs");
    for solver in Solver::ALL {
        assert!(
            report.rows.iter().any(|r| r.solver == solver),
            "{} did not run",
            solver.name()
        );
    }
    assert_eq!(report.scenes.len(), 5);
    let worst = report.exact_max_error();
    assert!(
        worst <= bench::EXACT_ERROR_LIMIT,
        "exact solver error {worst:e} m"
    );
    for r in report.rows.iter().filter(|r| r.solver == Solver::Exact) {
        assert_eq!(
            r.contacts.missed, 0,
            "{}: exact solver missed a contact",
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
