//! The table's sounds, synthesised at start (no audio files, nothing to license): sums of
//! exponentially damped partials with a short noise attack, the usual model of struck solids.
//! Pure and deterministic; `player.rs` plays them when the `sound` feature is on.

use std::f32::consts::TAU;

/// Samples per second of every synthesised sound.
pub const SAMPLE_RATE: u32 = 44_100;

/// One damped partial: `amplitude * exp(-t / decay) * sin(2 pi f t)`.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Partial {
    /// Frequency, Hz.
    frequency: f32,
    /// Time constant of the decay, seconds.
    decay: f32,
    /// Peak amplitude.
    amplitude: f32,
}

/// A struck body: its partials, the noise burst of the contact, and when it starts.
#[derive(Debug, Clone, Copy)]
struct Knock<'a> {
    partials: &'a [Partial],
    /// Amplitude of the white-noise attack.
    noise: f32,
    /// Time constant of the noise attack, seconds.
    noise_decay: f32,
    /// Start within the sound, seconds.
    at: f32,
    /// Gain of this knock.
    gain: f32,
}

/// The sounds of the table.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Sound {
    /// The cue's leather tip on the cue ball.
    CueStrike,
    /// Two phenolic balls: a bright click (partials near 2.6 and 4.2 kHz, a few ms).
    BallClick,
    /// A ball into a rubber cushion: a dull thud.
    CushionThud,
    /// A ball on a pocket's jaw: harder and shorter than a cushion.
    JawKnock,
    /// A ball dropping into a pocket: knocks on the liner as it falls and settles.
    PocketDrop,
}

impl Sound {
    /// Every sound, for synthesising them all at start.
    pub const ALL: [Sound; 5] = [
        Sound::CueStrike,
        Sound::BallClick,
        Sound::CushionThud,
        Sound::JawKnock,
        Sound::PocketDrop,
    ];

    /// The impact speed (m/s) that plays this sound at full volume.
    pub fn full_speed(self) -> f32 {
        match self {
            Sound::CueStrike => 8.0,
            Sound::BallClick => 6.0,
            Sound::CushionThud | Sound::JawKnock => 4.0,
            Sound::PocketDrop => 2.0,
        }
    }

    /// The sound's samples, mono, in -1..=1, at [`SAMPLE_RATE`].
    pub fn samples(self) -> Vec<f32> {
        let p = |frequency, decay, amplitude| Partial {
            frequency,
            decay,
            amplitude,
        };
        let knock = |partials, noise, noise_decay, at, gain| Knock {
            partials,
            noise,
            noise_decay,
            at,
            gain,
        };
        match self {
            Sound::CueStrike => render(
                0.08,
                &[knock(
                    &[p(1_150.0, 0.006, 0.5), p(2_300.0, 0.004, 0.3)],
                    0.5,
                    0.0015,
                    0.0,
                    1.0,
                )],
            ),
            Sound::BallClick => render(
                0.06,
                &[knock(
                    &[p(2_600.0, 0.008, 0.6), p(4_150.0, 0.005, 0.35)],
                    0.3,
                    0.0008,
                    0.0,
                    1.0,
                )],
            ),
            Sound::CushionThud => render(
                0.15,
                &[knock(
                    &[
                        p(95.0, 0.045, 0.7),
                        p(160.0, 0.03, 0.4),
                        p(420.0, 0.01, 0.15),
                    ],
                    0.25,
                    0.003,
                    0.0,
                    1.0,
                )],
            ),
            Sound::JawKnock => render(
                0.1,
                &[knock(
                    &[p(240.0, 0.02, 0.6), p(610.0, 0.008, 0.3)],
                    0.3,
                    0.002,
                    0.0,
                    1.0,
                )],
            ),
            Sound::PocketDrop => {
                // A fall onto the liner, a bounce, and the roll to the bottom.
                let liner = [p(120.0, 0.035, 0.7), p(210.0, 0.02, 0.35)];
                render(
                    0.45,
                    &[
                        knock(&liner, 0.2, 0.004, 0.0, 1.0),
                        knock(&liner, 0.15, 0.004, 0.09, 0.55),
                        knock(&liner, 0.1, 0.004, 0.17, 0.3),
                    ],
                )
            }
        }
    }
}

/// The volume (0..=1) of `sound` for an impact at `speed` m/s: silent below 1 cm/s, then the
/// square root of the speed's share of [`Sound::full_speed`] (sound pressure grows with the
/// impact speed; the root keeps soft contacts audible), capped at 1.
pub fn volume(sound: Sound, speed: f64) -> f32 {
    if !speed.is_finite() || speed < 0.01 {
        return 0.0;
    }
    ((speed as f32) / sound.full_speed()).sqrt().min(1.0)
}

