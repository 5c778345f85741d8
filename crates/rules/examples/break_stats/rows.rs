//! One row of the table: a set of breaks played and printed.

use crate::options::Options;
use billiards_physics::TableChoice;
use billiards_rules::Game;
use billiards_rules::breaks::{BreakSpec, BreakStats, Cue, one_break, params_with, wilson};
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use std::time::Instant;

/// One set of breaks: a game on a table with a rack slack, the cue ball's place and the
/// aim's error (radians).
pub struct Setup {
    pub game: Game,
    pub table: TableChoice,
    pub gap: f64,
    pub label: String,
    pub cue: Cue,
    pub aim_sd: f64,
}

/// Plays the setup's breaks: `breaks` from each seed's own stream.
pub fn run(o: &Options, s: &Setup) -> BreakStats {
    let params =
        params_with(o.cushion, o.pairwise, &o.set).expect("--set values in the physical ranges");
    let spec = BreakSpec {
        game: s.game,
        table: s.table,
        gap: s.gap,
        cue: s.cue,
        speed: o.speed,
        aim_sd: s.aim_sd,
        tip_height: o.tip_height,
        elevation: o.elevation,
        nine_on_spot: o.nine_on_spot,
    };
    // One stream a seed for the whole row, as the published tables were made.
    let mut st = BreakStats::default();
    for seed in o.seed..o.seed + o.seeds.max(1) {
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        for _ in 0..o.breaks {
            st.add(&one_break(&spec, &params, &mut rng).expect("a break is played"));
        }
    }
    st
}

/// The table's header.
pub fn header() {
    println!(
        "| game | table | rack | >= 1 ball (95 %) | balls/break | scratch | legal | success | \
         9/8 on the break | events/break | s |"
    );
    println!("|---|---|---|---|---|---|---|---|---|---|---|");
}

/// Plays a setup and prints its row (rates with Wilson 95 % intervals).
pub fn row(o: &Options, s: &Setup) {
    let start = Instant::now();
    let st = run(o, s);
    let n = st.breaks.max(1) as f64;
    let pct = |k: usize| 100.0 * k as f64 / n;
    let (lo, hi) = wilson(st.with_ball, st.breaks);
    let (mean, half) = st.balls_per_break();
    println!(
        "| {} | {} | {} | {:.1} % ({lo:.1}–{hi:.1}) | {mean:.2} ± {:.2} | {:.1} % | {:.1} % | \
         {:.1} % | {:.1} % | {:.0} | {:.1} |",
        match s.game {
            Game::NineBall => "9-ball",
            Game::TenBall => "10-ball",
            Game::EightBall => "8-ball",
            Game::FreePlay => "free play",
        },
        s.table,
        s.label,
        pct(st.with_ball),
        half,
        pct(st.scratches),
        pct(st.legal),
        pct(st.success),
        pct(st.money_ball),
        st.events as f64 / n,
        start.elapsed().as_secs_f64()
    );
}

/// A rack gap in words.
pub fn gap_label(gap: f64) -> String {
    if gap == 0.0 {
        "frozen".into()
    } else {
        format!("slack {gap:e} m (gaps 0–{:e} m)", 2.0 * gap)
    }
}

/// The game's own table: 9-ft for 9-ball, 7-ft for 8-ball.
pub fn default_table(game: Game) -> TableChoice {
    let name = match game {
        Game::NineBall | Game::TenBall => "9ft",
        Game::EightBall | Game::FreePlay => "7ft",
    };
    name.parse().expect("a table name")
}
