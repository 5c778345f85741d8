//! Where the balls stand: the spots of the carom table, the opening position (UMB 3.3,
//! Art. 23 of the 1989 edition), frozen balls and their re-spotting (Art. 27), balls off
//! the table set up again (Art. 28).
//!
//! Ends: the project's head (`-x`) is the UMB "bottom" of the table, its foot (`+x`) the "top".

use super::balls::Ball;
use super::error::ThreeCushionError;
use billiards_physics::{Table, Vec2};
use serde::{Deserialize, Serialize};

/// How far the two starting spots are from the bottom spot along the starting line: 182.5 mm
/// (UMB Art. 13, the marking of the spots; given as 7 3/16 in, 182.6 mm, by the general carom
/// rules of 14dot1.com, and as "18 cm to the left or right" by blueballinnsidford.co.uk).
pub const STARTING_SPOT_OFFSET: f64 = 0.1825;

/// A gap at or under which two balls count as in contact ("frozen"): 0.1 mm, below what a
/// referee's eye can tell and above the solver's resting-contact hops (1e-7 m).
pub const FROZEN_GAP: f64 = 1e-4;

/// Which of the two starting spots the striker's ball takes on the opening (UMB 3.3(c): "any
/// way the player wants on one of the two starting spots").
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Side {
    /// `+y`, left looking from the bottom (head) to the top (foot).
    Left,
    /// `-y`.
    #[default]
    Right,
}

/// The spots of a carom table (UMB Art. 13): on the long axis, a quarter of the length from
/// each short cushion and in the middle; and the two starting spots beside the bottom one.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Spots {
    /// The top spot (the foot spot): the red's.
    pub top: Vec2,
    /// The centre spot.
    pub centre: Vec2,
    /// The bottom spot (the head spot): the opponent's ball on the opening.
    pub bottom: Vec2,
    /// The starting spots, left and right of the bottom spot on the starting line.
    pub starting: [Vec2; 2],
}

impl Spots {
    /// The spots of `table` for balls of `radius`; an error if a ball on a starting spot would
    /// not be on the cloth or would touch the ball on the bottom spot.
    pub fn of(table: &Table, radius: f64) -> Result<Self, ThreeCushionError> {
        table
            .validate(radius)
            .map_err(|e| ThreeCushionError::Rules(e.to_string()))?;
        let fits = STARTING_SPOT_OFFSET + radius < 0.5 * table.width
            && STARTING_SPOT_OFFSET > 2.0 * radius + FROZEN_GAP;
        if !fits {
            return Err(ThreeCushionError::Rules(format!(
                "a {:.3} m wide table with {:.1} mm balls has no room for the starting spots",
                table.width,
                2000.0 * radius
            )));
        }
        let bottom = table.head_spot();
        Ok(Self {
            top: table.foot_spot(),
            centre: Vec2::ZERO,
            bottom,
            starting: [
                bottom + Vec2::new(0.0, STARTING_SPOT_OFFSET),
                bottom - Vec2::new(0.0, STARTING_SPOT_OFFSET),
            ],
        })
    }

    /// The starting spot on `side`.
    pub fn starting(&self, side: Side) -> Vec2 {
        match side {
            Side::Left => self.starting[0],
            Side::Right => self.starting[1],
        }
    }

    /// UMB 3.3 (Art. 23): the red on the top spot, the opponent's ball on the bottom spot, the
    /// striker's ball (`cue`) on the starting spot on `side`. Positions by [`Ball::index`].
    pub fn opening(&self, cue: Ball, side: Side) -> [Vec2; 3] {
        let mut p = [Vec2::ZERO; 3];
        p[Ball::Red.index()] = self.top;
        for b in cue.objects() {
            if b != Ball::Red {
                p[b.index()] = self.bottom;
            }
        }
        p[cue.index()] = self.starting(side);
        p
    }

    /// Art. 27's spot for `ball` when the balls are set up again with `cue` the striker's
    /// ball: the red on the top spot, the cue ball on the bottom spot, the other white on the
    /// centre spot.
    fn spot_for(&self, ball: Ball, cue: Ball) -> Vec2 {
        if ball == Ball::Red {
            self.top
        } else if ball == cue {
            self.bottom
        } else {
            self.centre
        }
    }

    /// Art. 27 (balls in contact), the striker's third choice: the cue ball and the ball(s) it
    /// is frozen to are set up again on their spots (the red on the top spot, the cue ball on
    /// the bottom spot, the other white on the centre spot). If a ball that stays occupies the
    /// spot of a ball being placed, that ball goes on the spot of the one occupying it (the
    /// Dutch text of the rule, winterswijksebiljartbond.nl, "Vastliggende ballen bij
    /// 3-banden"). An error if `cue` touches no ball.
    pub fn respot_frozen(
        &self,
        positions: [Vec2; 3],
        cue: Ball,
        radius: f64,
    ) -> Result<[Vec2; 3], ThreeCushionError> {
        let frozen = frozen_to(&positions, cue, radius);
        if frozen.is_empty() {
            return Err(ThreeCushionError::NotFrozen(cue.name()));
        }
        let mut moved = frozen;
        moved.push(cue);
        Ok(self.set_up(positions, &moved, cue, radius))
    }

    /// Art. 28 (balls bounding out of the table; its text not confirmed, see
    /// [`super::Foul::OffTable`]): the balls `off` are set up again on Art. 27's spots, `cue`
    /// the next striker's ball (the red on the top spot, that cue ball on the bottom spot,
    /// the other white on the centre spot), a spot taken by a ball that stays giving the spot
    /// of that ball, as in [`Spots::respot_frozen`].
    pub fn respot_off_table(
        &self,
        positions: [Vec2; 3],
        off: &[Ball],
        cue: Ball,
        radius: f64,
    ) -> [Vec2; 3] {
        self.set_up(positions, off, cue, radius)
    }

    /// Sets the balls `moved` on their spots (Art. 27), the others staying.
    fn set_up(&self, positions: [Vec2; 3], moved: &[Ball], cue: Ball, radius: f64) -> [Vec2; 3] {
        let mut out = positions;
        for &b in moved {
            let mut spot = self.spot_for(b, cue);
            let staying = Ball::ALL.into_iter().filter(|s| !moved.contains(s));
            for s in staying {
                if (positions[s.index()] - spot).length() < 2.0 * radius + FROZEN_GAP {
                    spot = self.spot_for(s, cue);
                }
            }
            out[b.index()] = spot;
        }
        out
    }
}

/// The balls `cue` touches (centres at most two radii and [`FROZEN_GAP`] apart), in
/// [`Ball::ALL`] order.
pub fn frozen_to(positions: &[Vec2; 3], cue: Ball, radius: f64) -> Vec<Ball> {
    cue.objects()
        .into_iter()
        .filter(|b| {
            (positions[b.index()] - positions[cue.index()]).length() <= 2.0 * radius + FROZEN_GAP
        })
        .collect()
}
