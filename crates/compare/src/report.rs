//! The CSV of every measurement.

use crate::bench::Report;
use std::fmt::Write as _;

/// Column names of the CSV, in order.
pub const HEADER: &str = "scene,solver,parameter,dt_s,runtime_s,reps,simulated_s,checked_s,position_error_m,\
energy_error_rel,final_position_error_m,pocket_differences,contacts_exact,contacts_solver,\
missed_collisions,extra_collisions,tunnelled,overlaps,max_overlap_m,gap_contacts,max_contact_gap_m,\
off_table,note";

/// The report as CSV text, one row per solver configuration and scene.
pub fn csv(report: &Report) -> String {
    let mut out = String::from(HEADER);
    out.push('\n');
    for r in &report.rows {
        let dt = r.dt.map_or(String::new(), |d| format!("{d:e}"));
        // Notes may hold commas: quote them, doubling any quote inside.
        let note = format!("\"{}\"", r.note.replace('"', "\"\""));
        let _ = writeln!(
            out,
            "{},{},{},{},{:e},{},{:.3},{:.3},{:e},{:e},{:e},{},{},{},{},{},{},{},{:e},{},{:e},{},{}",
            r.scene,
            r.solver.name(),
            r.parameter,
            dt,
            r.runtime,
            r.reps,
            r.horizon,
            r.checked,
            r.errors.position,
            r.errors.energy,
            r.errors.final_position,
            r.errors.pocket_differences,
            r.contacts.reference,
            r.contacts.run,
            r.contacts.missed,
            r.contacts.extra,
            r.diagnostics.tunnelled,
            r.diagnostics.overlaps,
            r.diagnostics.max_overlap,
            r.diagnostics.gap_contacts,
            r.diagnostics.max_contact_gap,
            r.diagnostics.off_table,
            note,
        );
    }
    out
}
