//! The table: playing surface between the cushion noses, four cushions, six pockets (none on
//! the carom table, [`PocketShape::Pocketless`]).

use crate::math::Vec2;
use serde::{Deserialize, Serialize};

/// Metres per inch; inches appear only where the WPA specifies them.
pub const INCH: f64 = 0.0254;

/// WPBSA Official Rules (November 2019) 1.1(a): the snooker playing area within the cushion
/// faces, 3569 mm long ([`crate::snooker`] re-exports it with the table's marks).
pub const SNOOKER_LENGTH: f64 = 3.569;
/// 1.1(a): the snooker playing area within the cushion faces, 1778 mm wide.
pub const SNOOKER_WIDTH: f64 = 1.778;

/// Radius of the rounded cushion ends of [`Table::snooker_12ft`], metres: 1 in, the
/// knuckle of a snooker cushion being broader than a pool jaw's 15 mm. With the 4 1/8 in
/// middle mouths a 52.5 mm ball can still reach the opening line between the jaws.
pub const SNOOKER_JAW_RADIUS: f64 = INCH;

/// One of the four cushions. The head end is at `-x` (where the cue ball starts), the foot
/// at `+x`; left is `+y` looking from head to foot.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Cushion {
    /// The short cushion at `x = -length/2`.
    Head,
    /// The short cushion at `x = +length/2`.
    Foot,
    /// The long cushion at `y = +width/2`.
    Left,
    /// The long cushion at `y = -width/2`.
    Right,
}

impl Cushion {
    /// All four, in a fixed order (also the tie order between cushion events).
    pub const ALL: [Cushion; 4] = [Cushion::Head, Cushion::Foot, Cushion::Left, Cushion::Right];

    /// Unit normal pointing into the playing surface.
    pub fn inward_normal(self) -> Vec2 {
        match self {
            Cushion::Head => Vec2::new(1.0, 0.0),
            Cushion::Foot => Vec2::new(-1.0, 0.0),
            Cushion::Left => Vec2::new(0.0, -1.0),
            Cushion::Right => Vec2::new(0.0, 1.0),
        }
    }
}

/// One of the six pockets.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Pocket {
    /// Corner at `(-L/2, +W/2)`.
    HeadLeft,
    /// Corner at `(-L/2, -W/2)`.
    HeadRight,
    /// Side pocket at `(0, +W/2)`.
    SideLeft,
    /// Side pocket at `(0, -W/2)`.
    SideRight,
    /// Corner at `(+L/2, +W/2)`.
    FootLeft,
    /// Corner at `(+L/2, -W/2)`.
    FootRight,
}

impl Pocket {
    /// All six.
    pub const ALL: [Pocket; 6] = [
        Pocket::HeadLeft,
        Pocket::HeadRight,
        Pocket::SideLeft,
        Pocket::SideRight,
        Pocket::FootLeft,
        Pocket::FootRight,
    ];

    /// Corner or side.
    pub fn is_corner(self) -> bool {
        !matches!(self, Pocket::SideLeft | Pocket::SideRight)
    }
}

/// Table geometry. The playing surface is the rectangle between the cushion noses, centred at
/// the origin.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Table {
    /// Length between the head and foot cushion noses, metres.
    pub length: f64,
    /// Width between the side cushion noses, metres.
    pub width: f64,
    /// Corner pocket mouth, measured straight across between the cushion noses, metres.
    pub corner_mouth: f64,
    /// Side pocket mouth, metres.
    pub side_mouth: f64,
    /// How the cushions end at the pocket mouths.
    #[serde(default)]
    pub pockets: PocketShape,
}

