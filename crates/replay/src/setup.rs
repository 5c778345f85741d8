//! What every `simulate` run shares, free shots, a game (`game.rs`) or a frame: the table,
//! physics, balls and shots its options set up, the cue ball's respot after a scratch, and a
//! shot's summary. Apart from the dispatcher (`simulate.rs`), which the games need not import
//! back (issue 50).

use crate::args::*;
use crate::flight::FlightEvent;
use billiards_physics::recording::Recorder;
use billiards_physics::scene::{Scene, SceneFlight};
use billiards_physics::*;
use serde::Serialize;

/// The command line's shots, each at its own cue elevation, else at `--elevation`'s.
pub(crate) fn command_line_shots(a: &SimulateArgs) -> impl Iterator<Item = Shot> + '_ {
    a.shots.iter().map(|s| Shot {
        elevation: s.elevation.unwrap_or(a.elevation),
        ..s.shot
    })
}

/// One shot's outcome.
#[derive(Serialize, Debug)]
pub struct ShotSummary {
    /// The shot.
    pub shot: Shot,
    /// Events it produced.
    pub events: usize,
    /// Numbers of the balls it pocketed.
    pub pocketed: Vec<u8>,
    /// Seconds of simulated time until everything rested.
    pub time_to_rest: f64,
    /// Take-offs, bounces, landings and flights off the table (none for a shot that stays
    /// on the cloth).
    pub flight: Vec<FlightEvent>,
    /// The rules' judgement (with `--game`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub judgement: Option<billiards_rules::Judgement>,
}

impl ShotSummary {
    /// The shot `shot` as `sim` played it from its event `first` (the strike) on: begun at
    /// `start` seconds with the balls `in_air` then ([`crate::flight::airborne`]), judged
    /// `judgement` if a game's rules judged it.
    pub(crate) fn of(
        shot: Shot,
        sim: &Simulation,
        (first, start, in_air): (usize, f64, Vec<bool>),
        judgement: Option<billiards_rules::Judgement>,
    ) -> Self {
        let events = &sim.history().events()[first..];
        let pocketed = events
            .iter()
            .filter_map(|e| match e.kind {
                EventKind::Pocketed { ball, .. } => Some(sim.numbers()[ball]),
                _ => None,
            })
            .collect();
        Self {
            shot,
            events: events.len(),
            pocketed,
            time_to_rest: sim.time() - start,
            flight: crate::flight::flight_events(events, sim.numbers(), start, in_air),
            judgement,
        }
    }
}

/// What a `simulate` run starts from: the table, physics, balls, the balls in the air (a
/// scene file's `flights`) and the shots.
pub(crate) type Start = (Table, Params, Vec<BallSetup>, Vec<SceneFlight>, Vec<Shot>);

/// The table, physics, balls and shots of `a`: a scene file's, or a standard rack's.
pub(crate) fn setup(a: &SimulateArgs) -> Result<Start, String> {
    let randomization = a.seed.map(|seed| Randomization {
        spread: 0.005,
        seed,
    });
    if let Some(path) = &a.scene {
        let text = std::fs::read_to_string(path).map_err(|e| format!("{}: {e}", path.display()))?;
        let scene = Scene::from_json(&text).map_err(|e| format!("{}: {e}", path.display()))?;
        let params = with_choices(
            Params {
                randomization: randomization.or(scene.params.randomization),
                ..scene.params
            },
            a,
        )?;
        let shots = scene
            .shots
            .iter()
            .map(|s| s.shot)
            .chain(command_line_shots(a))
            .collect();
        return Ok((scene.table, params, scene.balls(), scene.flights, shots));
    }
    let model = match a.model {
        ModelArg::Paper => Model::Paper(PaperModel::default()),
        ModelArg::Spin => Model::Spin(SpinModel::default()),
    };
    let table = match a.model {
        ModelArg::Paper => a.table.table(),
        ModelArg::Spin => a.table.table().with_jaws(0.015),
    };
    let params = with_choices(
        Params {
            model,
            randomization,
            ..Params::default()
        },
        a,
    )?;
    let rack = match a.rack {
        RackArg::PaperDefault => Rack::PaperDefault,
        RackArg::FifteenBall => Rack::FifteenBall,
        RackArg::Tight => Rack::Tight,
        RackArg::NineBall => Rack::NineBall,
    };
    Ok((
        table,
        params,
        rack.layout(&table, &params.ball),
        Vec::new(),
        command_line_shots(a).collect(),
    ))
}

/// `params` with the model choices of the command line applied: they need the spin model.
fn with_choices(params: Params, a: &SimulateArgs) -> Result<Params, String> {
    if a.ball_friction.is_none() && a.cushion.is_none() && a.end_mass.is_none() {
        return Ok(params);
    }
    let Model::Spin(mut m) = params.model else {
        return Err(
            "--ball-friction, --cushion and --end-mass need the spin model (--model spin)".into(),
        );
    };
    if let Some(kg) = a.end_mass {
        m.end_mass = Some(kg);
    }
    if let Some(friction) = a.ball_friction {
        m.ball_friction = match friction {
            BallFrictionArg::Constant => BallFriction::Constant,
            BallFrictionArg::SpeedDependent => BallFriction::ALCIATORE,
        };
    }
    if let Some(cushion) = a.cushion {
        m.cushion = match cushion {
            CushionArg::Han2005 => CushionModel::default(),
            CushionArg::Mathavan2010 => CushionModel::MATHAVAN_2010,
            CushionArg::Reflect => CushionModel::Reflect { e: 0.85 },
        };
    }
    Ok(Params {
        model: Model::Spin(m),
        ..params
    })
}

/// After a scratch the cue ball goes back on the head string: the rule of
/// [`billiards_rules::respot`], the same as the game's.
pub(crate) fn respot_cue_ball(rec: &mut Recorder) -> Result<(), String> {
    if rec.sim().ball(0).motion.on_table() {
        return Ok(());
    }
    let spot = billiards_rules::cue_ball_spot(rec.sim(), 0)
        .ok_or("no free place on the head string for the cue ball")?;
    rec.place(0, spot, Vec2::ZERO, Vec3::ZERO)
        .map_err(|e| e.to_string())
}
