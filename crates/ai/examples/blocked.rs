//! Hard at 9-ball with the 1 hidden (issue 52): seeded positions where a blocker stands
//! 10 to 40 cm from the cue ball on its line to the 1 and every straight path to the 1 is
//! blocked ([`billiards_ai::jump::hidden`]); hard decides each twice, as it is (jumps on)
//! and with the budget's jumps off (the computer before issue 52), and each decision is
//! played a number of times under hard's execution noise and judged by the rules. Printed:
//! how often the chosen shot was a jump, a kick or something else, and the share of all
//! executions that made a ball legally (kept the table or won) with a jump, with a kick and
//! overall, and the fouls.
//!
//! ```sh
//! cargo run --release -p billiards-ai --example blocked -- 150 52 10  # positions, seed, plays
//! ```

use billiards_ai::evaluate::Mode;
use billiards_ai::jump::hidden;
use billiards_ai::noise::stream;
use billiards_ai::play::{execute, table_and_params};
use billiards_ai::{Budget, Decision, Layout, Level, Plan, ShotKind, decide_planned};
use billiards_physics::{BallSetup, Simulation, Vec2};
use billiards_rules::{CueBall, Game, GameState, Seat};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use std::time::Instant;

/// A shot at this elevation or more is counted as a jump (a level shot's elevation noise is
/// a tenth of a degree).
const JUMP_DEGREES: f64 = 5.0;

/// Position `seed`: the cue ball, the 1 at least 60 cm away, the 2 between them 10 to 40 cm
/// from the cue ball (within half a radius of the line), the 9 and two to four of the 3 to 8
/// anywhere, every ball 1 cm clear of the others; `None` unless the 1 is then hidden.
fn position(seed: u64) -> Option<Vec<(u8, Vec2)>> {
    let (table, params) = table_and_params();
    let r = params.ball.radius;
    let b = table.centre_bounds(r);
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let anywhere = |rng: &mut ChaCha8Rng| {
        Vec2::new(
            rng.random_range(-b.x..b.x) * 0.95,
            rng.random_range(-b.y..b.y) * 0.95,
        )
    };
    let cue = anywhere(&mut rng);
    let one = anywhere(&mut rng);
    let dir = (one - cue).normalized()?;
    if (one - cue).length() < 0.6 {
        return None;
    }
    let d = rng.random_range(0.10..0.40);
    let off = rng.random_range(-0.5..0.5) * r;
    let blocker = cue + dir * d + dir.perp() * off;
    if blocker.x.abs() > b.x || blocker.y.abs() > b.y {
        return None;
    }
    let mut balls = vec![(0, cue), (1, one), (2, blocker)];
    let clear =
        |balls: &[(u8, Vec2)], p: Vec2| balls.iter().all(|q| (q.1 - p).length() > 2.0 * r + 0.01);
    if !clear(&balls[..2], blocker) {
        return None;
    }
    let extra = rng.random_range(2..=4);
    let mut others: Vec<u8> = vec![9];
    others.extend((3..=8).take(extra));
    for n in others {
        let p = (0..100)
            .map(|_| anywhere(&mut rng))
            .find(|&p| clear(&balls, p))?;
        balls.push((n, p));
    }
    let layout = Layout {
        table,
        radius: r,
        cue,
        balls: balls[1..].to_vec(),
    };
    hidden(&layout, &[1]).then_some(balls)
}

/// What came of one configuration's decisions.
#[derive(Default)]
struct Tally {
    decisions: usize,
    jumps: usize,
    kicks: usize,
    plays: usize,
    jump_plays: usize,
    kick_plays: usize,
    made_jump: usize,
    made_kick: usize,
    made: usize,
    fouls: usize,
    secs: f64,
}

/// The 9-ball state with `balls` (the cue ball first) on the table, the 1 on, A to shoot
/// where the cue ball lies.
fn state_of(balls: &[(u8, Vec2)]) -> GameState {
    let mut state = GameState::new(Game::NineBall, Seat::A);
    state.on_table = balls[1..].iter().map(|b| b.0).collect();
    state.on_table.sort_unstable();
    state.next.break_shot = false;
    state.next.cue_ball = CueBall::AsItLies;
    state.next.legal_first = vec![1];
    state
}

