#!/usr/bin/env python3
"""Writes the standard drills, assets/drills/*.json: the geometry worked out here (9-ft WPA
table, 15 mm jaws, the game's table), the rest of each drill as written below."""
import json, math, os

INCH = 0.0254
L, W = 100 * INCH, 50 * INCH
CORNER, SIDE = 4.5 * INCH, 5 * INCH
R = 0.5 * 2.25 * INCH
TABLE = {"length": L, "width": W, "corner_mouth": CORNER, "side_mouth": SIDE,
         "pockets": {"kind": "jaws", "radius": 0.015}}
HX, HY, LEG = L / 2, W / 2, CORNER / math.sqrt(2)

def target(pocket):
    """Where a ball's centre aims into a pocket (as the computer's candidates do)."""
    s = {"foot_right": (1, -1), "foot_left": (1, 1), "head_right": (-1, -1), "head_left": (-1, 1)}
    if pocket in s:
        sx, sy = s[pocket]
        return (sx * (HX - LEG / 2), sy * (HY - LEG / 2))
    return (0.0, HY if pocket == "side_left" else -HY)

def unit(a, b):
    d = (b[0] - a[0], b[1] - a[1]); n = math.hypot(*d); return (d[0] / n, d[1] / n)

def add(p, u, k): return (p[0] + u[0] * k, p[1] + u[1] * k)

def rot(u, deg):
    c, s = math.cos(math.radians(deg)), math.sin(math.radians(deg))
    return (u[0] * c - u[1] * s, u[0] * s + u[1] * c)

def xy(p): return {"x": round(p[0], 4), "y": round(p[1], 4)}

def drill(file, name, desc, game, balls, goals, shots=1):
    d = {"name": name, "description": desc, "tries": 10, "shots": shots,
         "position": {"game": game, "table": TABLE,
                      "balls": [{"number": n, "position": xy(p)} for n, p in balls]},
         "goals": goals}
    with open(os.path.join("assets/drills", file), "w") as f:
        json.dump(d, f, indent=2); f.write("\n")

def circle(c, r): return {"kind": "cue_ball_in", "zone": {"shape": "circle", "centre": xy(c), "radius": r}}

def pot(ball, pocket, cushions=0):
    g = {"kind": "pocket", "ball": ball, "pocket": pocket}
    if cushions: g["cushions"] = cushions
    return g

NOFOUL = {"kind": "no_foul"}

def straight(obj, pocket, back):
    u = unit(obj, target(pocket))
    return u, add(obj, u, -(2 * R + back))

# 1-3: straight in, the cue ball's stop, draw and follow.
o = (0.70, -0.25); u, cue = straight(o, "foot_right", 0.6)
drill("01-stop-shot.json", "Stop shot", "Straight in to the foot right corner; the cue ball stops dead where it hit the 1 (within 10 cm).",
      "free_play", [(0, cue), (1, o)], [pot(1, "foot_right"), circle(add(o, u, -2 * R), 0.10)])
o = (0.70, 0.25); u, cue = straight(o, "foot_left", 0.5)
drill("02-draw-shot.json", "Draw shot", "Straight in to the foot left corner; draw the cue ball back 40 cm (within 12 cm).",
      "free_play", [(0, cue), (1, o)], [pot(1, "foot_left"), circle(add(o, u, -(2 * R + 0.40)), 0.12)])
o = (0.50, -0.20); u, cue = straight(o, "foot_right", 0.5)
drill("03-follow-shot.json", "Follow shot", "Straight in to the foot right corner; follow the cue ball 35 cm after the 1 without scratching (within 12 cm).",
      "free_play", [(0, cue), (1, o)], [pot(1, "foot_right"), circle(add(o, u, 0.35), 0.12)])

def cut(obj, pocket, deg, back):
    u = unit(obj, target(pocket)); g = add(obj, u, -2 * R)
    return add(g, rot(u, deg), -back)

# 4-5: cut angles.
o = (0.75, -0.30)
drill("04-cut-30.json", "30 degree cut", "Cut the 1 at 30 degrees into the foot right corner, no scratch.",
      "free_play", [(0, cut(o, "foot_right", 30, 0.8)), (1, o)], [pot(1, "foot_right"), NOFOUL])
o = (0.85, 0.35)
drill("05-thin-cut.json", "Thin cut", "A thin cut, 60 degrees, of the 1 into the foot left corner, no scratch.",
      "free_play", [(0, cut(o, "foot_left", -60, 0.6)), (1, o)], [pot(1, "foot_left"), NOFOUL])

# 6: cross-side bank off the right rail into the left side pocket.
o = (0.15, -0.48)
img = (target("side_left")[0], 2 * -(HY - R) - (HY + R / 2))
ub = unit(o, img)
# The cue ball comes in at a 35 degree cut, so it leaves the 1's way back from the rail.
drill("06-bank.json", "Cross-side bank", "Bank the 1 off the near long rail into the far side pocket.",
      "free_play", [(0, add(add(o, ub, -2 * R), rot(ub, 35), -0.6)), (1, o)], [pot(1, "side_left", 1), NOFOUL])

# 7: a kick: the 2 blocks the straight way to the 1 (9-ball: the 1 first, WPA 6.2).
drill("07-kick.json", "One-rail kick", "The 2 hides the 1: kick off a cushion and hit the 1 first, with a legal shot (9-ball: the 1 first, a rail after contact).",
      "nine_ball", [(0, (-0.60, -0.10)), (1, (0.95, -0.10)), (2, (0.25, -0.10))],
      [{"kind": "first_contact", "ball": 1, "cushions": 1}, NOFOUL])

# 8: 9-ball, 7-8-9 run-out in one visit.
drill("08-run-out-789.json", "Run out 7-8-9", "9-ball: pocket the 7, the 8 and the 9 in order in one visit.",
      "nine_ball", [(0, (-0.20, 0.05)), (7, (0.80, 0.40)), (8, (0.35, -0.30)), (9, (-0.70, -0.35))],
      [{"kind": "run_out"}], shots=3)

# 9: a safety behind a wall of balls.
wall = [(k + 2, (-0.10, -0.36 + 0.065 * k)) for k in range(5)]
drill("09-safety.json", "Safety", "9-ball: hit the 1 legally, pocket nothing, and leave the cue ball with no straight line to the 1 (hidden behind the other balls).",
      "nine_ball", [(0, (-0.35, 0.25)), (1, (0.70, -0.30))] + wall,
      [NOFOUL, {"kind": "no_pocket"}, {"kind": "hide"}])

# 10: position play: pot the 1, cue ball to a rectangle for the next shot.
o = (0.55, 0.20)
drill("10-position-zone.json", "Position play", "Pot the 1 in the foot left corner and bring the cue ball into the shaded box in the middle of the table, for a shot on the 2 into the head corners.",
      "free_play", [(0, cut(o, "foot_left", -25, 0.5)), (1, o), (2, (-0.90, 0.0))],
      [pot(1, "foot_left"), {"kind": "cue_ball_in", "zone": {"shape": "rect", "min": xy((-0.25, -0.30)), "max": xy((0.25, 0.30))}}])

# 11: a long straight pot the length of the table.
o = (0.90, 0.45); u, cue = straight(o, "foot_left", 1.6)
drill("11-long-pot.json", "Long pot", "A long straight pot of the 1 into the foot left corner from the far end, no scratch.",
      "free_play", [(0, cue), (1, o)], [pot(1, "foot_left"), NOFOUL])
