//! A drill's goals ([`Goal`]) and the table zones they name ([`Zone`]).

use billiards_physics::{Pocket, Vec2};
use serde::{Deserialize, Serialize};

/// A region of the table, in table coordinates (metres, origin at the centre).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "shape", rename_all = "snake_case")]
pub enum Zone {
    /// The disc of `radius` about `centre`.
    Circle {
        /// Centre.
        centre: Vec2,
        /// Radius, metres.
        radius: f64,
    },
    /// The rectangle between two corners.
    Rect {
        /// The corner of least x and y.
        min: Vec2,
        /// The corner of greatest x and y.
        max: Vec2,
    },
}

impl Zone {
    /// The zone holds the ball centre `p` (its edge included).
    pub fn contains(&self, p: Vec2) -> bool {
        match *self {
            Zone::Circle { centre, radius } => (p - centre).length() <= radius,
            Zone::Rect { min, max } => {
                (min.x..=max.x).contains(&p.x) && (min.y..=max.y).contains(&p.y)
            }
        }
    }

    /// The zone's centre.
    pub fn centre(&self) -> Vec2 {
        match *self {
            Zone::Circle { centre, .. } => centre,
            Zone::Rect { min, max } => (min + max) * 0.5,
        }
    }

    /// How close `p` is to the centre, 1 at the centre to 0 at the edge (the rectangle's
    /// edge by the larger of the two normalised offsets); 0 outside.
    pub fn closeness(&self, p: Vec2) -> f64 {
        let c = self.centre();
        let d = match *self {
            Zone::Circle { radius, .. } => (p - c).length() / radius,
            Zone::Rect { min, max } => {
                let h = (max - min) * 0.5;
                ((p.x - c.x).abs() / h.x).max((p.y - c.y).abs() / h.y)
            }
        };
        (1.0 - d).clamp(0.0, 1.0)
    }

    /// The zone has some area and finite corners (a drill's check refuses others).
    pub(super) fn valid(&self) -> bool {
        match *self {
            Zone::Circle { centre, radius } => {
                centre.x.is_finite() && centre.y.is_finite() && radius.is_finite() && radius > 0.0
            }
            Zone::Rect { min, max } => {
                [min.x, min.y, max.x, max.y].iter().all(|v| v.is_finite())
                    && min.x < max.x
                    && min.y < max.y
            }
        }
    }
}

/// What an attempt must do; a drill's goals must all be met.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum Goal {
    /// Pocket `ball` (in `pocket` if named), after it has touched at least `cushions`
    /// cushions (a bank: 1; a jaw is not counted here, so a rattle is no bank).
    Pocket {
        /// The ball.
        ball: u8,
        /// The pocket it must drop in (`None`: any).
        #[serde(default, skip_serializing_if = "Option::is_none")]
        pocket: Option<Pocket>,
        /// Cushions it must touch before it drops.
        #[serde(default)]
        cushions: u32,
    },
    /// The cue ball comes to rest on the table inside `zone` after the attempt's last shot.
    CueBallIn {
        /// The zone.
        zone: Zone,
    },
    /// The cue ball's first contact is `ball`, after at least `cushions` cushion contacts of
    /// the cue ball (a kick: 1).
    FirstContact {
        /// The ball hit first.
        ball: u8,
        /// Cushions the cue ball touches before it.
        #[serde(default)]
        cushions: u32,
    },
    /// Every shot legal under the game's rules (WPA 6.1 to 6.3 in 8-ball and 9-ball); in free
    /// play, no scratch and an object ball hit.
    NoFoul,
    /// No ball is pocketed (a safety).
    NoPocket,
    /// At rest, the cue ball has no straight path to `ball` (`None`: the ball the game says is
    /// on: 9-ball's lowest, WPA 6.2): its centre line to the ball's centre passes within a
    /// ball's diameter of another ball's centre (the opponent is hidden: a safety).
    Hide {
        /// The ball hidden (`None`: the ball on).
        #[serde(default, skip_serializing_if = "Option::is_none")]
        ball: Option<u8>,
    },
    /// Every object ball pocketed in one visit: each shot legal and pocketing a ball, in
    /// 9-ball the lowest ball hit first every time (WPA 2.1, 6.2).
    RunOut,
}

impl Goal {
    /// The goal in words ("pocket the 1 in the foot right corner").
    pub fn text(&self) -> String {
        match *self {
            Goal::Pocket {
                ball,
                pocket,
                cushions,
            } => {
                let mut s = format!("pocket the {ball}");
                if let Some(p) = pocket {
                    s += &format!(" in the {}", crate::foul::pocket_name(p));
                }
                if cushions > 0 {
                    s += &format!(" off {cushions} cushion(s)");
                }
                s
            }
            Goal::CueBallIn { .. } => "leave the cue ball in the zone".into(),
            Goal::FirstContact { ball, cushions: 0 } => format!("hit the {ball} first"),
            Goal::FirstContact { ball, cushions } => {
                format!("hit the {ball} first after {cushions} cushion(s)")
            }
            Goal::NoFoul => "no foul".into(),
            Goal::NoPocket => "pocket nothing".into(),
            Goal::Hide { ball: Some(b) } => format!("hide the {b} from the cue ball"),
            Goal::Hide { ball: None } => "hide the ball on from the cue ball".into(),
            Goal::RunOut => "run out the table".into(),
        }
    }
}
