//! The snooker table of the computer's studies: the WPBSA 12-ft table with
//! [`Params::snooker`]. Whole frames between players are matches of the one loop
//! ([`crate::match_record`]), as every game's are.

use billiards_physics::{Params, Table};

/// The snooker table and parameters: the WPBSA 12-ft table, [`Params::snooker`].
pub fn snooker_table() -> (Table, Params) {
    (Table::snooker_12ft(), Params::snooker())
}
