//! Judging one stroke of a frame (WPBSA 3.3 mode of play, 3.10 penalties, 3.12 free ball,
//! 3.14 foul and a miss, 3.3(d) the re-spotted black, 2.1 the end of the frame).

use super::balls::{BLACK, PINK, WHITE, is_colour, is_red, name, value};
use super::frame::{Frame, Snapshot, SnookerError};
use super::geometry::{clear_path, respot_all, snookered};
use super::verdict::{BallOn, Choice, Foul, FrameEnd, NextShot, Verdict};
use crate::game::Seat;
use crate::shot::ShotSummary;
use billiards_physics::Vec2;

/// One stroke as played: its summary, the colour nominated, and the balls on the table
/// before the strike and at rest after it (pocketed balls absent; positions as the caller's
/// recording has them).
#[derive(Clone, Copy, Debug)]
pub struct Stroke<'a> {
    /// What the stroke did.
    pub summary: &'a ShotSummary,
    /// The colour nominated after a red (2.12, 3.3(b)), or the free ball (3.12).
    pub nominated: Option<u8>,
    /// Every ball on the table at the strike (the cue ball included).
    pub before: &'a [(u8, Vec2)],
    /// Every ball on the table at rest.
    pub after: &'a [(u8, Vec2)],
}

fn cue_of(layout: &[(u8, Vec2)]) -> Option<Vec2> {
    layout.iter().find(|&&(n, _)| n == WHITE).map(|&(_, p)| p)
}

fn objects(layout: &[(u8, Vec2)]) -> Vec<(u8, Vec2)> {
    layout
        .iter()
        .copied()
        .filter(|&(n, _)| n != WHITE)
        .collect()
}

/// Balls by number and place.
type Layout = Vec<(u8, Vec2)>;

/// What a stroke was played at: the ball on and its value, the balls that may be potted
/// (the free ball among them, 3.12) and the balls that may be hit first.
struct Aim {
    on: BallOn,
    on_value: u32,
    free: Option<u8>,
    legal: Vec<u8>,
    first_ok: Vec<u8>,
}

/// The frame as it stood at the strike: 3.14 asks whether snookers were needed then, and a
/// put-back restores it.
struct Before {
    on_table: Vec<u8>,
    after_red: bool,
    next: NextShot,
    scores: [u32; 2],
}

impl Frame {
    /// Judges a stroke and moves the frame on (the ball on, the break, the scores, the next
    /// striker); the verdict says which colours to spot and where.
    pub fn play(&mut self, stroke: Stroke<'_>) -> Result<Verdict, SnookerError> {
        let cue_before = self.check_stroke(&stroke)?;
        let aim = self.aim(&stroke)?;
        let potted: Vec<u8> = stroke.summary.pocketed_object_balls().collect();
        let fouls = self.fouls(&stroke, &aim, &potted);
        let before = Before {
            on_table: self.on_table.clone(),
            after_red: self.after_red,
            next: self.next.clone(),
            scores: self.scores,
        };
        let (spots, rest) = self.spot_colours(&stroke, &aim, &fouls, &potted)?;
        let mut verdict = Verdict {
            striker: self.next.striker,
            on: aim.on,
            free_ball: aim.free,
            fouls: fouls.clone(),
            points: 0,
            penalty: 0,
            miss: false,
            spots,
            scores: self.scores,
            end: None,
            next: None,
            text: String::new(),
        };
        if fouls.is_empty() {
            self.score_pots(&aim, &potted, &mut verdict);
        } else {
            self.penalise(&stroke, cue_before, &aim, before, &rest, &mut verdict);
        }
        self.close_verdict(&mut verdict);
        Ok(verdict)
    }

