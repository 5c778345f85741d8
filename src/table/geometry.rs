//! Table dimensions and the mapping between physics and Bevy coordinates.
//!
//! Physics coordinates: x along the table length (head end at x = -L/2, foot end at +L/2),
//! y across (left = +y), z up, SI units, origin at the table centre on the cloth plane.
//! Bevy is y-up, so a physics point (x, y, z) is drawn at Bevy (x, z, -y); a ball centre at
//! table position p is drawn at (p.x, R, -p.y) so the ball sits on the cloth.

use bevy::math::{DVec2, DVec3, Vec3};
use bevy::prelude::Resource;
use billiards_physics::TableChoice;

/// Height of the cloth above the floor (WPA: 29.25-31 in).
pub const CLOTH_HEIGHT: f64 = 0.78;

/// One inch in metres: equipment specifications are in inches, everything else is SI.
pub const INCH: f64 = 0.0254;

/// Which side of the table a rail or cushion is on.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Rail {
    /// The long rail at +y (the player's left when standing at the head end).
    Left,
    /// The long rail at -y.
    Right,
    /// The short rail at x = -L/2, where the cue ball is placed.
    Head,
    /// The short rail at x = +L/2, behind the rack.
    Foot,
}

/// The game the table and its balls are made for: it decides the balls' look, the cloth's
/// marks and the pockets' jaws.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Hash)]
pub enum TableKind {
    /// A pool table with pool balls (head string, foot spot).
    #[default]
    Pool,
    /// The 12-ft snooker table with 52.5 mm balls (baulk line, D, spots; WPBSA 1.1).
    Snooker,
    /// The carom match table without pockets, 61.5 mm balls (UMB Art. 11-12; three-cushion).
    Carom,
}

impl TableKind {
    /// The kind of a solver's table: a pocketless table is a carom table, a table of the
    /// snooker size a snooker table (a recording stores the table, not the game).
    pub fn of(table: &billiards_physics::Table) -> Self {
        use billiards_physics::snooker::{SNOOKER_LENGTH, SNOOKER_WIDTH};
        if table.pockets == billiards_physics::PocketShape::Pocketless {
            Self::Carom
        } else if table.length == SNOOKER_LENGTH && table.width == SNOOKER_WIDTH {
            Self::Snooker
        } else {
            Self::Pool
        }
    }

    /// The balls played on this kind of table.
    pub fn ball(self) -> billiards_physics::BallSpec {
        match self {
            Self::Pool => billiards_physics::BallSpec::default(),
            Self::Snooker => billiards_physics::BallSpec::snooker(),
            Self::Carom => billiards_physics::BallSpec::carom(),
        }
    }
}

/// The two kinds of pocket, which differ in mouth width and jaw angle.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PocketKind {
    /// The four pockets at the corners.
    Corner,
    /// The two pockets in the middle of the long rails.
    Side,
}

/// A pocket: the hole in the bed a ball drops into.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Pocket {
    /// Corner or side.
    pub kind: PocketKind,
    /// Centre of the hole in the table plane.
    pub centre: DVec2,
    /// Radius of the hole.
    pub radius: f64,
}

/// A straight cushion between two pockets.
///
/// Its nose runs along the playing-surface edge from `start` to `end` (coordinates along the
/// rail); behind the nose each end is cut back by the jaw angle of the pocket it meets.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CushionSegment {
    /// The rail the cushion is mounted on.
    pub rail: Rail,
    /// Start of the nose, along the rail (x for long rails, y for short rails).
    pub start: f64,
    /// End of the nose, along the rail; `end > start`.
    pub end: f64,
    /// How far each end grows toward its pocket per metre of depth behind the nose.
    pub start_jaw_slope: f64,
    /// Same as `start_jaw_slope`, for the `end` side.
    pub end_jaw_slope: f64,
}