/// Renders `knocks` into `seconds` of samples, normalised to a peak of 0.9.
fn render(seconds: f32, knocks: &[Knock]) -> Vec<f32> {
    let n = (seconds * SAMPLE_RATE as f32) as usize;
    let dt = 1.0 / SAMPLE_RATE as f32;
    let mut out = vec![0.0f32; n];
    // Xorshift noise: deterministic, so every run sounds the same.
    let mut state: u32 = 0x9e37_79b9;
    let mut noise = move || {
        state ^= state << 13;
        state ^= state >> 17;
        state ^= state << 5;
        state as f32 / u32::MAX as f32 * 2.0 - 1.0
    };
    for k in knocks {
        let start = (k.at * SAMPLE_RATE as f32) as usize;
        for (i, sample) in out.iter_mut().enumerate().skip(start) {
            let t = (i - start) as f32 * dt;
            let tonal: f32 = k
                .partials
                .iter()
                .map(|p| p.amplitude * (-t / p.decay).exp() * (TAU * p.frequency * t).sin())
                .sum();
            let attack = k.noise * (-t / k.noise_decay).exp() * noise();
            *sample += k.gain * (tonal + attack);
        }
    }
    let peak = out.iter().fold(0.0f32, |m, s| m.max(s.abs()));
    if peak > 0.0 {
        for s in &mut out {
            *s *= 0.9 / peak;
        }
    }
    // Fade the last 5 ms to zero so no sound ends in a click.
    let fade = (0.005 * SAMPLE_RATE as f32) as usize;
    let len = out.len();
    for (j, s) in out.iter_mut().skip(len.saturating_sub(fade)).enumerate() {
        *s *= 1.0 - (j + 1) as f32 / fade as f32;
    }
    out
}

#[cfg(test)]
mod tests {
    use crate::sound::synth::*;

    /// Energy of `samples` between `from` and `to` seconds.
    fn energy(samples: &[f32], from: f32, to: f32) -> f32 {
        let r = SAMPLE_RATE as f32;
        samples[(from * r) as usize..(to * r) as usize]
            .iter()
            .map(|s| s * s)
            .sum()
    }

    #[test]
    fn every_sound_is_bounded_decays_and_ends_silent() {
        for sound in Sound::ALL {
            let s = sound.samples();
            assert!(s.len() > SAMPLE_RATE as usize / 20, "{sound:?} too short");
            let peak = s.iter().fold(0.0f32, |m, x| m.max(x.abs()));
            assert!((peak - 0.9).abs() < 1e-3, "{sound:?} peak {peak}");
            assert_eq!(*s.last().unwrap(), 0.0, "{sound:?} ends in a click");
            // Struck bodies ring down: the first 10 ms hold more energy than the last 10 ms.
            let end = s.len() as f32 / SAMPLE_RATE as f32;
            assert!(energy(&s, 0.0, 0.01) > 10.0 * energy(&s, end - 0.01, end));
        }
    }

    #[test]
    fn a_click_is_brighter_than_a_thud() {
        // Zero crossings per second estimate the dominant frequency.
        let crossings = |s: &[f32]| {
            let n = SAMPLE_RATE as usize / 50; // the first 20 ms
            s[..n].windows(2).filter(|w| w[0] * w[1] < 0.0).count()
        };
        let click = crossings(&Sound::BallClick.samples());
        let thud = crossings(&Sound::CushionThud.samples());
        assert!(click > 5 * thud, "click {click}, thud {thud} crossings");
    }

    #[test]
    fn the_pocket_drop_knocks_three_times() {
        let s = Sound::PocketDrop.samples();
        // A knock starts at 0, 90 and 170 ms: more energy just after each start than before.
        for at in [0.09, 0.17] {
            assert!(
                energy(&s, at, at + 0.01) > 2.0 * energy(&s, at - 0.01, at),
                "{at}"
            );
        }
    }

    #[test]
    fn volume_grows_with_the_impact_speed_and_is_capped() {
        let v = |speed| volume(Sound::BallClick, speed);
        assert_eq!(v(0.0), 0.0);
        assert_eq!(v(0.005), 0.0);
        assert_eq!(v(f64::NAN), 0.0);
        assert!(v(0.5) < v(2.0) && v(2.0) < v(5.0));
        assert!(
            (v(1.5) - 0.5).abs() < 1e-6,
            "a quarter of full speed plays at half volume"
        );
        assert_eq!(v(6.0), 1.0);
        assert_eq!(v(60.0), 1.0);
    }
}