/// How the cushions end at the pocket mouths.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum PocketShape {
    /// The paper's rule (4.2, `HitPocket`): the cushion lines run on across the mouths, and a
    /// ball that reaches a cushion line inside a mouth is pocketed.
    #[default]
    Mouth,
    /// Cushions stop at the mouths and end in rounded jaws (circular arcs of `radius`, tangent
    /// to the cushion nose); a ball can rattle between them and is pocketed when its centre
    /// crosses the pocket opening (the line across the mouth between the cushion noses).
    Jaws {
        /// Radius of the rounded cushion end, metres.
        radius: f64,
    },
    /// No pockets at all (the carom table, [`Table::carom_match`]): the cushions run unbroken
    /// round the table, so no pocket, opening or jaw event can occur; both mouths are zero.
    Pocketless,
}

/// A rounded cushion end at a pocket mouth.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Jaw {
    /// The pocket it guards.
    pub pocket: Pocket,
    /// Centre of the arc.
    pub centre: Vec2,
}

/// The line across a pocket's opening: `offset + normal · p` is positive on the table side.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Opening {
    /// The pocket.
    pub pocket: Pocket,
    /// Unit normal pointing onto the table.
    pub normal: Vec2,
    /// Offset of the line.
    pub offset: f64,
}

impl Default for Table {
    fn default() -> Self {
        Self::wpa_8ft()
    }
}

/// Why a table was rejected.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum TableError {
    /// A dimension is NaN, infinite, zero or negative.
    #[error("table {name} must be a positive finite length in metres, got {value}")]
    BadDimension {
        /// Which dimension.
        name: &'static str,
        /// The value given.
        value: f64,
    },
    /// The pockets do not fit on the table, or a ball cannot fit between the cushions.
    #[error("table {what}")]
    Inconsistent {
        /// What does not fit.
        what: String,
    },
}

/// A WPA table size: the playing surface between the cushion noses.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum TableSize {
    /// 7-ft (bar box): 78 x 39 in.
    Seven,
    /// 8-ft: 92 x 46 in (the paper's table, the game's default).
    #[default]
    Eight,
    /// 9-ft (tournament): 100 x 50 in.
    Nine,
}

impl TableSize {
    /// Every size, smallest first.
    pub const ALL: [TableSize; 3] = [TableSize::Seven, TableSize::Eight, TableSize::Nine];

    /// Length and width of the playing surface, metres (WPA equipment specifications).
    pub fn surface(self) -> (f64, f64) {
        let (l, w) = match self {
            TableSize::Seven => (78.0, 39.0),
            TableSize::Eight => (92.0, 46.0),
            TableSize::Nine => (100.0, 50.0),
        };
        (l * INCH, w * INCH)
    }

    /// Its name on the command line: `7ft`, `8ft`, `9ft`.
    pub fn name(self) -> &'static str {
        match self {
            TableSize::Seven => "7ft",
            TableSize::Eight => "8ft",
            TableSize::Nine => "9ft",
        }
    }
}

/// Pocket mouths, measured straight across between the cushion noses.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum PocketCut {
    /// The WPA's widest: corner 4.625 in, side 5.125 in.
    WpaWide,
    /// The WPA's narrowest: corner 4.5 in, side 5 in (the paper's, the game's default).
    #[default]
    Wpa,
    /// A tight pro table: corner 4 in, side 5 in (the 9- and 10-ball pro events of issue 23).
    Tight,
}

impl PocketCut {
    /// Every cut, widest first.
    pub const ALL: [PocketCut; 3] = [PocketCut::WpaWide, PocketCut::Wpa, PocketCut::Tight];

    /// Corner and side mouths, metres.
    pub fn mouths(self) -> (f64, f64) {
        let (c, s) = match self {
            PocketCut::WpaWide => (4.625, 5.125),
            PocketCut::Wpa => (4.5, 5.0),
            PocketCut::Tight => (4.0, 5.0),
        };
        (c * INCH, s * INCH)
    }

    /// Its name on the command line: `wide`, `wpa`, `tight`.
    pub fn name(self) -> &'static str {
        match self {
            PocketCut::WpaWide => "wide",
            PocketCut::Wpa => "wpa",
            PocketCut::Tight => "tight",
        }
    }
}