/// The dimensions of the pool table in play and its balls, in metres (by default the WPA
/// 8-ft table; [`TableSpec::of`] for the others).
#[derive(Resource, Debug, Clone, PartialEq)]
pub struct TableSpec {
    /// Playing-surface length between the cushion noses (92 in).
    pub length: f64,
    /// Playing-surface width between the cushion noses (46 in).
    pub width: f64,
    /// Ball radius (diameter 2.25 in).
    pub ball_radius: f64,
    /// Ball mass (5.5 oz).
    pub ball_mass: f64,
    /// Pool, snooker or carom.
    pub kind: TableKind,
    /// Corner pocket mouth, between the cushion noses (4.5 in).
    pub corner_mouth: f64,
    /// Side pocket mouth, between the cushion noses (5 in).
    pub side_mouth: f64,
    /// Height of the cushion nose above the cloth (63.5 % of the ball diameter).
    pub cushion_nose_height: f64,
    /// Height of the top of the cushions and rails above the cloth.
    pub rail_height: f64,
    /// Depth of the cushion rubber from the nose to the wooden rail.
    pub cushion_depth: f64,
    /// Width of the wooden rail behind the cushion.
    pub rail_width: f64,
    /// Angle between a corner cushion's face and its jaw (WPA: 142 degrees).
    pub corner_jaw_angle: f64,
    /// Angle between a side cushion's face and its jaw (WPA: 103-104 degrees).
    pub side_jaw_angle: f64,
}

impl Default for TableSpec {
    fn default() -> Self {
        Self::wpa_eight_foot()
    }
}

impl TableSpec {
    /// The WPA 8-ft table with regulation balls.
    pub fn wpa_eight_foot() -> Self {
        let ball_diameter = 2.25 * INCH;
        Self {
            length: 92.0 * INCH,
            width: 46.0 * INCH,
            ball_radius: ball_diameter / 2.0,
            ball_mass: billiards_physics::BallSpec::default().mass,
            kind: TableKind::Pool,
            corner_mouth: 4.5 * INCH,
            side_mouth: 5.0 * INCH,
            cushion_nose_height: 0.635 * ball_diameter,
            rail_height: 1.75 * INCH,
            cushion_depth: 2.0 * INCH,
            rail_width: 4.5 * INCH,
            corner_jaw_angle: 142f64.to_radians(),
            side_jaw_angle: 104f64.to_radians(),
        }
    }

    /// The table a player chose ([`TableChoice`]: 7, 8 or 9 ft, WPA, wide or tight pockets),
    /// with regulation balls, rails and jaw angles.
    pub fn of(choice: TableChoice) -> Self {
        Self::fitting(&choice.table())
    }

    /// The 12-ft snooker table ([`billiards_physics::Table::snooker_12ft`]) with 52.5 mm
    /// balls ([`billiards_physics::BallSpec::snooker`]).
    pub fn snooker() -> Self {
        Self::fitting(&billiards_physics::Table::snooker_12ft())
    }

    /// The carom match table ([`billiards_physics::Table::carom_match`], no pockets) with
    /// 61.5 mm balls ([`billiards_physics::BallSpec::carom`]).
    pub fn carom() -> Self {
        Self::fitting(&billiards_physics::Table::carom_match())
    }

    /// The table drawn for a solver's table (a recording's): its playing surface and pocket
    /// mouths, with regulation rails, and the balls of its kind ([`TableKind::of`]: a
    /// pocketless table is a carom table, a table of the snooker size a snooker table).
    pub fn fitting(table: &billiards_physics::Table) -> Self {
        let kind = TableKind::of(table);
        let pool = Self::wpa_eight_foot();
        let ball = kind.ball();
        Self {
            length: table.length,
            width: table.width,
            corner_mouth: table.corner_mouth,
            side_mouth: table.side_mouth,
            ball_radius: ball.radius,
            ball_mass: ball.mass,
            kind,
            // The cushion nose at 63.5 % of the ball's diameter, as on the pool table.
            cushion_nose_height: pool.cushion_nose_height * ball.radius / pool.ball_radius,
            ..pool
        }
    }

    /// The balls' size and mass.
    pub fn ball(&self) -> billiards_physics::BallSpec {
        billiards_physics::BallSpec {
            radius: self.ball_radius,
            mass: self.ball_mass,
        }
    }

    /// How many times the 8-ft table's outer length this table is, at least 1: what the camera
    /// and the lamps scale by to frame a larger table (the stress table).
    pub fn reach(&self) -> f32 {
        let eight = Self::wpa_eight_foot().outer_half_extents().x;
        (self.outer_half_extents().x / eight).max(1.0) as f32
    }

    /// Whether this is the snooker table.
    pub fn is_snooker(&self) -> bool {
        self.kind == TableKind::Snooker
    }

    /// Half the playing-surface length and width.
    pub fn half_extents(&self) -> DVec2 {
        DVec2::new(self.length / 2.0, self.width / 2.0)
    }

    /// The outer edge of the rails, measured from the table centre.
    pub fn outer_half_extents(&self) -> DVec2 {
        self.half_extents() + DVec2::splat(self.cushion_depth + self.rail_width)
    }