    /// Refuses a stroke the frame cannot take: the frame over, a choice pending, an unknown
    /// ball, no cue ball, or the cue ball in hand outside the D (3.5). Returns the cue ball's
    /// place at the strike.
    fn check_stroke(&self, stroke: &Stroke<'_>) -> Result<Vec2, SnookerError> {
        if self.end.is_some() {
            return Err(SnookerError::Over);
        }
        if !self.next.choices.is_empty() {
            return Err(SnookerError::ChoicePending(self.next.choices.clone()));
        }
        let s = stroke.summary;
        for n in s
            .first_contact
            .iter()
            .chain(s.pocketed.iter().map(|(n, _)| n))
            .chain(s.off_table.iter())
        {
            self.check_ball(*n)?;
        }
        let cue_before = cue_of(stroke.before).ok_or(SnookerError::NoCueBall)?;
        if self.next.in_hand && !self.marks.in_d(cue_before) {
            return Err(SnookerError::NotInD(cue_before.x, cue_before.y));
        }
        Ok(cue_before)
    }

    /// The ball on for this stroke with the nomination checked (2.12, 3.3(b), 3.12): which
    /// balls may be potted and hit first, and the value of the ball on.
    fn aim(&self, stroke: &Stroke<'_>) -> Result<Aim, SnookerError> {
        let s = stroke.summary;
        let base_on = self.ball_on();
        let ordinary = self.balls_on(base_on);
        // 3.12: a free ball is a nominated ball that is not on, after a foul left a snooker.
        let free = stroke
            .nominated
            .filter(|n| self.next.free_ball && !ordinary.contains(n));
        if let Some(n) = stroke.nominated {
            // 2.12: a colour after a red; 3.12: any ball as a free ball; the ball on itself.
            let allowed = self.on_table.contains(&n)
                && match base_on {
                    BallOn::Colour { .. } => is_colour(n),
                    _ => free.is_some() || ordinary.contains(&n),
                };
            if !allowed {
                return Err(SnookerError::BadNomination(n));
            }
        }
        let (on, on_value, mut legal) = match base_on {
            BallOn::Red => (BallOn::Red, 1, ordinary.clone()),
            BallOn::Colour { .. } => {
                // 2.12: an obvious colour (the one hit first) counts as nominated.
                let n = stroke
                    .nominated
                    .or(s.first_contact.filter(|&c| is_colour(c)));
                let v = n.and_then(value).unwrap_or(0);
                (BallOn::Colour { nominated: n }, v, n.into_iter().collect())
            }
            BallOn::Next { colour } => (base_on, value(colour).unwrap_or(0), vec![colour]),
        };
        legal.extend(free);
        // 3.12: with a free ball nominated, it must be hit first (the summary has one first
        // contact, so a simultaneous hit with the ball on is not seen).
        let first_ok: Vec<u8> = match free {
            Some(f) => vec![f],
            None => legal.clone(),
        };
        Ok(Aim {
            on,
            on_value,
            free,
            legal,
            first_ok,
        })
    }

    /// The stroke's fouls (3.10): no ball hit, the wrong ball first, a ball not on potted,
    /// in-off, a ball forced off the table, and (3.12) a free ball that snookers the
    /// opponent.
    fn fouls(&self, stroke: &Stroke<'_>, aim: &Aim, potted: &[u8]) -> Vec<Foul> {
        let s = stroke.summary;
        let mut fouls = Vec::new();
        match s.first_contact {
            None => fouls.push(Foul::NoBallHit),
            Some(hit) if !aim.first_ok.contains(&hit) => {
                fouls.push(Foul::WrongBallFirst { hit, on: aim.on });
            }
            Some(_) => {}
        }
        for &b in potted {
            if !aim.legal.contains(&b) {
                fouls.push(Foul::PottedNotOn { ball: b });
            }
        }
        if s.scratch() {
            fouls.push(Foul::InOff);
        }
        // 3.10: forcing a ball off the table, whichever it is (the cue ball included).
        fouls.extend(s.off_table.iter().map(|&ball| Foul::OffTable { ball }));
        let scored = fouls.is_empty() && !potted.is_empty();
        if let Some(f) = aim.free
            && fouls.is_empty()
            && !scored
            && !(self.on_table.iter().all(|&n| n == PINK || n == BLACK))
            && let Some(cue) = cue_of(stroke.after)
        {
            // 3.12: the free ball may not snooker the opponent on the ball(s) he will be on.
            let after = objects(stroke.after);
            let next_on = self.balls_on(self.ball_on());
            let without: Vec<(u8, Vec2)> = after.iter().copied().filter(|&(n, _)| n != f).collect();
            if snookered(cue, &next_on, &after, self.radius)
                && !snookered(cue, &next_on, &without, self.radius)
            {
                fouls.push(Foul::SnookeredByFreeBall { free_ball: f });
            }
        }
        fouls
    }

