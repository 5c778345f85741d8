//! What the replay says in words: an event with the balls by number ("ball 3 hit the foot
//! cushion") and the outcome of a verification.

use billiards_physics::{Cushion, Event, EventKind, Motion, Pocket, recording::Verdict};

use super::open::OpenRecording;

impl OpenRecording {
    /// What happened at an event, with the balls by number (`"ball 3 hit the foot cushion"`).
    pub fn describe(&self, event: &Event) -> String {
        let ball = |id: usize| self.ball_name(id);
        match event.kind {
            EventKind::Strike { ball: id, shot } => format!(
                "strike: {} at {:.1} deg, {:.2} m/s",
                ball(id),
                shot.angle.to_degrees(),
                shot.speed
            ),
            EventKind::Placed { ball: id } => format!("{} placed", ball(id)),
            EventKind::ParamsChanged => "parameters changed".to_owned(),
            EventKind::Transition { ball: id, from, to } => {
                format!(
                    "{}: {} to {}",
                    ball(id),
                    motion_label(from),
                    motion_label(to)
                )
            }
            EventKind::Cushion { ball: id, cushion } => {
                format!("{} hit the {} cushion", ball(id), cushion_label(cushion))
            }
            EventKind::Jaw { ball: id, pocket } => {
                format!(
                    "{} hit a jaw of the {} pocket",
                    ball(id),
                    pocket_label(pocket)
                )
            }
            EventKind::Pocketed { ball: id, pocket } => {
                format!(
                    "{} pocketed in the {} pocket",
                    ball(id),
                    pocket_label(pocket)
                )
            }
            EventKind::BallBall { a, b } => format!("{} hit {}", ball(a), ball(b)),
        }
    }

    /// The outcome of [`Recording::verify`](billiards_physics::recording::Recording::verify)
    /// for the player. Where the histories differ, the two events are printed with every digit
    /// needed to tell them apart (a strike at 6.0 and one at 6.000001 m/s do not both read
    /// "6.00 m/s").
    pub fn verdict_text(&self, verdict: &Result<Verdict, String>) -> String {
        match verdict {
            Ok(Verdict::Reproduced { events }) => {
                format!("reproduced bit for bit ({events} events)")
            }
            Ok(Verdict::Differs {
                index,
                recorded,
                replayed,
            }) => {
                let (recorded, replayed) =
                    self.tell_apart(recorded.as_deref(), replayed.as_deref());
                format!("differs at event {index}: recorded {recorded}, re-simulated {replayed}")
            }
            Err(error) => format!("cannot re-simulate: {error}"),
        }
    }

    /// The two events of a difference, in words and with their exact numbers (shortest text
    /// that reads back to the same bits); when even those agree, the first differing state.
    fn tell_apart(&self, a: Option<&Event>, b: Option<&Event>) -> (String, String) {
        let exact = |e: Option<&Event>| {
            e.map_or("nothing".to_owned(), |e| {
                let what = match e.kind {
                    EventKind::Strike { ball, shot } => format!(
                        "strike: {} at {} rad, {} m/s, tip {}/{} R",
                        self.ball_name(ball),
                        shot.angle,
                        shot.speed,
                        shot.tip.side,
                        shot.tip.height
                    ),
                    _ => self.describe(e),
                };
                format!("{what} at {} s", e.time)
            })
        };
        let (mut ta, mut tb) = (exact(a), exact(b));
        if ta == tb
            && let (Some(a), Some(b)) = (a, b)
            && let Some((id, sa, sb)) = a
                .states_after()
                .zip(b.states_after())
                .map(|((id, sa), (_, sb))| (id, sa, sb))
                .find(|(_, sa, sb)| format!("{sa:?}") != format!("{sb:?}"))
        {
            let name = self.ball_name(id);
            ta.push_str(&format!(" leaving {name} at {:?}", sa));
            tb.push_str(&format!(" leaving {name} at {:?}", sb));
        }
        (ta, tb)
    }

    /// A ball in words, as the game whose table it is names it
    /// ([`billiards_rules::catalog::of_table`]): snooker's by colour ("pink"; every red is
    /// "red"), carom's white, yellow and red (UMB), pool's by number ("cue ball", "ball 3").
    fn ball_name(&self, id: usize) -> String {
        let game = billiards_rules::catalog::of_table(&self.recording.table);
        (game.ball_word)(self.number(id))
    }
}

fn cushion_label(cushion: Cushion) -> &'static str {
    match cushion {
        Cushion::Head => "head",
        Cushion::Foot => "foot",
        Cushion::Left => "left",
        Cushion::Right => "right",
    }
}

fn pocket_label(pocket: Pocket) -> &'static str {
    match pocket {
        Pocket::HeadLeft => "head-left corner",
        Pocket::HeadRight => "head-right corner",
        Pocket::SideLeft => "left side",
        Pocket::SideRight => "right side",
        Pocket::FootLeft => "foot-left corner",
        Pocket::FootRight => "foot-right corner",
    }
}

fn motion_label(motion: Motion) -> &'static str {
    match motion {
        Motion::Stationary => "rest",
        Motion::Sliding => "sliding",
        Motion::Rolling => "rolling",
        Motion::Airborne => "in the air",
        Motion::Spinning => "spinning in place",
        Motion::Pocketed(_) => "pocketed",
        Motion::OffTable => "off the table",
    }
}