    /// The head spot: one quarter of the length from the head cushion, where the paper puts
    /// the cue ball.
    pub fn head_spot(&self) -> DVec2 {
        DVec2::new(-self.length / 4.0, 0.0)
    }

    /// The foot spot: one quarter of the length from the foot cushion, the apex of the rack.
    pub fn foot_spot(&self) -> DVec2 {
        DVec2::new(self.length / 4.0, 0.0)
    }

    /// Distance along each rail from a playing-surface corner to the corner cushion's nose
    /// end: the mouth is measured across the diagonal between the two noses.
    pub fn corner_nose_offset(&self) -> f64 {
        self.corner_mouth / std::f64::consts::SQRT_2
    }

    /// Whether the table has pockets (the carom table has none).
    pub fn has_pockets(&self) -> bool {
        self.kind != TableKind::Carom
    }

    /// The six pockets: head-left, head-right, foot-left, foot-right corners, then the left
    /// and right side pockets; none on the carom table.
    ///
    /// The holes are drawn slightly larger than the mouth and set behind it, leaving a
    /// shelf between the mouth line and the drop, as on a real table. (The physics decides
    /// pocketing on its own; these holes are what the player sees.)
    pub fn pockets(&self) -> Vec<Pocket> {
        if !self.has_pockets() {
            return Vec::new();
        }
        let h = self.half_extents();
        let corner_radius = 0.55 * self.corner_mouth;
        let corner_shelf = 0.5 * INCH;
        // The mouth midpoint lies a/2 inside the corner on both axes; the hole centre sits on
        // the diagonal so that the hole edge is one shelf behind the mouth line.
        let corner_offset = (corner_radius + corner_shelf) / std::f64::consts::SQRT_2
            - self.corner_nose_offset() / 2.0;
        let side_radius = 0.52 * self.side_mouth;
        let side_offset = side_radius + 0.25 * INCH;
        let corner = |sx: f64, sy: f64| Pocket {
            kind: PocketKind::Corner,
            centre: DVec2::new(sx * (h.x + corner_offset), sy * (h.y + corner_offset)),
            radius: corner_radius,
        };
        let side = |sy: f64| Pocket {
            kind: PocketKind::Side,
            centre: DVec2::new(0.0, sy * (h.y + side_offset)),
            radius: side_radius,
        };
        vec![
            corner(-1.0, 1.0),
            corner(-1.0, -1.0),
            corner(1.0, 1.0),
            corner(1.0, -1.0),
            side(1.0),
            side(-1.0),
        ]
    }

    /// The hole of one of the solver's pockets; `None` on a table without pockets.
    pub fn pocket(&self, pocket: billiards_physics::Pocket) -> Option<Pocket> {
        use billiards_physics::Pocket as P;
        let index = match pocket {
            P::HeadLeft => 0,
            P::HeadRight => 1,
            P::FootLeft => 2,
            P::FootRight => 3,
            P::SideLeft => 4,
            P::SideRight => 5,
        };
        self.pockets().get(index).copied()
    }

    /// The six cushions between the pockets; on the carom table four, each the full length
    /// of its rail.
    pub fn cushions(&self) -> Vec<CushionSegment> {
        let h = self.half_extents();
        if !self.has_pockets() {
            // Slope 1: each end grows by its depth, so neighbouring cushions meet on the
            // corner's diagonal (a 45-degree mitre) and the frame is closed.
            let full = |rail, half: f64| CushionSegment {
                rail,
                start: -half,
                end: half,
                start_jaw_slope: 1.0,
                end_jaw_slope: 1.0,
            };
            return vec![
                full(Rail::Left, h.x),
                full(Rail::Right, h.x),
                full(Rail::Head, h.y),
                full(Rail::Foot, h.y),
            ];
        }
        let corner_gap = self.corner_nose_offset();
        let side_gap = self.side_mouth / 2.0;
        // A jaw at angle `a` to the cushion face leaves the nose line at 180 deg - a, so each
        // metre of depth moves it 1 / tan(180 deg - a) toward the pocket.
        let corner_slope = 1.0 / (std::f64::consts::PI - self.corner_jaw_angle).tan();
        let side_slope = 1.0 / (std::f64::consts::PI - self.side_jaw_angle).tan();
        let long = |rail, start, end, start_jaw_slope, end_jaw_slope| CushionSegment {
            rail,
            start,
            end,
            start_jaw_slope,
            end_jaw_slope,
        };
        vec![
            long(
                Rail::Left,
                -h.x + corner_gap,
                -side_gap,
                corner_slope,
                side_slope,
            ),
            long(
                Rail::Left,
                side_gap,
                h.x - corner_gap,
                side_slope,
                corner_slope,
            ),
            long(
                Rail::Right,
                -h.x + corner_gap,
                -side_gap,
                corner_slope,
                side_slope,
            ),
            long(
                Rail::Right,
                side_gap,
                h.x - corner_gap,
                side_slope,
                corner_slope,
            ),
            long(
                Rail::Head,
                -h.y + corner_gap,
                h.y - corner_gap,
                corner_slope,
                corner_slope,
            ),
            long(
                Rail::Foot,
                -h.y + corner_gap,
                h.y - corner_gap,
                corner_slope,
                corner_slope,
            ),
        ]
    }