    /// Takes the potted balls and those forced off the table out of play and spots the
    /// colours that come back (3.3(c): the colour on potted in order stays down; none after
    /// the re-spotted black; a colour forced off the table is re-spotted, a red is not
    /// replaced, games.md "Balls off the table"). Returns the spots and every ball at rest
    /// once they are placed.
    fn spot_colours(
        &mut self,
        stroke: &Stroke<'_>,
        aim: &Aim,
        fouls: &[Foul],
        potted: &[u8],
    ) -> Result<(Layout, Layout), SnookerError> {
        let off: Vec<u8> = stroke
            .summary
            .off_table_object_balls()
            .filter(|n| !potted.contains(n))
            .collect();
        self.on_table
            .retain(|n| !potted.contains(n) && !off.contains(n));
        let mut to_spot: Vec<u8> = potted
            .iter()
            .chain(off.iter())
            .copied()
            .filter(|&n| is_colour(n))
            .collect();
        if fouls.is_empty()
            && let BallOn::Next { colour } = aim.on
        {
            to_spot.retain(|&c| c != colour);
        }
        if self.respotted_black {
            to_spot.clear();
        }
        let mut rest = stroke.after.to_vec();
        rest.retain(|&(n, _)| !potted.contains(&n) && !off.contains(&n));
        let spots = respot_all(&to_spot, &self.marks, &self.table, self.radius, &rest)?;
        self.on_table.extend(to_spot.iter().copied());
        self.on_table.sort_unstable();
        rest.extend(spots.iter().copied());
        Ok((spots, rest))
    }

    /// 3.10: the value of the ball on, or of the ball hit first, or of a ball potted wrongly
    /// or forced off the table, whichever is highest, at least 4. 3.10(d)(i): after a red, a foul before a colour is
    /// nominated (2.12: none named, none hit first) costs 7; that covers (d)(iii), playing at
    /// reds in successive strokes.
    fn penalty(aim: &Aim, fouls: &[Foul]) -> u32 {
        let mut penalty = aim.on_value.max(4);
        if matches!(aim.on, BallOn::Colour { nominated: None }) {
            penalty = 7;
        }
        for f in fouls {
            let v = match *f {
                Foul::WrongBallFirst { hit, .. } => value(hit).unwrap_or(0),
                Foul::PottedNotOn { ball } | Foul::OffTable { ball } => value(ball).unwrap_or(0),
                _ => 0,
            };
            penalty = penalty.max(v);
        }
        penalty
    }

