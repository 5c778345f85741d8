//! The Play section and the name of the table on.

use bevy::prelude::*;
use bevy_egui::egui;

use super::param::SettingsParam;
use super::widgets::{apply_physics_edit, param_slider};
use crate::ui::layout::BUTTON_WIDTH;
use crate::{
    settings::{PhysicsSettings, table_choices, table_label},
    sim::{RACKS, RackRequested, StepRequested, clock_seed, rack_label},
    stress::StressMonitor,
    table::geometry::TableSpec,
};

/// The Play section: the time scale, the racks and the table.
pub(super) fn play_section(ui: &mut egui::Ui, state: &mut SettingsParam) {
    let mut next = *state.physics;
    param_slider(ui, &mut next.time_scale, PhysicsSettings::TIME_SCALE);
    ui.horizontal(|ui| {
        // One width for both labels: the button next to it stays where it is.
        let label = if next.paused { "Resume" } else { "Pause" };
        let size = egui::vec2(BUTTON_WIDTH, 0.0);
        if ui.add(egui::Button::new(label).min_size(size)).clicked() {
            next.paused = !next.paused;
        }
        let step = ui.add_enabled(
            next.paused,
            egui::Button::new("Step to next event").min_size(size),
        );
        if step.clicked() {
            state.steps.write(StepRequested);
        }
    });
    apply_physics_edit(next, state);
    ui.add_space(6.0);
    ui.label("New rack (asks first when a game is in progress):");
    let in_progress = state.solver.as_ref().is_some_and(|s| s.in_progress());
    egui::Grid::new("racks")
        .num_columns(2)
        .spacing([8.0, 4.0])
        .show(ui, |ui| {
            for (k, rack) in RACKS.into_iter().enumerate() {
                let button =
                    egui::Button::new(rack_label(rack)).min_size(egui::vec2(BUTTON_WIDTH, 0.0));
                if ui.add(button).clicked() {
                    if in_progress {
                        state.confirm.0 = Some(rack);
                    } else {
                        state.racks.write(RackRequested::fresh(rack, clock_seed()));
                    }
                }
                if k % 2 == 1 {
                    ui.end_row();
                }
            }
        });
    // Free play only: a match's table is chosen in its new-game dialog. Changing it racks the
    // same rack afresh on the new table.
    let free_play = state.referee.edits;
    ui.add_enabled_ui(free_play, |ui| {
        ui.horizontal(|ui| {
            ui.label("Table:");
            let mut table = state.setup.table;
            // The table really on (the stress table, snooker's, a recording's), not only the
            // pool table last chosen.
            egui::ComboBox::from_id_salt("free-play-table")
                .selected_text(table_in_play(table, &state.spec, &state.stress))
                .width(230.0)
                .show_ui(ui, |ui| {
                    for choice in table_choices() {
                        ui.selectable_value(&mut table, choice, table_label(choice));
                    }
                });
            if table != state.setup.table {
                state.setup.table = table;
            }
        });
    });
}

/// The name of the table on now, for the Play section: the stress table while `stress` says
/// it is on, else the table `spec` draws ([`table_on_label`]).
pub fn table_in_play(
    chosen: billiards_physics::TableChoice,
    spec: &TableSpec,
    stress: &StressMonitor,
) -> String {
    let on = stress
        .built
        .filter(|_| stress.active)
        .map(|built| (stress.table.0, stress.table.1, built.balls));
    table_on_label(chosen, spec, on)
}

/// The name of the table on, for the Play section: `stress` (length, width in metres, balls)
/// when the stress table is on ("stress table: 3.2 x 1.6 m, 300 balls"); the snooker table
/// ("12-ft snooker table"); the pool table `spec` draws, by its name when it is one of the
/// choices (`chosen` first: "8-ft, WPA pockets (4.5 in)"), else by its size.
pub fn table_on_label(
    chosen: billiards_physics::TableChoice,
    spec: &TableSpec,
    stress: Option<(f64, f64, usize)>,
) -> String {
    if let Some((length, width, balls)) = stress {
        return format!("stress table: {length:.1} x {width:.1} m, {balls} balls");
    }
    if spec.is_snooker() {
        return "12-ft snooker table".to_owned();
    }
    let same = |other: &TableSpec| {
        let close = |a: f64, b: f64| (a - b).abs() < 1e-6;
        close(other.length, spec.length)
            && close(other.width, spec.width)
            && close(other.corner_mouth, spec.corner_mouth)
            && close(other.side_mouth, spec.side_mouth)
    };
    std::iter::once(chosen)
        .chain(table_choices())
        .find(|&choice| same(&TableSpec::of(choice)))
        .map_or_else(
            || format!("{:.2} x {:.2} m table", spec.length, spec.width),
            table_label,
        )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::settings::table_label;
    use billiards_physics::{PocketCut, TableChoice, TableSize};

    /// Issue 48: the Play section named the chosen pool table ("8-ft, WPA pockets (4.5 in)")
    /// on the stress table and on the snooker table; it names the table really on.
    #[test]
    fn the_play_section_names_the_table_really_on() {
        let eight = TableChoice::default();
        assert_eq!(table_label(eight), "8-ft, WPA pockets (4.5 in)");
        let stress = table_on_label(eight, &TableSpec::default(), Some((3.2, 1.6, 300)));
        assert_eq!(stress, "stress table: 3.2 x 1.6 m, 300 balls");
        assert_eq!(
            table_on_label(eight, &TableSpec::snooker(), None),
            "12-ft snooker table"
        );
        assert_eq!(
            table_on_label(eight, &TableSpec::of(eight), None),
            "8-ft, WPA pockets (4.5 in)"
        );
        // A pool table other than the one chosen (a recording's): named as it is.
        let nine = TableChoice {
            size: TableSize::Nine,
            pockets: PocketCut::Tight,
        };
        assert_eq!(
            table_on_label(eight, &TableSpec::of(nine), None),
            table_label(nine)
        );
        assert!(table_label(nine).starts_with("9-ft"));
        // A table that is none of the choices: by its size.
        let odd = TableSpec {
            length: 2.0,
            width: 1.0,
            ..TableSpec::default()
        };
        assert_eq!(table_on_label(eight, &odd, None), "2.00 x 1.00 m table");
    }
}
