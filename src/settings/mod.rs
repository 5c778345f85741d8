//! Player-editable settings: the next shot and the physical parameters.
//!
//! The panels write these resources; the simulation reads them. Every numeric field has a
//! physical range and [`ShotSettings::clamp_to_physical`] / [`PhysicsSettings::clamp_to_physical`]
//! pull out-of-range values back into it and report what they changed, so the panel can say so.

mod physics;
mod range;
mod shot;
mod table;
mod view;

pub use physics::*;
pub use range::*;
pub use shot::*;
pub use table::*;
pub use view::*;

use bevy::prelude::*;

/// Registers the settings resources.
pub fn plugin(app: &mut App) {
    app.init_resource::<ShotSettings>()
        .init_resource::<PhysicsSettings>()
        .init_resource::<ViewSettings>()
        .init_resource::<GraphicsSettings>()
        .init_resource::<TableSetup>()
        .init_resource::<ClampReport>();
}

#[cfg(test)]
mod tests {
    use super::*;
    use billiards_physics::TipOffset;
    use std::f64::consts::TAU;

    #[test]
    fn defaults_are_inside_their_ranges() {
        assert!(PhysicsSettings::default().clamp_to_physical().is_empty());
        assert!(ShotSettings::default().clamp_to_physical().is_empty());
    }

    #[test]
    fn out_of_range_values_are_clamped_and_reported() {
        let mut settings = PhysicsSettings {
            mu_slide: 0.9,
            e_cushion: -1.0,
            ..default()
        };
        let notes = settings.clamp_to_physical();
        assert_eq!(settings.mu_slide, 0.4);
        assert_eq!(settings.e_cushion, 0.6);
        assert_eq!(notes.len(), 2);
        assert_eq!(notes[0].requested, 0.9);
        assert!(notes[0].to_string().contains("sliding friction"));
    }

    #[test]
    fn nan_is_replaced() {
        let mut shot = ShotSettings {
            elevation: 0.0,
            angle: f64::NAN,
            power: f64::NAN,
            tip: TipOffset {
                side: f64::NAN,
                height: 0.0,
            },
        };
        let notes = shot.clamp_to_physical();
        assert_eq!(shot.angle, 0.0);
        assert_eq!(shot.power, ShotSettings::POWER.min);
        assert_eq!(shot.tip.side, ShotSettings::TIP_SIDE.min);
        assert_eq!(notes.len(), 2);
    }

    #[test]
    fn a_tip_beyond_the_miscue_limit_is_pulled_back_along_its_direction() {
        let mut shot = ShotSettings {
            elevation: 0.0,
            tip: TipOffset {
                side: 0.4,
                height: -0.4,
            },
            ..default()
        };
        let notes = shot.clamp_to_physical();
        assert_eq!(notes.len(), 1);
        let limit = ShotSettings::tip_limit();
        assert!((shot.tip.side.hypot(shot.tip.height) - limit).abs() < 1e-12);
        assert!((shot.tip.side + shot.tip.height).abs() < 1e-12);
        assert!(notes[0].to_string().contains("tip offset"));
    }

    #[test]
    fn the_shown_angle_stays_below_a_full_turn() {
        assert_eq!(shown_degrees(TAU - 1e-9), 0.0);
        assert_eq!(shown_degrees(0.0), 0.0);
        assert_eq!(shown_degrees(std::f64::consts::PI), 180.0);
        assert_eq!(shown_degrees(359.99f64.to_radians()), 359.99);
        assert_eq!(shown_degrees(-1f64.to_radians()), 359.0);
    }

    #[test]
    fn angle_wraps_without_a_note() {
        let mut shot = ShotSettings {
            elevation: 0.0,
            angle: -std::f64::consts::FRAC_PI_2,
            power: 1.0,
            tip: TipOffset::default(),
        };
        assert!(shot.clamp_to_physical().is_empty());
        assert!((shot.angle - 1.5 * std::f64::consts::PI).abs() < 1e-12);
    }
}
