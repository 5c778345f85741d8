//! The benchmark program: `billiards-compare [--quick] [--out DIR]`; and
//! `billiards-compare scaling CSV [--out FILE.svg] [--other NAME]`, the plot of the physics
//! crate's `scaling` example table (issue 37, default `docs/scaling.svg`); and
//! `billiards-compare realism [--out DIR]`, the models against measurements (issue 24:
//! `throw.svg`, `cushion.svg`, `squirt.svg`, `swerve.svg` and the numbers of `docs/realism.md`, default `docs/realism`).
//!
//! Runs every solver on every scene, prints one line per configuration, writes
//! `results.csv` and `runtime_vs_error.svg` into `DIR` (default `target/compare`), and exits
//! non-zero if the exact solver's error anywhere exceeds 1e-9 m.

use billiards_compare::{bench, plot, realism as models, report, scaling as cost};
use std::path::PathBuf;
use std::process::ExitCode;
use std::time::Instant;

fn main() -> ExitCode {
    if std::env::args().nth(1).as_deref() == Some("realism") {
        return realism(std::env::args().skip(2).collect());
    }
    if std::env::args().nth(1).as_deref() == Some("scaling") {
        return scaling(std::env::args().skip(2).collect());
    }
    let mut quick = false;
    let mut out = PathBuf::from("target/compare");
    let mut args = std::env::args().skip(1);
    while let Some(a) = args.next() {
        match a.as_str() {
            "--quick" => quick = true,
            "--out" => match args.next() {
                Some(dir) => out = PathBuf::from(dir),
                None => return usage("--out needs a directory"),
            },
            "-h" | "--help" => {
                println!("usage: billiards-compare [--quick] [--out DIR]");
                return ExitCode::SUCCESS;
            }
            other => return usage(&format!("unknown argument {other}")),
        }
    }
    let settings = if quick {
        bench::Settings::quick()
    } else {
        bench::Settings::full()
    };
    let started = Instant::now();
    let report = match bench::run(&settings, |line| println!("{line}")) {
        Ok(r) => r,
        Err(e) => {
            eprintln!("benchmark failed: {e}");
            return ExitCode::FAILURE;
        }
    };
    if let Err(e) = write(&report, &out) {
        eprintln!("cannot write the results to {}: {e}", out.display());
        return ExitCode::FAILURE;
    }
    let worst = report.exact_max_error();
    println!(
        "wrote {}/results.csv and runtime_vs_error.svg in {:.1} s; exact solver's largest error {worst:.1e} m",
        out.display(),
        started.elapsed().as_secs_f64()
    );
    if worst > bench::EXACT_ERROR_LIMIT {
        eprintln!(
            "FAIL: the exact solver's error {worst:e} m exceeds {:e} m",
            bench::EXACT_ERROR_LIMIT
        );
        return ExitCode::FAILURE;
    }
    ExitCode::SUCCESS
}

fn write(report: &bench::Report, out: &std::path::Path) -> Result<(), Box<dyn std::error::Error>> {
    std::fs::create_dir_all(out)?;
    std::fs::write(out.join("results.csv"), report::csv(report))?;
    plot::draw(report, &out.join("runtime_vs_error.svg"))?;
    Ok(())
}

fn usage(msg: &str) -> ExitCode {
    eprintln!("{msg}\nusage: billiards-compare [--quick] [--out DIR]");
    ExitCode::from(2)
}

fn realism(args: Vec<String>) -> ExitCode {
    let out = match args.as_slice() {
        [] => PathBuf::from("docs/realism"),
        [flag, dir] if flag == "--out" => PathBuf::from(dir),
        _ => return usage("usage: billiards-compare realism [--out DIR]"),
    };
    let lines = match models::report() {
        Ok(l) => l,
        Err(e) => {
            eprintln!("realism: {e}");
            return ExitCode::FAILURE;
        }
    };
    for line in &lines {
        println!("{line}");
    }
    if let Err(e) = models::draw(&out) {
        eprintln!("cannot write the plots to {}: {e}", out.display());
        return ExitCode::FAILURE;
    }
    println!(
        "wrote {0}/throw.svg, {0}/cushion.svg, {0}/squirt.svg and {0}/swerve.svg",
        out.display()
    );
    ExitCode::SUCCESS
}

fn scaling(args: Vec<String>) -> ExitCode {
    let usage = || usage("usage: billiards-compare scaling CSV [--out FILE.svg] [--other NAME]");
    let Some(csv) = args.first() else {
        return usage();
    };
    let (mut out, mut other) = (PathBuf::from("docs/scaling.svg"), "c339665".to_owned());
    let mut rest = args[1..].iter();
    while let Some(a) = rest.next() {
        match (a.as_str(), rest.next()) {
            ("--out", Some(p)) => out = PathBuf::from(p),
            ("--other", Some(n)) => other = n.clone(),
            _ => return usage(),
        }
    }
    let rows = match std::fs::read_to_string(csv).map_err(|e| e.to_string()) {
        Ok(text) => cost::parse(&text),
        Err(e) => Err(e),
    };
    let rows = match rows {
        Ok(r) => r,
        Err(e) => {
            eprintln!("cannot read {csv}: {e}");
            return ExitCode::FAILURE;
        }
    };
    if let Err(e) = cost::draw(&rows, &other, &out) {
        eprintln!("cannot write {}: {e}", out.display());
        return ExitCode::FAILURE;
    }
    println!("wrote {}", out.display());
    ExitCode::SUCCESS
}