    /// A point on a rail in physics coordinates: `along` the rail, `depth` behind the cushion
    /// nose (outward), `height` above the cloth.
    pub fn rail_point(&self, rail: Rail, along: f64, depth: f64, height: f64) -> DVec3 {
        let h = self.half_extents();
        match rail {
            Rail::Left => DVec3::new(along, h.y + depth, height),
            Rail::Right => DVec3::new(along, -(h.y + depth), height),
            Rail::Head => DVec3::new(-(h.x + depth), along, height),
            Rail::Foot => DVec3::new(h.x + depth, along, height),
        }
    }

    /// Whether a table-plane point is a legal ball-centre position (on the cloth, clear of
    /// the cushions).
    pub fn contains_ball_centre(&self, p: DVec2) -> bool {
        let limit = self.half_extents() - DVec2::splat(self.ball_radius);
        p.x.abs() <= limit.x && p.y.abs() <= limit.y
    }

    /// The solver's table with these dimensions.
    pub fn physics_table(&self) -> billiards_physics::Table {
        let base = match self.kind {
            TableKind::Snooker => return billiards_physics::Table::snooker_12ft(),
            // The pocketless shape and zero mouths are the carom table's own.
            TableKind::Carom => billiards_physics::Table::carom_match(),
            TableKind::Pool => billiards_physics::Table {
                corner_mouth: self.corner_mouth,
                side_mouth: self.side_mouth,
                ..billiards_physics::Table::wpa_8ft()
            },
        };
        billiards_physics::Table {
            length: self.length,
            width: self.width,
            ..base
        }
    }

    /// Where a ball resting at table position `p` is drawn.
    pub fn ball_world_position(&self, p: DVec2) -> Vec3 {
        to_world(p.extend(self.ball_radius))
    }
}

/// Maps a physics point (x, y, z-up) to Bevy's y-up world: (x, z, -y).
///
/// The map is a proper rotation, so it keeps triangle winding and handedness.
pub fn to_world(p: DVec3) -> Vec3 {
    Vec3::new(p.x as f32, p.z as f32, -p.y as f32)
}

/// Maps a Bevy world point back to the physics table plane (drops the height).
pub fn to_table_plane(world: Vec3) -> DVec2 {
    DVec2::new(f64::from(world.x), -f64::from(world.z))
}

/// The Bevy world direction of a table-plane direction.
pub fn table_dir_to_world(d: DVec2) -> Vec3 {
    Vec3::new(d.x as f32, 0.0, -d.y as f32)
}

