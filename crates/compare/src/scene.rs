//! The benchmark scenes: the same table, model and starting layout for every solver.
//!
//! A strike is given as the cue ball's starting velocity, so every solver starts from exactly
//! the same state at `t = 0`.

use billiards_physics::{
    BallSetup, Model, PaperModel, Params, Rack, Table, Vec2, racks, sim::PLACEMENT_TOLERANCE,
};

/// How the exact solver's own error is estimated in a scene (every other solver is measured
/// against the exact solver).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Reference {
    /// A closed form exists: the exact solver is measured against it.
    Analytic,
    /// Chaotic: the exact solver's error is estimated by the divergence of a run whose start
    /// differs by one unit in the last place (what one rounding error does), and, for elastic
    /// frictionless scenes, by running to the horizon and back again.
    Chaotic,
}

/// One benchmark scene.
#[derive(Clone, Debug)]
pub struct Scene {
    /// Short name used in the CSV and the plot.
    pub name: &'static str,
    /// One line for the README.
    pub description: &'static str,
    /// The table (pockets closed by tiny mouths for the closed billiard).
    pub table: Table,
    /// Model and constants (always [`Model::Paper`]).
    pub params: Params,
    /// Starting layout and velocities.
    pub balls: Vec<BallSetup>,
    /// Time at which the run ends and outcomes are compared, seconds. `None`: when the exact
    /// solution comes to rest (rounded up to a sample time).
    pub end: Option<f64>,
    /// Interval between the sample times at which positions and energy are compared, seconds.
    /// Every fixed time step of the sweep divides it exactly.
    pub sample_interval: f64,
    /// Frictionless and elastic, so Rapier's rigid-body model matches the paper's.
    pub frictionless: bool,
    /// How the exact solver's own error is estimated.
    pub reference: Reference,
}

/// The paper's model with default constants and the given restitution and friction.
fn paper(mu_slide: f64, mu_roll: f64) -> Params {
    Params {
        model: Model::Paper(PaperModel {
            mu_slide,
            mu_roll,
            ..PaperModel::default()
        }),
        ..Params::default()
    }
}

/// The WPA table with pocket mouths too small for any ball to drop: a closed billiard.
pub fn closed_table() -> Table {
    Table {
        // A mouth of a nanometre: `pocket_at` can only fire for a centre within half a
        // nanometre of the side pocket's middle, which no trajectory hits exactly.
        corner_mouth: 1e-9,
        side_mouth: 1e-9,
        ..Table::wpa_8ft()
    }
}

/// One ball struck along the table's length from near the head cushion: slides, rolls and
/// stops in the open without touching a cushion. Closed form: stop after
/// `(v0^2 - vs^2) / (2 mu_s g) + vs^2 / (2 mu_r g)` metres.
pub fn stop() -> Scene {
    let table = Table::wpa_8ft();
    Scene {
        name: "stop",
        description: "one ball at 1.2 m/s slides, rolls and stops (closed form)",
        table,
        params: Params::default(),
        balls: vec![BallSetup::moving(
            0,
            Vec2::new(-0.9, 0.1),
            Vec2::from_angle(-0.05) * 1.2,
        )],
        end: None,
        sample_interval: 0.1,
        frictionless: false,
        reference: Reference::Analytic,
    }
}

/// Cut-shot geometry: the object ball sits `CUT_OFFSET` off the cue ball's line, a cut of
/// about 32 degrees.
pub const CUT_OFFSET: f64 = 0.03;

/// A cut shot: the cue ball at 1.5 m/s hits a resting object ball about 32 degrees off
/// centre; both roll out and stop in the open. Closed form (paper model, no cushion).
pub fn cut() -> Scene {
    let table = Table::wpa_8ft();
    Scene {
        name: "cut",
        description: "cue ball at 1.5 m/s cuts a resting ball at ~32 degrees; both stop (closed form)",
        table,
        params: Params::default(),
        balls: vec![
            BallSetup::moving(0, Vec2::new(-0.5, 0.0), Vec2::new(1.5, 0.0)),
            BallSetup::at(1, Vec2::new(0.2, CUT_OFFSET)),
        ],
        end: None,
        sample_interval: 0.1,
        frictionless: false,
        reference: Reference::Analytic,
    }
}

