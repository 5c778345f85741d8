//! The models against the measurements of `docs/realism.md`, each within the tolerance the
//! note states, and the plots written.

use billiards_compare::realism::{self, CushionCurve, Spin, data};
use billiards_physics::{BallFriction, SpinModel};

#[test]
fn mathavan_2010_meets_fig_7a_below_the_rigid_limit_within_3_percent_rms() {
    // docs/realism.md: rms 2.6 %, largest 4.5 % over the 12 points below 2.5 m/s.
    let f = realism::fig7a_fit(CushionCurve::Mathavan2010);
    assert!(f.rms_below < 0.03, "{f:?}");
    assert!(f.max_below < 0.05, "{f:?}");
    // Above the limit the rigid cushion over-predicts (the paper's own finding).
    assert!(f.rms_above > 0.05, "{f:?}");
}

#[test]
fn han_2005_and_reflection_lose_too_much_at_e_0_85_as_the_note_says() {
    // docs/realism.md: Han (e 0.85, mu 0.2) is 25.3 % rms below the measured rebound of a
    // rolling ball square in, reflection (e 0.85) 8.1 %; no e <= 1 brings Han up to it.
    //
    // Neither model has a rate, so each fit is that of one constant rebound ratio k (the
    // model's at any speed) to the measured points: rms over the points below the limit of
    // k vin / vout - 1. For reflection k = e = 0.85 by the law itself (an independent check
    // of the fit); for Han k is the model's own rebound at 1 m/s.
    let rms_of_ratio = |k: f64| {
        let rel: Vec<f64> = data::MATHAVAN_FIG7A
            .iter()
            .filter(|p| p.0 < data::MATHAVAN_RIGID_LIMIT)
            .map(|&(vin, vout)| k * vin / vout - 1.0)
            .collect();
        (rel.iter().map(|e| e * e).sum::<f64>() / rel.len() as f64).sqrt()
    };
    let han = realism::fig7a_fit(CushionCurve::Han2005);
    let k_han = CushionCurve::Han2005.rebound(1.0, 90.0, 1.0, 0.0).0;
    assert!(
        (han.rms_below - rms_of_ratio(k_han)).abs() < 1e-12,
        "{han:?}"
    );
    let reflect = realism::fig7a_fit(CushionCurve::Reflect);
    assert!(
        (reflect.rms_below - rms_of_ratio(0.85)).abs() < 1e-12,
        "{reflect:?}"
    );
    // Regression pins: the figures docs/realism.md quotes, from the code's own output (to the
    // note's rounding), so a change of the models or the data that changes the note fails.
    assert!((han.rms_below - 0.253).abs() < 5e-4, "{han:?}");
    assert!((reflect.rms_below - 0.081).abs() < 5e-4, "{reflect:?}");
    let (e, got, want) = realism::fit_e(CushionCurve::Han2005);
    assert!(e > 0.999 && got < want - 0.05, "{e} {got} {want}");
    let (e, got, want) = realism::fit_e(CushionCurve::Reflect);
    assert!((got - want).abs() < 1e-9 && (e - 0.923).abs() < 1e-3, "{e}");
}

#[test]
fn the_solvers_throw_follows_tp_a14_within_0_15_degrees() {
    // The solver (e 0.95) against TP A-14's closed form (e 1) with the same mu(v): equal
    // where friction limits the throw (rolling: to 1e-4 deg, the 1 um run-up), within
    // 0.13 deg where the no-reversal limit 1/7 does (stun, small cuts: the normal impulse is
    // 0.975 of e = 1's).
    let model = SpinModel {
        ball_friction: BallFriction::ALCIATORE,
        ..SpinModel::default()
    };
    for &(_, speed) in &data::ALCIATORE_SPEEDS {
        for cut in [5.0, 15.0, 30.0, 45.0, 60.0, 80.0] {
            for (roll, bound) in [(0.0, 0.15), (1.0, 1e-4)] {
                let spin = Spin { roll, english: 0.0 };
                let s = realism::solver_throw(model, speed, cut, spin).unwrap();
                let t = realism::tp_a14_throw(speed, cut, spin);
                assert!((s - t).abs() < bound, "{speed} {cut} {roll}: {s} vs {t}");
            }
        }
    }
    // Dr. Dave's "about 5 degrees" typical maximum: the slow stun peak is 5.3 deg.
    let peak = (20..45)
        .map(|c| {
            realism::solver_throw(
                model,
                0.447,
                f64::from(c),
                Spin {
                    roll: 0.0,
                    english: 0.0,
                },
            )
            .unwrap()
        })
        .fold(0.0, f64::max);
    assert!((peak - data::ALCIATORE_MAX_THROW.1).abs() < 0.7, "{peak}");
}

#[test]
fn the_plots_are_written() {
    let dir = std::env::temp_dir().join(format!("realism-{}", std::process::id()));
    realism::draw(&dir).unwrap();
    for name in ["throw.svg", "cushion.svg", "squirt.svg", "swerve.svg"] {
        let text = std::fs::read_to_string(dir.join(name)).unwrap();
        assert!(
            text.starts_with("<svg") && text.contains("polyline"),
            "{name}"
        );
        assert!(!text.to_lowercase().contains("nan"), "{name}");
    }
    std::fs::remove_dir_all(dir).ok();
}

#[test]
fn squirt_at_the_miscue_limit_spans_the_quoted_1_to_3_degrees() {
    // docs/realism.md: the two end masses give 2.77 and 1.48 deg at half a radius of english.
    let ball = billiards_physics::BallSpec::default().mass;
    let at = |m: f64| billiards_physics::resolve::cue::squirt_angle(0.5, ball / m).to_degrees();
    let (standard, low) = (at(realism::END_MASSES[0].1), at(realism::END_MASSES[1].1));
    assert!(
        (standard - 2.77).abs() < 0.01 && (low - 1.48).abs() < 0.01,
        "{standard} {low}"
    );
}

/// docs/realism.md: a centre-height hit with side `b` on a cue raised `theta` leaves the slide
/// heading `atan(b tan(theta))` towards the english (the slip's sideways part is
/// `(5/2) v b sin(theta)`, 2/7 of the slip is lost while sliding, 5/7 of `v cos(theta)` kept),
/// whatever the speed and the cloth's friction; 2.52, 5.20 and 8.21 degrees at half a tip.
#[test]
fn swerve_heading_is_atan_of_side_times_tan_elevation() {
    for (deg, quoted) in [(0.0, 0.0), (10.0, 2.52), (20.0, 5.20), (30.0, 8.21)] {
        for speed in [0.5, realism::SWERVE_SPEED, 6.0] {
            let p = realism::swerve_path(
                billiards_physics::SpinModel::default(),
                deg,
                realism::HALF_TIP,
                speed,
            )
            .unwrap();
            let want = -(realism::HALF_TIP * f64::to_radians(deg).tan())
                .atan()
                .to_degrees();
            assert!(
                (p.heading - want).abs() < 1e-9,
                "{deg} {speed}: {}",
                p.heading
            );
            assert!((-p.heading - quoted).abs() < 0.005, "{deg}: {}", p.heading);
            // The ball curves to the right and ends to the right of where it began to roll.
            let (_, y_end) = *p.points.last().unwrap();
            assert_eq!(y_end < p.rolls_at.y, deg > 0.0, "{deg}");
        }
    }
}
