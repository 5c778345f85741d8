//! The solver's cost per event against the number of balls, and the break on each cushion
//! model, in one run (issue 37): one line per ball count of the frictionless gas (16, 100,
//! 1,000, 10,000, 100,000 balls on tables scaled to the same density, `racks::frictionless_gas`)
//! and the spin model's 9-ball break on Han 2005 and on Mathavan 2010.
//!
//! ```sh
//! cargo run --release -p billiards-physics --example scaling -- [--events N] [--csv FILE]
//!     [--against OTHER] [--million]
//! ```
//!
//! `--against OTHER` runs `OTHER` (this example built from another commit, see
//! `tools/scaling-against.sh`) for each measurement in turn with this one, so both columns come
//! from the same minutes of a noisy machine. Each figure is the best of three rounds.
//! Peak memory is the process's high-water mark (Linux `VmHWM`) after building the
//! 100,000-ball gas and running 20,000 of its events with the history off, over the balls.
//! `--million` adds a line for a gas of 1,000,000 balls (a tenth of the events, its set-up
//! taking seconds) and its peak memory, measured the same way in a process of its own.

use billiards_physics::*;
use std::process::Command;
use std::time::Instant;

const SIZES: [usize; 5] = [16, 100, 1000, 10_000, 100_000];

/// The size `--million` adds.
const MILLION: usize = 1_000_000;

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let value = |flag: &str| {
        args.iter()
            .position(|a| a == flag)
            .map(|i| args.get(i + 1).cloned().unwrap_or_default())
    };
    // `--one gas N` / `--one break han|mathavan`: one measurement, printed as a number (what
    // `--against` asks of the other build).
    if let Some(i) = args.iter().position(|a| a == "--one") {
        let what = (args.get(i + 1), args.get(i + 2));
        let events = value("--events")
            .and_then(|s| s.parse().ok())
            .unwrap_or(200_000);
        let ns = match what {
            (Some(k), Some(n)) if k == "gas" => n.parse().ok().map(|n| gas(n, events)),
            (Some(k), Some(c)) if k == "break" => cushion(c).map(break_us),
            (Some(k), Some(n)) if k == "memory" => n
                .parse()
                .ok()
                .map(|n| peak_memory_per_ball(n).unwrap_or(f64::NAN)),
            _ => None,
        };
        match ns {
            Some(x) => println!("{x}"),
            None => usage(),
        }
        return;
    }
    let events: usize = match value("--events").map(|s| s.parse()) {
        None => 200_000,
        Some(Ok(n)) if n >= 1000 => n,
        Some(_) => usage(),
    };
    let against = value("--against");
    let csv = value("--csv");
    if args.iter().any(|a| a == "-h" || a == "--help") {
        usage();
    }
    let memory = peak_memory_per_ball(100_000);
    let other = |what: &str| -> Option<f64> {
        let path = against.as_ref()?;
        let mut cmd = Command::new(path);
        cmd.arg("--one").args(what.split(' '));
        cmd.args(["--events", &events.to_string()]);
        let out = cmd.output().ok()?;
        String::from_utf8_lossy(&out.stdout).trim().parse().ok()
    };
    let best = |f: &dyn Fn() -> f64| (0..3).map(|_| f()).fold(f64::INFINITY, f64::min);
    let mut rows = Vec::new();
    let mut base = None;
    let million = args.iter().any(|a| a == "--million");
    let sizes = SIZES.iter().copied().chain(million.then_some(MILLION));
    for n in sizes {
        // Fewer events for the big gases, whose set-up (every ball predicted) is costly.
        let events = match n {
            MILLION => events / 10,
            100_000.. => events / 4,
            _ => events,
        };
        let (mut mine, mut theirs) = (f64::INFINITY, f64::INFINITY);
        for _ in 0..3 {
            mine = mine.min(gas(n, events));
            if let Some(x) = other(&format!("gas {n}")) {
                theirs = theirs.min(x);
            }
        }
        let b = *base.get_or_insert(mine);
        let vs = if theirs.is_finite() {
            format!(
                " (other build: {theirs:.0} ns, {:.2}x faster)",
                theirs / mine
            )
        } else {
            String::new()
        };
        println!(
            "{n:>6} balls: {mine:>5.0} ns/event, {:>4.2} M events/s, {:.2}x the 16-ball event{vs}",
            1e3 / mine,
            mine / b
        );
        rows.push((n, mine, theirs));
    }
    let mut breaks = Vec::new();
    for name in ["han", "mathavan"] {
        let model = cushion(name).expect("a known cushion");
        let mine = best(&|| break_us(model));
        let theirs = (0..3)
            .filter_map(|_| other(&format!("break {name}")))
            .fold(f64::INFINITY, f64::min);
        breaks.push((name, mine, theirs));
    }
    let han = breaks[0].1;
    for &(name, mine, theirs) in &breaks {
        let vs = if theirs.is_finite() {
            format!(" (other build: {theirs:.1} us)")
        } else {
            String::new()
        };
        println!(
            "9-ball break on {name:<8}: {mine:>6.1} us, {:.2}x the Han break{vs}",
            mine / han
        );
    }
    match memory {
        Some(bytes) => println!("peak memory: {bytes:.0} bytes a ball (100,000 balls)"),
        None => println!("peak memory: not measured (no /proc/self/status)"),
    }
    if million {
        // In a process of its own: the high-water mark of this one is already the largest
        // gas's.
        let me = std::env::current_exe().ok();
        let out = me.and_then(|me| {
            Command::new(me)
                .args(["--one", "memory", &MILLION.to_string()])
                .output()
                .ok()
        });
        let bytes = out.and_then(|o| String::from_utf8_lossy(&o.stdout).trim().parse().ok());
        match bytes.filter(|b: &f64| b.is_finite()) {
            Some(b) => println!("peak memory: {b:.0} bytes a ball (1,000,000 balls)"),
            None => println!("peak memory: not measured (1,000,000 balls)"),
        }
    }
    if let Some(path) = csv {
        let mut text = String::from("balls,ns_per_event,other_ns_per_event\n");
        for (n, mine, theirs) in rows {
            let theirs = if theirs.is_finite() {
                format!("{theirs:.1}")
            } else {
                String::new()
            };
            text += &format!("{n},{mine:.1},{theirs}\n");
        }
        if let Err(e) = std::fs::write(&path, text) {
            eprintln!("cannot write {path}: {e}");
            std::process::exit(1);
        }
    }
}