    /// A foul: the penalty to the opponent, the miss (3.14), and what follows: the frame
    /// awarded after three misses, decided on the black, or the opponent's choice of playing
    /// on, putting the striker back in, or replacing the balls after a miss.
    fn penalise(
        &mut self,
        stroke: &Stroke<'_>,
        cue_before: Vec2,
        aim: &Aim,
        before: Before,
        rest: &[(u8, Vec2)],
        verdict: &mut Verdict,
    ) {
        let opponent = verdict.striker.other();
        let fouls = verdict.fouls.clone();
        let penalty = Self::penalty(aim, &fouls);
        self.scores[opponent.index()] += penalty;
        verdict.penalty = penalty;
        verdict.miss = self.miss(stroke, cue_before, aim, &before, &fouls);
        // 3.14: a miss with both edges of a ball on in view counts towards three.
        let full_view = !snookered(
            cue_before,
            &aim.first_ok,
            &objects(stroke.before),
            self.radius,
        );
        self.full_view_misses = if verdict.miss && full_view {
            self.full_view_misses + 1
        } else {
            0
        };
        self.current_break = 0;
        let black_alone = before.on_table == [BLACK];
        if self.full_view_misses >= 3 {
            self.end = Some((opponent, FrameEnd::ThreeMisses));
            verdict.end = self.end;
        } else if self.respotted_black || black_alone {
            self.finish(opponent, black_alone, verdict);
        } else {
            self.offer_choices(stroke, before, rest, verdict);
        }
        let list: Vec<String> = fouls.iter().map(ToString::to_string).collect();
        verdict.text = format!(
            "{}: {}: {} points to {}",
            if verdict.miss {
                "foul and a miss"
            } else {
                "foul"
            },
            list.join("; "),
            penalty,
            self.name(opponent)
        );
    }

    /// 3.14: a miss when a ball on could be reached in a straight line, unless either player
    /// needed snookers before or after the stroke. Clears the colour on after a red (the
    /// foul ends the turn).
    fn miss(
        &mut self,
        stroke: &Stroke<'_>,
        cue_before: Vec2,
        aim: &Aim,
        before: &Before,
        fouls: &[Foul],
    ) -> bool {
        let failed_contact = fouls
            .iter()
            .any(|f| matches!(f, Foul::NoBallHit | Foul::WrongBallFirst { .. }));
        let needed_before = {
            let mut f = self.clone();
            f.scores = before.scores;
            f.on_table = before.on_table.clone();
            f.after_red = before.after_red;
            f.snookers_required(Seat::A) + f.snookers_required(Seat::B) > 0
        };
        self.after_red = false;
        let needed_after = self.snookers_required(Seat::A) + self.snookers_required(Seat::B) > 0;
        let reachable = !aim.first_ok.is_empty()
            && clear_path(
                cue_before,
                &aim.first_ok,
                &objects(stroke.before),
                self.radius,
            );
        failed_contact && reachable && !needed_before && !needed_after
    }

    /// After a foul that does not end the frame: the opponent is next and chooses (3.14) to
    /// play on, put the striker back in, or (after a miss) have the balls replaced; the
    /// state before the stroke is kept for the last two. 3.12: a free ball if the cue ball
    /// (not in hand) is left snookered.
    fn offer_choices(
        &mut self,
        stroke: &Stroke<'_>,
        before: Before,
        rest: &[(u8, Vec2)],
        verdict: &Verdict,
    ) {
        self.before_foul = Some(Snapshot {
            layout: stroke.before.to_vec(),
            on_table: before.on_table,
            after_red: before.after_red,
            next: NextShot {
                choices: Vec::new(),
                ..before.next
            },
        });
        // 3.5 (in hand in the D) after an in-off, and after the cue ball forced off the table.
        let in_hand = stroke.summary.scratch() || stroke.summary.cue_off_table();
        let next_on = self.ball_on();
        let free_ball = !in_hand
            && cue_of(rest).is_some_and(|c| {
                snookered(c, &self.balls_on(next_on), &objects(rest), self.radius)
            });
        let mut choices = vec![Choice::PlayOn, Choice::PutBack];
        if verdict.miss {
            choices.push(Choice::Replace);
        }
        self.next = NextShot {
            striker: verdict.striker.other(),
            on: next_on,
            in_hand,
            free_ball,
            choices,
        };
    }