/// A table size with its pocket cut: what a player chooses (`9ft`, `9ft-tight`, `7ft-wide`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub struct TableChoice {
    /// The playing surface.
    pub size: TableSize,
    /// The pocket mouths.
    pub pockets: PocketCut,
}

impl TableChoice {
    /// The table (pocket mouths of the paper's rule; add jaws with [`Table::with_jaws`]).
    pub fn table(self) -> Table {
        let ((length, width), (corner_mouth, side_mouth)) =
            (self.size.surface(), self.pockets.mouths());
        Table {
            length,
            width,
            corner_mouth,
            side_mouth,
            pockets: PocketShape::Mouth,
        }
    }
}

impl std::fmt::Display for TableChoice {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self.pockets {
            PocketCut::Wpa => write!(f, "{}", self.size.name()),
            p => write!(f, "{}-{}", self.size.name(), p.name()),
        }
    }
}

impl std::str::FromStr for TableChoice {
    type Err = String;

    /// `7ft`, `8ft` or `9ft`, optionally followed by `-wpa`, `-wide` or `-tight`.
    fn from_str(s: &str) -> Result<Self, String> {
        let (size, cut) = s.split_once('-').unwrap_or((s, "wpa"));
        let size = TableSize::ALL
            .into_iter()
            .find(|t| t.name() == size)
            .ok_or_else(|| format!("table `{s}`: expected 7ft, 8ft or 9ft"))?;
        let pockets = PocketCut::ALL
            .into_iter()
            .find(|p| p.name() == cut)
            .ok_or_else(|| format!("table `{s}`: pockets expected wpa, wide or tight"))?;
        Ok(Self { size, pockets })
    }
}

impl Table {
    /// The WPA 7-ft table: 78 x 39 in, corner mouths 4.5 in, side mouths 5 in.
    pub fn wpa_7ft() -> Self {
        TableChoice {
            size: TableSize::Seven,
            pockets: PocketCut::Wpa,
        }
        .table()
    }

    /// The WPA 9-ft table: 100 x 50 in, corner mouths 4.5 in, side mouths 5 in.
    pub fn wpa_9ft() -> Self {
        TableChoice {
            size: TableSize::Nine,
            pockets: PocketCut::Wpa,
        }
        .table()
    }

    /// The WPA 8-ft table of the paper: 92 x 46 in, corner mouths 4.5 in, side mouths 5 in.
    pub fn wpa_8ft() -> Self {
        Self {
            length: 92.0 * INCH,
            width: 46.0 * INCH,
            corner_mouth: 4.5 * INCH,
            side_mouth: 5.0 * INCH,
            pockets: PocketShape::Mouth,
        }
    }

    /// The 12-ft snooker table: WPBSA Official Rules (November 2019) 1.1(a), playing area
    /// 3569 x 1778 mm, with rounded jaws at the pocket mouths.
    ///
    /// 1.1(c)(ii) makes the pocket openings those of the WPBSA templates, which are not
    /// published. The mouths taken are the figures tables cut for snooker are commonly given:
    /// corners 3.5 in (88.9 mm) and middles 4 1/8 in (104.8 mm) between the cushion noses,
    /// with the cushions ending in jaws of [`SNOOKER_JAW_RADIUS`].
    pub fn snooker_12ft() -> Self {
        Self {
            length: SNOOKER_LENGTH,
            width: SNOOKER_WIDTH,
            corner_mouth: 3.5 * INCH,
            side_mouth: 4.125 * INCH,
            pockets: PocketShape::Jaws {
                radius: SNOOKER_JAW_RADIUS,
            },
        }
    }

    /// The same table with rounded jaws of `radius` at the pocket mouths.
    pub fn with_jaws(self, radius: f64) -> Self {
        Self {
            pockets: PocketShape::Jaws { radius },
            ..self
        }
    }

