//! Throw: the solver's object ball direction against TP A-14's closed form, the curves of
//! `throw.svg`.

use billiards_physics::*;

/// The cue ball's spin at contact.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Spin {
    /// Follow as a fraction of natural roll (1: rolling, 0: stun, negative: draw).
    pub roll: f64,
    /// Side spin as TP A-14's percent english (1.25 x this x v/R, the spin rate factor of
    /// TP ); positive is outside english, which lessens the sliding at the contact.
    pub english: f64,
}

/// Throw (degrees) of a still object ball hit at `cut` degrees by a cue ball at `speed` with
/// `spin`, from the solver: the two balls 1 um apart, run to their contact, the object ball's
/// velocity read after it. Positive throw is along the cue ball's tangential motion.
pub fn solver_throw(model: SpinModel, speed: f64, cut: f64, spin: Spin) -> Result<f64, String> {
    let params = Params {
        model: Model::Spin(model),
        ..Params::default()
    };
    let r = params.ball.radius;
    let phi = cut.to_radians();
    let n = Vec2::new(phi.cos(), phi.sin());
    let v = Vec2::new(speed, 0.0);
    // Rolling: w = (z x v) / R; english about z, its sign set so that outside english
    // lessens the tangential slip v sin(phi) - R w_z.
    let w = Vec3::new(0.0, spin.roll * speed / r, 1.25 * spin.english * speed / r);
    let cue = BallSetup {
        velocity: v,
        spin: w,
        ..BallSetup::at(0, Vec2::ZERO)
    };
    let object = BallSetup::at(1, Vec2::new(1e-6, 0.0) + n * (2.0 * r + 1e-9));
    let mut sim = Simulation::new(Table::wpa_8ft(), params, &[cue, object])
        .map_err(|e| format!("throw scene: {e}"))?;
    for _ in 0..100 {
        match sim.step_event() {
            Some(e) if matches!(e.kind, EventKind::BallBall { .. }) => {
                let vb = sim.ball(1).velocity;
                let t = Vec2::new(phi.sin(), -phi.cos());
                return Ok(vb.dot(t).atan2(vb.dot(n)).to_degrees());
            }
            Some(_) => {}
            None => break,
        }
    }
    Err(format!("no contact at cut {cut} deg, {speed} m/s"))
}

/// TP A-14's closed-form throw (degrees), e = 1, friction `mu(v_rel)` (Alciatore's fit):
/// `tan(throw) = min(mu v cos(phi) / v_rel, 1/7) (v sin(phi) - R w_z) / (v cos(phi))`.
pub fn tp_a14_throw(speed: f64, cut: f64, spin: Spin) -> f64 {
    let r = BallSpec::default().radius;
    let phi = cut.to_radians();
    let (wx, wz) = (spin.roll * speed / r, 1.25 * spin.english * speed / r);
    let side = speed * phi.sin() - r * wz;
    let v_rel = side.hypot(r * wx * phi.cos());
    if v_rel == 0.0 {
        return 0.0;
    }
    let mu = BallFriction::ALCIATORE.mu(0.0, v_rel);
    ((mu * speed * phi.cos() / v_rel).min(1.0 / 7.0) * side / (speed * phi.cos()))
        .atan()
        .to_degrees()
}