    /// A fair stroke: the points of the balls potted (3.3) go to the striker's break, who
    /// plays again if he scored; the last colour potted (or the re-spotted black) ends the
    /// frame.
    fn score_pots(&mut self, aim: &Aim, potted: &[u8], verdict: &mut Verdict) {
        let striker = verdict.striker;
        let opponent = striker.other();
        let points = match aim.on {
            BallOn::Red => potted.len() as u32,
            BallOn::Colour { nominated } => nominated
                .filter(|c| potted.contains(c))
                .and_then(value)
                .unwrap_or(0),
            BallOn::Next { .. } => {
                if potted.is_empty() {
                    0
                } else {
                    aim.on_value
                }
            }
        };
        verdict.points = points;
        self.full_view_misses = 0;
        self.scores[striker.index()] += points;
        let ended_colours = self.on_table.is_empty();
        if points > 0 {
            self.current_break += points;
            let best = &mut self.highest_break[striker.index()];
            *best = (*best).max(self.current_break);
            self.after_red = aim.on == BallOn::Red;
            verdict.text = format!(
                "{} pots {}: {points} point{}, break {}",
                self.name(striker),
                describe(potted),
                if points == 1 { "" } else { "s" },
                self.current_break
            );
        } else {
            self.after_red = false;
            self.current_break = 0;
            verdict.text = format!(
                "{} pots nothing: {} to play",
                self.name(striker),
                self.name(opponent)
            );
        }
        if ended_colours || (self.respotted_black && points > 0) {
            self.finish(striker, true, verdict);
        } else {
            self.next = NextShot {
                striker: if points > 0 { striker } else { opponent },
                on: self.ball_on(),
                in_hand: false,
                free_ball: false,
                choices: Vec::new(),
            };
        }
    }

    /// The verdict's final scores and next stroke, and the end of its sentence: the frame's
    /// winner (2.1), or the tie that re-spots the black (3.3(d)).
    fn close_verdict(&self, verdict: &mut Verdict) {
        verdict.scores = self.scores;
        verdict.next = self.end.is_none().then(|| self.next.clone());
        if let Some((w, how)) = verdict.end {
            verdict.text += &format!(
                "; {} wins the frame {} ({}-{})",
                self.name(w),
                how,
                self.scores[0],
                self.scores[1]
            );
        } else if self.next.choices.contains(&Choice::BlackFirst(Seat::A)) {
            verdict.text += &format!(
                "; level at {}-{}: the black is re-spotted",
                self.scores[0], self.scores[1]
            );
        }
    }

    /// The frame's last stroke: decided on points (2.1(c)), by the re-spotted black, or a tie
    /// that re-spots the black (3.3(d)). `by` takes the frame if the black decides it.
    fn finish(&mut self, by: Seat, on_points: bool, verdict: &mut Verdict) {
        let [a, b] = self.scores;
        if self.respotted_black {
            self.end = Some((by, FrameEnd::RespottedBlack));
        } else if on_points && a != b {
            let w = if a > b { Seat::A } else { Seat::B };
            self.end = Some((w, FrameEnd::Points));
        } else {
            // 3.3(d): a tie: the black is spotted, the cue ball in hand, the players' toss
            // decides who plays first.
            self.respotted_black = true;
            self.on_table = vec![BLACK];
            self.after_red = false;
            self.current_break = 0;
            verdict.spots = vec![(BLACK, self.marks.black)];
            self.next = NextShot {
                striker: by,
                on: BallOn::Next { colour: BLACK },
                in_hand: true,
                free_ball: false,
                choices: vec![Choice::BlackFirst(Seat::A), Choice::BlackFirst(Seat::B)],
            };
        }
        verdict.end = self.end;
    }
}

/// "the red", "2 reds", "the blue", "a red and the pink".
fn describe(potted: &[u8]) -> String {
    let reds = potted.iter().filter(|&&n| is_red(n)).count();
    let mut parts = Vec::new();
    match reds {
        0 => {}
        1 => parts.push("a red".to_owned()),
        n => parts.push(format!("{n} reds")),
    }
    parts.extend(
        potted
            .iter()
            .filter(|&&n| !is_red(n))
            .map(|&n| format!("the {}", name(n))),
    );
    parts.join(" and ")
}