    /// The twelve jaws (two per pocket), if the table has them.
    pub fn jaws(&self) -> Vec<Jaw> {
        let PocketShape::Jaws { radius: rho } = self.pockets else {
            return Vec::new();
        };
        let (hx, hy, leg, half_side) = (
            0.5 * self.length,
            0.5 * self.width,
            self.corner_leg(),
            0.5 * self.side_mouth,
        );
        let mut out = Vec::with_capacity(12);
        for (sx, sy) in [(-1.0, 1.0), (-1.0, -1.0), (1.0, 1.0), (1.0, -1.0)] {
            let pocket = self.corner_at(sx, sy);
            // Ends of the long and of the short cushion, each arc just outside its nose line.
            out.push(Jaw {
                pocket,
                centre: Vec2::new(sx * (hx - leg), sy * (hy + rho)),
            });
            out.push(Jaw {
                pocket,
                centre: Vec2::new(sx * (hx + rho), sy * (hy - leg)),
            });
        }
        for (sy, pocket) in [(1.0, Pocket::SideLeft), (-1.0, Pocket::SideRight)] {
            out.push(Jaw {
                pocket,
                centre: Vec2::new(-half_side, sy * (hy + rho)),
            });
            out.push(Jaw {
                pocket,
                centre: Vec2::new(half_side, sy * (hy + rho)),
            });
        }
        out
    }

    fn corner_at(&self, sx: f64, sy: f64) -> Pocket {
        match (sx > 0.0, sy > 0.0) {
            (false, true) => Pocket::HeadLeft,
            (false, false) => Pocket::HeadRight,
            (true, true) => Pocket::FootLeft,
            (true, false) => Pocket::FootRight,
        }
    }

    /// The six pocket openings (used with jaws only: the solver never reads them on a table
    /// with the paper's mouths or without pockets).
    pub fn openings(&self) -> [Opening; 6] {
        let (hx, hy, leg) = (0.5 * self.length, 0.5 * self.width, self.corner_leg());
        let corner = |sx: f64, sy: f64| {
            // Through (sx (hx - leg), sy hy) and (sx hx, sy (hy - leg)).
            let normal = Vec2::new(-sx, -sy) / std::f64::consts::SQRT_2;
            let offset = (hx - leg + hy) / std::f64::consts::SQRT_2;
            Opening {
                pocket: self.corner_at(sx, sy),
                normal,
                offset,
            }
        };
        [
            corner(-1.0, 1.0),
            corner(-1.0, -1.0),
            Opening {
                pocket: Pocket::SideLeft,
                normal: Vec2::new(0.0, -1.0),
                offset: hy,
            },
            Opening {
                pocket: Pocket::SideRight,
                normal: Vec2::new(0.0, 1.0),
                offset: hy,
            },
            corner(1.0, 1.0),
            corner(1.0, -1.0),
        ]
    }

    /// With jaws: does a ball centred at `centre` touching `cushion`'s nose line touch the
    /// cushion itself (not the gap of a mouth)?
    pub fn on_cushion(&self, cushion: Cushion, centre: Vec2) -> bool {
        self.pocket_at(cushion, centre).is_none()
    }

    /// The WPA table scaled by `k` in length and width (pocket mouths unchanged).
    pub fn scaled(k: f64) -> Self {
        let t = Self::wpa_8ft();
        Self {
            length: t.length * k,
            width: t.width * k,
            ..t
        }
    }

