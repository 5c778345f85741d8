//! The table in play and how its racks are set: chosen in the new-game dialog and the
//! free-play panel, kept in the settings file.

use bevy::prelude::*;
use billiards_physics::TableChoice;
use billiards_rules::RackStyle;
use serde::{Deserialize, Serialize};

/// The table (7, 8 or 9 ft; WPA, wide or tight pockets) and the rack style of the games on it
/// (a template: frozen; a triangle: seeded gaps of up to 0.1 mm).
#[derive(Resource, Debug, Clone, Copy, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(default)]
pub struct TableSetup {
    /// The table's size and pockets.
    pub table: TableChoice,
    /// How 8-ball and 9-ball racks are set.
    pub rack_style: RackStyle,
}

/// A table's name for the player: "9-ft, tight pockets".
pub fn table_label(choice: TableChoice) -> String {
    use billiards_physics::{PocketCut, TableSize};
    let size = match choice.size {
        TableSize::Seven => "7-ft",
        TableSize::Eight => "8-ft",
        TableSize::Nine => "9-ft",
    };
    let pockets = match choice.pockets {
        PocketCut::WpaWide => "wide pockets (4.625 in)",
        PocketCut::Wpa => "WPA pockets (4.5 in)",
        PocketCut::Tight => "tight pockets (4 in)",
    };
    format!("{size}, {pockets}")
}

/// A rack style's name for the player.
pub fn rack_style_label(style: RackStyle) -> &'static str {
    match style {
        RackStyle::Template => "template (frozen)",
        RackStyle::Triangle => "triangle (gaps to 0.1 mm)",
    }
}

/// Every table a player can choose, smallest first.
pub fn table_choices() -> impl Iterator<Item = TableChoice> {
    use billiards_physics::{PocketCut, TableSize};
    TableSize::ALL
        .into_iter()
        .flat_map(|size| PocketCut::ALL.map(|pockets| TableChoice { size, pockets }))
}
