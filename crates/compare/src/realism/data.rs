//! Published measurements the models are set against, each with its source.

/// Marlow's ball–ball friction measurements at a 45-degree cut, as Alciatore fits them
/// (TP A-28, "Throw plots for all types of shots", p. 1, citing Marlow, "The Physics of
/// Pocket Billiards", 1995, Table 10, p. 245): `(sliding speed m/s, mu)`, the sliding speed
/// being the cue ball speed times sin 45 deg.
pub const MARLOW_FRICTION: [(f64, f64); 3] = [
    (0.1 * std::f64::consts::FRAC_1_SQRT_2, 0.11),
    (1.0 * std::f64::consts::FRAC_1_SQRT_2, 0.06),
    (10.0 * std::f64::consts::FRAC_1_SQRT_2, 0.01),
];

/// Mathavan, Jackson & Parkin (2010), Fig. 7(a), p. 1870: a rolling snooker ball square into
/// the cushion, high-speed camera, `(incident speed, rebound speed)` in m/s. The experimental
/// markers as digitised from the figure by the BilliardGL project
/// (`tests/physics_validation/reference_data/mathavan_2010_cushion/raw_extracted.csv`; axis
/// calibration there: about 0.01 m/s per pixel). The paper finds the rigid-cushion model valid
/// below 2.5 m/s normal speed (abstract); the last six points lie above it.
pub const MATHAVAN_FIG7A: [(f64, f64); 19] = [
    (0.262999, 0.234401),
    (0.354983, 0.323511),
    (0.418037, 0.383074),
    (0.650776, 0.583087),
    (0.704133, 0.665104),
    (0.844922, 0.790892),
    (1.153559, 1.068803),
    (1.299180, 1.236813),
    (1.526487, 1.455654),
    (1.755444, 1.645238),
    (1.991247, 1.824138),
    (2.276377, 2.031109),
    (2.529540, 2.279685),
    (2.700844, 2.265189),
    (2.892779, 2.382759),
    (2.984683, 2.462069),
    (3.106437, 2.620175),
    (3.185100, 2.568495),
    (3.404540, 2.732328),
];

/// Normal speed (m/s) below which Mathavan et al. find the rigid cushion valid (abstract).
pub const MATHAVAN_RIGID_LIMIT: f64 = 2.5;

/// The paper's snooker ball and cushion (Mathavan et al. 2010, section 5): radius (m), mass
/// (kg), nose height as a multiple of the radius, ball–cloth friction during the impact.
pub const MATHAVAN_BALL: (f64, f64, f64, f64) = (0.02625, 0.1406, 1.4, 0.212);

/// Alciatore's shot speeds (TP A-14 and TP A-28 plots): slow, medium, fast = 1, 3, 7 mph.
pub const ALCIATORE_SPEEDS: [(&str, f64); 3] = [
    ("slow 0.45 m/s", 0.447),
    ("medium 1.34 m/s", 1.341),
    ("fast 3.13 m/s", 3.129),
];

/// Dr. Dave's summary of his throw articles ("Throw – Part XI: everything you ever wanted to
/// know about throw", Billiards Digest, June 2007, conclusions): typical maximum throw is
/// "about 1 inch per foot of CB travel, which is about 5 degrees"; maximum cut-induced throw
/// occurs at slow speed near a half-ball hit (30 degrees). `(cut deg, throw deg)`.
pub const ALCIATORE_MAX_THROW: (f64, f64) = (30.0, 4.8);