fn usage() -> ! {
    eprintln!(
        "usage: scaling [--events N (at least 1000)] [--csv FILE] [--against OTHER_BUILD] \
         [--million]"
    );
    std::process::exit(2);
}

/// Nanoseconds per event of a frictionless gas of `n` balls (history on, as in the game),
/// after a warm-up of a tenth as many events.
fn gas(n: usize, events: usize) -> f64 {
    let (table, params, balls) = racks::frictionless_gas(n);
    let mut sim = Simulation::new(table, params, &balls).expect("a valid gas");
    for _ in 0..events / 10 {
        sim.step_event();
    }
    let start = Instant::now();
    for _ in 0..events {
        sim.step_event();
    }
    start.elapsed().as_secs_f64() / events as f64 * 1e9
}

fn cushion(name: &str) -> Option<CushionModel> {
    match name {
        "han" => Some(SpinModel::default().cushion),
        "mathavan" => Some(CushionModel::MATHAVAN_2010),
        _ => None,
    }
}

/// Microseconds per 9-ball break of the spin model on `cushion` (cue ball on the head string
/// a quarter of the length from the centre, 8 m/s at the 1-ball, as `realism_cost`), over 200
/// breaks.
fn break_us(cushion: CushionModel) -> f64 {
    let table = Table::wpa_8ft();
    let params = Params {
        model: Model::Spin(SpinModel {
            cushion,
            ..SpinModel::default()
        }),
        ..Params::default()
    };
    let mut balls = Rack::NineBall.layout(&table, &params.ball);
    balls[0].position = Vec2::new(-0.25 * table.length, 0.1);
    let aim = (balls[1].position - balls[0].position).angle();
    let mut sim = Simulation::new(table, params, &balls).expect("a valid rack");
    sim.strike(0, Shot::new(aim, 8.0)).expect("a valid shot");
    let runs = 200;
    let start = Instant::now();
    for _ in 0..runs {
        let mut s = sim.clone();
        s.run_to_rest().expect("the break comes to rest");
    }
    start.elapsed().as_secs_f64() / runs as f64 * 1e6
}

/// The process's peak resident memory after building a gas of `n` balls and running 20,000
/// of its events with the history off, over `n`; `None` where `/proc` is not there.
fn peak_memory_per_ball(n: usize) -> Option<f64> {
    let hwm = || -> Option<f64> {
        let status = std::fs::read_to_string("/proc/self/status").ok()?;
        let line = status.lines().find(|l| l.starts_with("VmHWM:"))?;
        let kb: f64 = line.split_whitespace().nth(1)?.parse().ok()?;
        Some(kb * 1024.0)
    };
    let before = hwm()?;
    let (table, params, balls) = racks::frictionless_gas(n);
    let mut sim = Simulation::new(table, params, &balls).ok()?;
    sim.set_record_history(false);
    for _ in 0..20_000 {
        sim.step_event();
    }
    let after = hwm()?;
    drop(sim);
    Some((after - before) / n as f64)
}
