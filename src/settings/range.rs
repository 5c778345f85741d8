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
            r.label, self.requested, r.unit, r.min, r.max, r.unit, self.applied, r.unit
        )
    }
}

/// The clamp notes of the most recent edit, shown by the panel until the next clamp.
#[derive(Resource, Debug, Default, Clone, PartialEq)]
pub struct ClampReport {
    /// Notes of the last edit that needed clamping.
    pub notes: Vec<ClampNote>,
}
