//! Plays [`super::synth`]'s sounds through Bevy's audio (feature `sound`).

use std::{collections::HashMap, sync::Arc, time::Duration};

use bevy::{
    audio::{AddAudioSource, ChannelCount, Decodable, SampleRate, Source, Volume},
    prelude::*,
};

use super::synth::{SAMPLE_RATE, Sound, volume};
use crate::{
    input::InputSystems,
    sim::{BallContact, BallPocketed, CueStruck, CushionHit, CushionPart},
};

/// Most sounds started in one frame: a break's burst of clicks plays its loudest few, not a
/// clipped wall of noise.
const MAX_PER_FRAME: usize = 8;

/// Whether sounds play (`M` toggles).
#[derive(Resource, Debug, Clone, Copy, PartialEq, Eq)]
pub struct SoundOn(pub bool);

/// A synthesised sound as an asset Bevy's audio can play.
#[derive(Asset, TypePath, Debug, Clone)]
struct Synth {
    samples: Arc<[f32]>,
}

/// Plays a [`Synth`] from its start.
struct SynthDecoder {
    samples: Arc<[f32]>,
    at: usize,
}

impl Iterator for SynthDecoder {
    type Item = f32;

    fn next(&mut self) -> Option<f32> {
        let s = self.samples.get(self.at).copied();
        self.at += 1;
        s
    }
}

impl Source for SynthDecoder {
    fn current_span_len(&self) -> Option<usize> {
        Some(self.samples.len().saturating_sub(self.at))
    }

    fn channels(&self) -> ChannelCount {
        ChannelCount::new(1).expect("one channel")
    }

    fn sample_rate(&self) -> SampleRate {
        SampleRate::new(SAMPLE_RATE).expect("a positive rate")
    }

    fn total_duration(&self) -> Option<Duration> {
        Some(Duration::from_secs_f64(
            self.samples.len() as f64 / f64::from(SAMPLE_RATE),
        ))
    }
}

impl Decodable for Synth {
    type Decoder = SynthDecoder;

    fn decoder(&self) -> SynthDecoder {
        SynthDecoder {
            samples: Arc::clone(&self.samples),
            at: 0,
        }
    }
}

/// The synthesised sounds' handles.
#[derive(Resource, Debug, Default)]
struct Sounds(HashMap<Sound, Handle<Synth>>);

/// Adds the sounds: synthesised at start, played from the solver's messages.
pub fn plugin(app: &mut App) {
    app.add_audio_source::<Synth>()
        .insert_resource(SoundOn(true))
        .init_resource::<Sounds>()
        .add_systems(Startup, synthesise)
        .add_systems(Update, mute_key.in_set(InputSystems::Keyboard))
        .add_systems(PostUpdate, play);
}

fn synthesise(mut assets: ResMut<Assets<Synth>>, mut sounds: ResMut<Sounds>) {
    for sound in Sound::ALL {
        let samples: Arc<[f32]> = sound.samples().into();
        sounds.0.insert(sound, assets.add(Synth { samples }));
    }
}

fn mute_key(keys: Option<Res<ButtonInput<KeyCode>>>, mut on: ResMut<SoundOn>) {
    if keys.is_some_and(|k| k.just_pressed(KeyCode::KeyM)) {
        on.0 = !on.0;
        info!("sound {}", if on.0 { "on" } else { "muted" });
    }
}

fn play(
    mut commands: Commands,
    sounds: Res<Sounds>,
    on: Res<SoundOn>,
    mut strikes: MessageReader<CueStruck>,
    mut contacts: MessageReader<BallContact>,
    mut cushions: MessageReader<CushionHit>,
    mut pockets: MessageReader<BallPocketed>,
) {
    let mut queue: Vec<(Sound, f32)> = Vec::new();
    let mut push = |sound, speed| queue.push((sound, volume(sound, speed)));
    for s in strikes.read() {
        push(Sound::CueStrike, s.speed);
    }
    for c in contacts.read() {
        push(Sound::BallClick, c.speed);
    }
    for c in cushions.read() {
        let sound = match c.part {
            CushionPart::Cushion(_) => Sound::CushionThud,
            CushionPart::Jaw(_) => Sound::JawKnock,
        };
        push(sound, c.speed);
    }
    for _ in pockets.read() {
        push(Sound::PocketDrop, 1.5);
    }
    if !on.0 {
        return;
    }
    queue.retain(|&(_, v)| v > 0.0);
    queue.sort_by(|a, b| b.1.total_cmp(&a.1));
    for (sound, v) in queue.into_iter().take(MAX_PER_FRAME) {
        if let Some(handle) = sounds.0.get(&sound) {
            commands.spawn((
                AudioPlayer(handle.clone()),
                PlaybackSettings::DESPAWN.with_volume(Volume::Linear(v)),
            ));
        }
    }
}