/// The D of a snooker table (WPBSA 1.1(e)) as a polyline of `segments` pieces: the half circle
/// behind the baulk-line, centred on the brown spot, from the green's corner to the yellow's.
pub fn d_outline(marks: &billiards_physics::SnookerMarks, segments: u32) -> Vec<DVec2> {
    let centre = DVec2::new(marks.brown.x, marks.brown.y);
    (0..=segments)
        .map(|k| {
            let a = std::f64::consts::FRAC_PI_2
                + std::f64::consts::PI * f64::from(k) / f64::from(segments);
            centre + marks.d_radius * DVec2::from_angle(a)
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn wpa_dimensions_in_metres() {
        let t = TableSpec::wpa_eight_foot();
        assert!((t.length - 2.3368).abs() < 1e-12);
        assert!((t.width - 1.1684).abs() < 1e-12);
        assert!((t.ball_radius - 0.028575).abs() < 1e-12);
        assert!((t.cushion_nose_height - 0.036290).abs() < 1e-5);
    }

    #[test]
    fn the_solver_table_has_the_same_dimensions() {
        let spec = TableSpec::default();
        assert_eq!(spec.physics_table(), billiards_physics::Table::wpa_8ft());
        let ball = billiards_physics::BallSpec::default();
        assert!((ball.radius - spec.ball_radius).abs() < 1e-15);
    }

    #[test]
    fn mapping_round_trips_and_keeps_left_on_plus_y() {
        let p = DVec2::new(0.5, 0.25);
        let w = to_world(p.extend(0.0));
        assert_eq!(w, Vec3::new(0.5, 0.0, -0.25));
        assert_eq!(to_table_plane(w), p);
        let t = TableSpec::default();
        assert_eq!(t.ball_world_position(DVec2::ZERO).y, t.ball_radius as f32);
    }

    #[test]
    fn corner_mouth_is_measured_between_the_noses() {
        let t = TableSpec::default();
        let h = t.half_extents();
        let cushions = t.cushions();
        // Foot-left corner: nose end on the left rail and on the foot rail.
        let a = DVec2::new(cushions[1].end, h.y);
        let b = DVec2::new(h.x, cushions[5].end);
        assert!((a.distance(b) - t.corner_mouth).abs() < 1e-12);
        // Left side pocket.
        assert!((cushions[1].start - cushions[0].end - t.side_mouth).abs() < 1e-12);
    }

    #[test]
    fn solver_pockets_map_to_the_holes_at_their_positions() {
        let spec = TableSpec::default();
        let table = spec.physics_table();
        for pocket in billiards_physics::Pocket::ALL {
            let corner = table.pocket_position(pocket);
            let hole = spec.pocket(pocket).unwrap();
            assert!(hole.centre.distance(DVec2::new(corner.x, corner.y)) < hole.radius + 0.01);
        }
    }

    #[test]
    fn pocket_holes_lie_behind_the_mouths() {
        let t = TableSpec::default();
        let h = t.half_extents();
        for pocket in t.pockets() {
            match pocket.kind {
                PocketKind::Corner => {
                    let corner =
                        DVec2::new(h.x.copysign(pocket.centre.x), h.y.copysign(pocket.centre.y));
                    // The hole covers the playing-surface corner but not the table centre.
                    assert!(pocket.centre.distance(corner) < pocket.radius);
                    assert!(pocket.centre.length() > h.length());
                }
                PocketKind::Side => {
                    assert_eq!(pocket.centre.x, 0.0);
                    assert!(pocket.centre.y.abs() - pocket.radius > h.y);
                }
            }
        }
    }

    #[test]
    fn a_pocketless_table_is_the_carom_table_with_four_full_cushions() {
        let table = billiards_physics::Table::carom_match();
        let spec = TableSpec::fitting(&table);
        assert_eq!(spec.kind, TableKind::Carom);
        assert_eq!(spec, TableSpec::carom());
        // UMB Art. 12: 61.5 mm balls, 210 g.
        assert!((spec.ball_radius - 0.03075).abs() < 1e-15);
        assert!((spec.ball_mass - 0.210).abs() < 1e-15);
        assert!(spec.pockets().is_empty());
        for pocket in billiards_physics::Pocket::ALL {
            assert_eq!(spec.pocket(pocket), None);
        }
        // UMB Art. 11: 2.84 x 1.42 m; each cushion's nose runs the whole rail.
        let cushions = spec.cushions();
        assert_eq!(cushions.len(), 4);
        for c in &cushions {
            let rail_length = match c.rail {
                Rail::Left | Rail::Right => 2.84,
                Rail::Head | Rail::Foot => 1.42,
            };
            assert!((c.end - c.start - rail_length).abs() < 1e-12, "{c:?}");
            assert!((c.start + c.end).abs() < 1e-12, "{c:?}: not centred");
        }
        let rails: Vec<Rail> = cushions.iter().map(|c| c.rail).collect();
        for rail in [Rail::Left, Rail::Right, Rail::Head, Rail::Foot] {
            assert!(rails.contains(&rail), "no cushion on {rail:?}");
        }
        // The solver's table round-trips, and no jaws are added to it.
        assert_eq!(spec.physics_table(), table);
    }

    #[test]
    fn pool_and_snooker_tables_keep_their_kind_and_six_pockets() {
        for (table, kind) in [
            (billiards_physics::Table::wpa_8ft(), TableKind::Pool),
            (billiards_physics::Table::snooker_12ft(), TableKind::Snooker),
        ] {
            let spec = TableSpec::fitting(&table);
            assert_eq!(spec.kind, kind);
            assert_eq!(spec.pockets().len(), 6);
            assert_eq!(spec.cushions().len(), 6);
            assert!(
                billiards_physics::Pocket::ALL
                    .iter()
                    .all(|&p| spec.pocket(p).is_some())
            );
        }
    }
}