    /// Checks every dimension; `ball_radius` must fit.
    pub fn validate(&self, ball_radius: f64) -> Result<(), TableError> {
        let pocketless = self.pockets == PocketShape::Pocketless;
        for (name, value, mouth) in [
            ("length", self.length, false),
            ("width", self.width, false),
            ("corner_mouth", self.corner_mouth, true),
            ("side_mouth", self.side_mouth, true),
        ] {
            // A table without pockets has no mouths: zero, so no code can find one.
            if mouth && pocketless {
                if value != 0.0 {
                    return Err(TableError::Inconsistent {
                        what: format!("without pockets must have no pocket mouth: {name} {value}"),
                    });
                }
            } else if !(value.is_finite() && value > 0.0) {
                return Err(TableError::BadDimension { name, value });
            }
        }
        if let PocketShape::Jaws { radius } = self.pockets
            && !(radius.is_finite() && radius > 0.0)
        {
            return Err(TableError::BadDimension {
                name: "jaw radius",
                value: radius,
            });
        }
        if self.width <= 2.0 * ball_radius || self.length <= 2.0 * ball_radius {
            return Err(TableError::Inconsistent {
                what: format!("is too small for a ball of radius {ball_radius} m"),
            });
        }
        let leg = self.corner_leg();
        if 2.0 * leg + self.side_mouth >= self.length || 2.0 * leg >= self.width {
            return Err(TableError::Inconsistent {
                what: "pocket mouths overlap: they are too wide for the table".into(),
            });
        }
        Ok(())
    }

    /// Half extents of the rectangle the ball centres may occupy.
    pub fn centre_bounds(&self, ball_radius: f64) -> Vec2 {
        Vec2::new(
            0.5 * self.length - ball_radius,
            0.5 * self.width - ball_radius,
        )
    }

    /// How far a corner mouth reaches along each cushion from the corner (the mouth runs
    /// across the corner at 45 degrees).
    pub fn corner_leg(&self) -> f64 {
        self.corner_mouth / std::f64::consts::SQRT_2
    }

    /// Where a pocket is: the corner of the playing surface, or the middle of a long side.
    pub fn pocket_position(&self, p: Pocket) -> Vec2 {
        let (hx, hy) = (0.5 * self.length, 0.5 * self.width);
        match p {
            Pocket::HeadLeft => Vec2::new(-hx, hy),
            Pocket::HeadRight => Vec2::new(-hx, -hy),
            Pocket::SideLeft => Vec2::new(0.0, hy),
            Pocket::SideRight => Vec2::new(0.0, -hy),
            Pocket::FootLeft => Vec2::new(hx, hy),
            Pocket::FootRight => Vec2::new(hx, -hy),
        }
    }

    /// The pocket whose mouth contains the point where a ball centred at `centre` touches
    /// `cushion`, if any (paper 4.2, `HitPocket`).
    pub fn pocket_at(&self, cushion: Cushion, centre: Vec2) -> Option<Pocket> {
        if self.pockets == PocketShape::Pocketless {
            return None;
        }
        let (hx, hy) = (0.5 * self.length, 0.5 * self.width);
        let leg = self.corner_leg();
        match cushion {
            Cushion::Head | Cushion::Foot => {
                let head = cushion == Cushion::Head;
                if centre.y >= hy - leg {
                    Some(if head {
                        Pocket::HeadLeft
                    } else {
                        Pocket::FootLeft
                    })
                } else if centre.y <= -(hy - leg) {
                    Some(if head {
                        Pocket::HeadRight
                    } else {
                        Pocket::FootRight
                    })
                } else {
                    None
                }
            }
            Cushion::Left | Cushion::Right => {
                let left = cushion == Cushion::Left;
                if centre.x.abs() <= 0.5 * self.side_mouth {
                    Some(if left {
                        Pocket::SideLeft
                    } else {
                        Pocket::SideRight
                    })
                } else if centre.x >= hx - leg {
                    Some(if left {
                        Pocket::FootLeft
                    } else {
                        Pocket::FootRight
                    })
                } else if centre.x <= -(hx - leg) {
                    Some(if left {
                        Pocket::HeadLeft
                    } else {
                        Pocket::HeadRight
                    })
                } else {
                    None
                }
            }
        }
    }

    /// Head string (`x` of the line a quarter of the length from the head cushion).
    pub fn head_spot(&self) -> Vec2 {
        Vec2::new(-0.25 * self.length, 0.0)
    }

    /// Foot spot (a quarter of the length from the foot cushion), apex of the rack.
    pub fn foot_spot(&self) -> Vec2 {
        Vec2::new(0.25 * self.length, 0.0)
    }
}
