//! Physical ranges of the numeric settings and the notes a clamp leaves.

use std::fmt;

use bevy::prelude::*;

/// The physical range of one parameter.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ParamRange {
    /// Name shown to the player.
    pub label: &'static str,
    /// Smallest allowed value.
    pub min: f64,
    /// Largest allowed value.
    pub max: f64,
    /// Unit suffix shown after the value ("" for dimensionless numbers).
    pub unit: &'static str,
}

impl ParamRange {
    /// Clamps `value` into the range, recording a note when it had to change it.
    /// A NaN (which no widget should produce) becomes the lower bound.
    pub fn clamp(&self, value: &mut f64, notes: &mut Vec<ClampNote>) {
        let applied = if value.is_nan() {
            self.min
        } else {
            value.clamp(self.min, self.max)
        };
        if applied != *value {
            notes.push(ClampNote {
                range: *self,
                requested: *value,
                applied,
            });
            *value = applied;
        }
    }

    /// The range as an inclusive `f64` range, for sliders.
    pub fn as_range(&self) -> std::ops::RangeInclusive<f64> {
        self.min..=self.max
    }
}

/// A value the player asked for that was outside its physical range, and what was used.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ClampNote {
    /// The parameter and its range.
    pub range: ParamRange,
    /// What was asked for.
    pub requested: f64,
    /// What is used instead.
    pub applied: f64,
}

impl fmt::Display for ClampNote {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let r = &self.range;
        write!(
            f,
            "{} {}{} is outside {}..{}{}: clamped to {}{}",
            r.label,
            short(self.requested),
            r.unit,
            r.min,
            r.max,
            r.unit,
            short(self.applied),
            r.unit
        )
    }
}

/// `v` as a player reads it: as written when short ("20", "-3.5", "NaN"), else to three
/// decimals ("95.502", not "95.50192516999994").
fn short(v: f64) -> String {
    let plain = v.to_string();
    if plain.len() <= 8 {
        plain
    } else {
        format!("{v:.3}")
    }
}

/// The clamp notes of the most recent edit, shown by the panel until the next clamp.
#[derive(Resource, Debug, Default, Clone, PartialEq)]
pub struct ClampReport {
    /// Notes of the last edit that needed clamping.
    pub notes: Vec<ClampNote>,
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Played (issue 52): a held key sent the elevation past its end and the note read
    /// "95.50192516999994 deg"; a long request is said to three decimals, a short one as
    /// written.
    #[test]
    fn a_clamp_note_says_a_long_request_to_three_decimals() {
        let range = ParamRange {
            label: "cue elevation",
            min: 0.0,
            max: 85.0,
            unit: " deg",
        };
        let note = |requested| {
            ClampNote {
                range,
                requested,
                applied: 85.0,
            }
            .to_string()
        };
        assert_eq!(
            note(95.50192516999994),
            "cue elevation 95.502 deg is outside 0..85 deg: clamped to 85 deg"
        );
        assert_eq!(
            note(90.0),
            "cue elevation 90 deg is outside 0..85 deg: clamped to 85 deg"
        );
    }
}
