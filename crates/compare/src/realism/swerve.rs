//! Squirt and swerve: where english sends the cue ball, the shots of `swerve.svg` and
//! `squirt.svg` and the lines of the report about them.

use billiards_physics::*;

/// Two shaft end masses for the squirt curves, kg: a standard maple shaft and a
/// low-deflection one (illustrative: about 3 and 1.5 degrees at half a radius of english, the
/// ends of the 1-3 degree range the issue quotes from Dr. Dave; no measured end masses were in
/// reach).
pub const END_MASSES: [(&str, f64); 2] = [
    ("standard shaft, 8 g", 0.008),
    ("low-deflection, 4 g", 0.004),
];

/// Half a tip of side english, in ball radii: 0.25 R (7.1 mm), about half a 13 mm tip's width
/// and half the 0.5 R miscue limit.
pub const HALF_TIP: f64 = 0.25;

/// Cue elevations of the swerve curves, degrees.
pub const SWERVE_ELEVATIONS: [f64; 4] = [0.0, 10.0, 20.0, 30.0];

/// Speed of the swerve shots along the cue, m/s (a medium shot).
pub const SWERVE_SPEED: f64 = 2.0;

/// A swerve shot's outcome: the cue ball's path and where it starts to roll.
#[derive(Clone, Debug, PartialEq)]
pub struct SwervePath {
    /// `(x, y)` in metres every 5 ms of the history until the ball rests.
    pub points: Vec<(f64, f64)>,
    /// Where the sliding (the curve) ends.
    pub rolls_at: Vec2,
    /// Heading once rolling, degrees from the cue line (negative: to the right).
    pub heading: f64,
}

/// The cue ball's path from a shot along +x at `elevation` degrees with right english `side`
/// (radii) and `speed` along the cue, on an open table (no cushion reached).
pub fn swerve_path(
    model: SpinModel,
    elevation: f64,
    side: f64,
    speed: f64,
) -> Result<SwervePath, String> {
    let params = Params {
        model: Model::Spin(model),
        ..Params::default()
    };
    let table = Table::scaled(20.0);
    let mut sim = Simulation::new(table, params, &[BallSetup::at(0, Vec2::ZERO)])
        .map_err(|e| e.to_string())?;
    let shot = Shot {
        tip: TipOffset { side, height: 0.0 },
        elevation: elevation.to_radians(),
        ..Shot::new(0.0, speed)
    };
    sim.strike(0, shot).map_err(|e| e.to_string())?;
    sim.run_to_rest().map_err(|e| e.to_string())?;
    let h = sim.history();
    let rolls = h
        .events()
        .iter()
        .find(|e| {
            matches!(
                e.kind,
                EventKind::Transition {
                    to: Motion::Rolling,
                    ..
                }
            )
        })
        .ok_or("the ball never rolled")?;
    let end = sim.time();
    let steps = (end / 0.005).ceil() as usize;
    let points = (0..=steps)
        .map(|k| {
            let p = h.state_at(0, end * k as f64 / steps as f64).position;
            (p.x, p.y)
        })
        .collect();
    Ok(SwervePath {
        points,
        rolls_at: rolls.after[0].position,
        heading: rolls.after[0].velocity.angle().to_degrees(),
    })
}

/// Lateral offset (m, negative to the right) of `path` where it crosses `x` metres downrange.
pub fn offset_at(path: &[(f64, f64)], x: f64) -> Option<f64> {
    path.windows(2).find_map(|w| {
        let ((x0, y0), (x1, y1)) = (w[0], w[1]);
        (x0 <= x && x <= x1 && x1 > x0).then(|| y0 + (y1 - y0) * (x - x0) / (x1 - x0))
    })
}