/// Sixteen balls at up to 3 m/s on a closed, frictionless table with elastic collisions: a
/// dynamical billiard, chaotic, with hundreds of collisions. `end` is the run length.
pub fn billiard(end: f64) -> Scene {
    let table = closed_table();
    let params = Params {
        max_events: 10_000_000,
        ..paper(0.0, 0.0)
    };
    let balls = racks::scattered(&table, &params.ball, 16, 3.0, 7);
    Scene {
        name: "billiard",
        description: "16 balls up to 3 m/s, frictionless, elastic, closed table (chaotic)",
        table,
        params,
        balls,
        end: Some(end),
        sample_interval: 0.1,
        frictionless: true,
        reference: Reference::Chaotic,
    }
}

/// Break speed, m/s (the reference's break range is 11–13 m/s).
pub const BREAK_SPEED: f64 = 11.0;

/// The paper's 15-ball rack (1/10 in gaps) broken at [`BREAK_SPEED`], slightly off the long
/// axis so that no two collisions are exactly simultaneous by symmetry; run until every ball
/// rests. Chaotic.
pub fn break_shot() -> Scene {
    let table = Table::wpa_8ft();
    let params = Params::default();
    let mut balls = Rack::FifteenBall.layout(&table, &params.ball);
    balls[0].velocity = Vec2::from_angle(0.002) * BREAK_SPEED;
    Scene {
        name: "break",
        description: "15-ball rack broken at 11 m/s, run to rest with pockets (chaotic)",
        table,
        params,
        balls,
        end: None,
        sample_interval: 0.1,
        frictionless: false,
        reference: Reference::Chaotic,
    }
}

/// The same rack broken at [`BREAK_SPEED`] on a closed table with no friction and elastic
/// collisions: the break as Rapier's model can play it, and the fastest collisions of any
/// scene. Chaotic. `end` is the run length.
pub fn elastic_break(end: f64) -> Scene {
    let table = closed_table();
    let params = Params {
        max_events: 10_000_000,
        ..paper(0.0, 0.0)
    };
    let mut balls = Rack::FifteenBall.layout(&table, &params.ball);
    balls[0].velocity = Vec2::from_angle(0.002) * BREAK_SPEED;
    Scene {
        name: "elastic-break",
        description: "the same break with no friction, no pockets, elastic (chaotic)",
        table,
        params,
        balls,
        end: Some(end),
        sample_interval: 0.1,
        frictionless: true,
        reference: Reference::Chaotic,
    }
}

impl Scene {
    /// The same scene with ball `id` moved across the table by one unit in the last place of
    /// a coordinate of order one metre (2.2e-16 m): what a single rounding error does.
    pub fn nudged(&self, id: usize) -> Scene {
        self.shifted(id, f64::EPSILON)
    }

    /// The same scene with ball `id` moved by `delta` metres across the table (along y).
    /// Across, not along: the cue ball moves along x in most scenes, and a shift along its
    /// path only shifts the whole solution in time. `delta` stays below the placement
    /// tolerance.
    pub fn shifted(&self, id: usize, delta: f64) -> Scene {
        debug_assert!(delta.abs() < PLACEMENT_TOLERANCE);
        let mut s = self.clone();
        s.balls[id].position.y += delta;
        s
    }

    /// The constants of the paper's model, which every scene uses.
    ///
    /// # Panics
    ///
    /// If the scene was given the spin model: the fixed-step integrators and the closed forms
    /// here implement the paper's model only.
    pub fn paper_model(&self) -> PaperModel {
        match self.params.model {
            Model::Paper(m) => m,
            Model::Spin(_) => panic!("scene {} uses the spin model", self.name),
        }
    }

    /// Ball radius, metres.
    pub fn radius(&self) -> f64 {
        self.params.ball.radius
    }

    /// Ball mass, kg.
    pub fn mass(&self) -> f64 {
        self.params.ball.mass
    }

    /// Half extents of the rectangle the centres may occupy.
    pub fn bounds(&self) -> Vec2 {
        self.table.centre_bounds(self.radius())
    }
}