impl Tally {
    /// Plays `plan` (a jump or a kick as flagged) `plays` times on `sim` under hard's
    /// execution noise, streams `(seed, position, k)`, each judged on a copy of `state`.
    fn play(&mut self, plan: &Plan, (state, sim): (&GameState, &Simulation), seeds: [u64; 3]) {
        let [seed, position, plays] = seeds;
        let jump = plan.shot.elevation.to_degrees() >= JUMP_DEGREES;
        let kick = matches!(plan.kind, ShotKind::Kick { .. });
        self.decisions += 1;
        self.jumps += usize::from(jump);
        self.kicks += usize::from(kick);
        for k in 0..plays {
            let mut table = sim.clone();
            let exec_seed = stream(seed, position, k).random::<u64>();
            let noise = Level::Hard.execution_noise();
            let Ok(summary) = execute(&mut table, plan, noise, exec_seed) else {
                continue;
            };
            let mut after = state.clone();
            let Ok(verdict) = after.play(&summary, plan.call) else {
                continue;
            };
            let potted = summary.pocketed_object_balls().next().is_some();
            let made = verdict.legal() && potted;
            self.plays += 1;
            self.jump_plays += usize::from(jump);
            self.kick_plays += usize::from(kick);
            self.made += usize::from(made);
            self.made_jump += usize::from(made && jump);
            self.made_kick += usize::from(made && kick);
            self.fouls += usize::from(!verdict.legal());
        }
    }

    /// One line of figures under `name`.
    fn print(&self, name: &str) {
        let pct = |a: usize, b: usize| 100.0 * a as f64 / b.max(1) as f64;
        println!(
            "{name}: decisions {} (jump {}, kick {}), plays {}: made with a jump {:.1} % \
             ({:.1} % of the jumps), with a kick {:.1} % ({:.1} % of the kicks), overall \
             {:.1} %, fouls {:.1} %; {:.2} s a decision",
            self.decisions,
            self.jumps,
            self.kicks,
            self.plays,
            pct(self.made_jump, self.plays),
            pct(self.made_jump, self.jump_plays),
            pct(self.made_kick, self.plays),
            pct(self.made_kick, self.kick_plays),
            pct(self.made, self.plays),
            pct(self.fouls, self.plays),
            self.secs / self.decisions.max(1) as f64,
        );
    }
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let arg = |i: usize, d: u64| args.get(i).and_then(|s| s.parse().ok()).unwrap_or(d);
    let (count, seed, plays) = (arg(1, 150) as usize, arg(2, 52), arg(3, 10));
    let (table, params) = table_and_params();
    let mut positions = Vec::new();
    let mut drawn = 0u64;
    while positions.len() < count {
        if let Some(p) = position(seed.wrapping_mul(1_000_003).wrapping_add(drawn)) {
            positions.push(p);
        }
        drawn += 1;
    }
    let on = Level::Hard.budget();
    let off = Budget {
        jumps: None,
        ..on.clone()
    };
    let mut tallies = [Tally::default(), Tally::default()];
    for (i, balls) in positions.iter().enumerate() {
        let state = state_of(balls);
        let setups: Vec<BallSetup> = balls.iter().map(|&(n, p)| BallSetup::at(n, p)).collect();
        let mut sim = Simulation::new(table, params, &setups).expect("a valid layout");
        sim.set_record_history(false);
        for (tally, budget) in tallies.iter_mut().zip([&off, &on]) {
            let start = Instant::now();
            let noise = Level::Hard.planning_noise();
            let decision = decide_planned(&state, &sim, noise, budget, i as u64, Mode::Lean);
            tally.secs += start.elapsed().as_secs_f64();
            if let Ok(Decision::Shoot(plan)) = decision {
                tally.play(&plan, (&state, &sim), [seed, i as u64, plays]);
            }
        }
    }
    println!(
        "{count} hidden positions (seed {seed}, {drawn} drawn), {plays} plays of each decision"
    );
    tallies[0].print("jumps off (before)");
    tallies[1].print("jumps on (hard now)");
}
