#!/usr/bin/env python3
"""Convert content/clips/src/*.clip (readable key-frame text) into content/clips/boxing_clips.gltf.

Python 3 stdlib only.  Usage:  python3 scripts/content/make_clips.py [--report] [--check] [--out PATH]
  --report  print per-key knee angles and sole heights
  --check   parse + validate only, do not write the glTF

CLIP FORMAT (one statement per line, '#' starts a comment):
  header (before the first key):
    name <clip>                      must match the file name
    tags <tag>...                    from: guard punch defence footwork reaction fall down getup
    loop yes|no                      loop clips must end with the same pose as they start
    glove l|r                        punches: the striking glove
    impact <seconds>                 punches: time of contact, inside (0, duration)
    next <clip>...                   natural continuations (default: guard)
  keys:
    key <time_s>                     starts a key; times strictly increasing, first key at 0
    base <clip> <key_index>          start this key as a copy of another key (then override below)
    root <x> <y> <z> <heading> [<pitch> <roll>]   pelvis world position (m) and orientation (deg)
    <bone> <rx> <ry> <rz>            ball joint, Euler degrees relative to the parent bone
    <hinge_bone> <flexion>           forearm_l/r (elbow) and shank_l/r (knee): flexion in degrees
    ik l|r <x> <y> <z> <yaw>         place the left/right sole centre at world (x,y,z) with the foot
                                     flat and pointing at <yaw> deg; thigh/shank/foot are solved
                                     (knee towards the foot direction, towards +Z when the leg lies
                                     along it).  'ik l off' drops it.
  Euler order: R = Rz(rz) * Ry(ry) * Rx(rx), i.e. intrinsic Z-Y-X (yaw, then pitch about the new Y,
  then roll about the new X), in the parent frame.  Same order for the root's heading/pitch/roll.
  Axes: facing +X, left = +Y, Z up (the engine's frame; the .clip sources and all the maths here use it).
  Bones not listed keep the rest pose (identity).
  Rest pose: standing straight, arms hanging down.  Elbow hinge axis (0,-1,0), knee hinge (0,1,0).
  Sign hints: ry > 0 tips a bone's +Z forward (torso/head lean forward), so arms and legs (which
  hang along -Z) swing forward with ry < 0; rx < 0 leans the torso left; rx > 0 raises the left arm
  sideways (rx < 0 the right); rz > 0 turns left.

CONVERSION:
  * keys are resampled at ~30 Hz (densify): root, Euler/hinge angles and IK targets follow C1 cubic
    Hermite curves (the engine's tangent rule), and IK feet are re-solved at every resampled key, so
    planted soles stay on the floor between authored keys too (the report checks < 1 cm);
  * where one key has an IK foot and the next poses the leg explicitly (falls, stand-ups), the
    ankle moves on a line, the foot orientation is slerped, and the foot is lifted out of the floor;
  * the file is written in glTF's frame (+Y up, facing +Z, left +X): engine (x, y, z) = glTF (z, x, y),
    the axis permutation of make_boxer.py's to_gltf, applied to translations, quaternion vector parts
    and the direction/point extras; engine/assets/frame.h undoes it on load, bit for bit;
  * output: content/clips/boxing_clips.gltf -- the 16 skeleton nodes (rest offsets as translations,
    joint kind/hinge axis in node extras) and one animation per clip: a LINEAR translation channel
    on the pelvis and LINEAR rotation channels (x,y,z,w, hemisphere-continuous) on every bone, with
    extras {tags, loop, next, source, glove, impact}.  Embedded base64 buffer: one file to commit.
  * ball joints are clamped to the swing/twist limits in content/boxer/boxer.gltf (physics extras,
    swing about the bone's Z axis; the feet's swing capped at 0.6 rad, see CLIP_SWING_CAP); IK-driven
    legs are not clamped, only reported as warnings;
  * errors name the file and line (unknown bone/statement, bad numbers, hinge out of range, IK out
    of reach, base cycles) and exit with status 1.
"""
import base64
import glob
import json
import math
import os
import struct
import sys

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
SRC = os.path.join(ROOT, "content", "clips", "src")
OUT = os.path.join(ROOT, "content", "clips", "boxing_clips.gltf")

# name, parent, offset, kind ('ball' | 'hinge' | 'fixed'), hinge axis, hinge range (deg)
SKELETON = [
    ("pelvis", -1, (0.0, 0.0, 0.97), "ball", None, None),
    ("abdomen", 0, (0.0, 0.0, 0.10), "ball", None, None),
    ("chest", 1, (0.0, 0.0, 0.18), "ball", None, None),
    ("head", 2, (0.0, 0.0, 0.25), "ball", None, None),
    ("upper_arm_l", 2, (0.0, 0.19, 0.19), "ball", None, None),
    ("forearm_l", 4, (0.0, 0.0, -0.30), "hinge", (0.0, -1.0, 0.0), (0.0, 149.0)),
    ("glove_l", 5, (0.0, 0.0, -0.26), "fixed", None, None),
    ("upper_arm_r", 2, (0.0, -0.19, 0.19), "ball", None, None),
    ("forearm_r", 7, (0.0, 0.0, -0.30), "hinge", (0.0, -1.0, 0.0), (0.0, 149.0)),
    ("glove_r", 8, (0.0, 0.0, -0.26), "fixed", None, None),
    ("thigh_l", 0, (0.0, 0.09, -0.04), "ball", None, None),
    ("shank_l", 10, (0.0, 0.0, -0.43), "hinge", (0.0, 1.0, 0.0), (0.0, 143.0)),
    ("foot_l", 11, (0.0, 0.0, -0.42), "ball", None, None),
    ("thigh_r", 0, (0.0, -0.09, -0.04), "ball", None, None),
    ("shank_r", 13, (0.0, 0.0, -0.43), "hinge", (0.0, 1.0, 0.0), (0.0, 143.0)),
    ("foot_r", 14, (0.0, 0.0, -0.42), "ball", None, None),
]
NAMES = [b[0] for b in SKELETON]
INDEX = {n: i for i, n in enumerate(NAMES)}
TAGS = {"guard", "punch", "defence", "footwork", "reaction", "fall", "down", "getup"}
SOLE = (0.04, 0.0, -0.08)  # sole centre in the foot frame (at rest the sole is at z = 0)
L_THIGH, L_SHANK = 0.43, 0.42


class ClipError(Exception):
    pass


# ---------------------------------------------------------------- quaternion / vector helpers (w,x,y,z)
def qmul(a, b):
    aw, ax, ay, az = a
    bw, bx, by, bz = b
    return (aw * bw - ax * bx - ay * by - az * bz, aw * bx + ax * bw + ay * bz - az * by,
            aw * by - ax * bz + ay * bw + az * bx, aw * bz + ax * by - ay * bx + az * bw)


def qconj(q):
    return (q[0], -q[1], -q[2], -q[3])


def qaxis(axis, deg):
    h = math.radians(deg) * 0.5
    s = math.sin(h)
    return (math.cos(h), axis[0] * s, axis[1] * s, axis[2] * s)


def qeuler(rx, ry, rz):
    return qmul(qmul(qaxis((0, 0, 1), rz), qaxis((0, 1, 0), ry)), qaxis((1, 0, 0), rx))


def qrot(q, v):
    p = qmul(qmul(q, (0.0, v[0], v[1], v[2])), qconj(q))
    return (p[1], p[2], p[3])


def qnorm(q):
    n = math.sqrt(sum(c * c for c in q))
    return tuple(c / n for c in q)


def qfrommat(m):  # m[row][col], columns = rotated basis
    tr = m[0][0] + m[1][1] + m[2][2]
    if tr > 0:
        s = math.sqrt(tr + 1.0) * 2
        q = (0.25 * s, (m[2][1] - m[1][2]) / s, (m[0][2] - m[2][0]) / s, (m[1][0] - m[0][1]) / s)
    elif m[0][0] > m[1][1] and m[0][0] > m[2][2]:
        s = math.sqrt(1.0 + m[0][0] - m[1][1] - m[2][2]) * 2
        q = ((m[2][1] - m[1][2]) / s, 0.25 * s, (m[0][1] + m[1][0]) / s, (m[0][2] + m[2][0]) / s)
    elif m[1][1] > m[2][2]:
        s = math.sqrt(1.0 + m[1][1] - m[0][0] - m[2][2]) * 2
        q = ((m[0][2] - m[2][0]) / s, (m[0][1] + m[1][0]) / s, 0.25 * s, (m[1][2] + m[2][1]) / s)
    else:
        s = math.sqrt(1.0 + m[2][2] - m[0][0] - m[1][1]) * 2
        q = ((m[1][0] - m[0][1]) / s, (m[0][2] + m[2][0]) / s, (m[1][2] + m[2][1]) / s, 0.25 * s)
    return qnorm(q)


def add(a, b):
    return (a[0] + b[0], a[1] + b[1], a[2] + b[2])


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def scale(a, s):
    return (a[0] * s, a[1] * s, a[2] * s)


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def normalize(a):
    n = math.sqrt(dot(a, a))
    return scale(a, 1.0 / n)


# ---------------------------------------------------------------- parsing
def parse_file(path):
    clip = {"file": path, "name": None, "tags": [], "loop": None, "glove": None, "impact": None,
            "next": None, "keys": []}
    cur = None

    def err(ln, msg):
        raise ClipError(f"{path}:{ln}: {msg}")

    def nums(ln, toks, n_min, n_max, what):
        if not (n_min <= len(toks) <= n_max):
            err(ln, f"'{what}' expects {n_min}..{n_max} numbers, got {len(toks)}")
        try:
            return [float(t) for t in toks]
        except ValueError:
            err(ln, f"'{what}': not a number in {' '.join(toks)!r}")

    with open(path, encoding="utf-8") as f:
        for ln, raw in enumerate(f, 1):
            line = raw.split("#", 1)[0].strip()
            if not line:
                continue
            tok = line.split()
            w, args = tok[0], tok[1:]
            if w == "key":
                t = nums(ln, args, 1, 1, "key")[0]
                if clip["keys"] and t <= clip["keys"][-1]["time"]:
                    err(ln, "key times must increase")
                if not clip["keys"] and t != 0.0:
                    err(ln, "the first key must be at time 0")
                cur = {"time": t, "line": ln, "base": None, "root": None, "bones": {}, "ik": {}}
                clip["keys"].append(cur)
            elif cur is None:
                if w == "name":
                    if len(args) != 1:
                        err(ln, "'name' expects one word")
                    clip["name"] = args[0]
                elif w == "tags":
                    for t in args:
                        if t not in TAGS:
                            err(ln, f"unknown tag '{t}' (allowed: {' '.join(sorted(TAGS))})")
                    clip["tags"] = args
                elif w == "loop":
                    if args not in (["yes"], ["no"]):
                        err(ln, "'loop' expects yes or no")
                    clip["loop"] = args[0] == "yes"
                elif w == "glove":
                    if args not in (["l"], ["r"]):
                        err(ln, "'glove' expects l or r")
                    clip["glove"] = "glove_" + args[0]
                elif w == "impact":
                    clip["impact"] = nums(ln, args, 1, 1, "impact")[0]
                elif w == "next":
                    if not args:
                        err(ln, "'next' expects clip names")
                    clip["next"] = args
                else:
                    err(ln, f"unknown header statement '{w}'")
            else:
                if w == "base":
                    if len(args) != 2 or not args[1].isdigit():
                        err(ln, "'base' expects <clip> <key_index>")
                    cur["base"] = (args[0], int(args[1]), ln)
                elif w == "root":
                    v = nums(ln, args, 4, 6, "root")
                    cur["root"] = tuple(v + [0.0] * (6 - len(v)))
                elif w == "ik":
                    if not args or args[0] not in ("l", "r"):
                        err(ln, "'ik' expects l|r <x> <y> <z> <yaw> or l|r off")
                    if args[1:] == ["off"]:
                        cur["ik"][args[0]] = None
                    else:
                        cur["ik"][args[0]] = tuple(nums(ln, args[1:], 4, 4, "ik"))
                elif w in INDEX:
                    b = SKELETON[INDEX[w]]
                    if b[3] == "fixed":
                        err(ln, f"bone '{w}' is a fixed joint and cannot be posed")
                    if w == "pelvis":
                        err(ln, "pose the pelvis with 'root'")
                    if b[3] == "hinge":
                        v = nums(ln, args, 1, 1, w)
                        lo, hi = b[5]
                        if not (lo - 1e-9 <= v[0] <= hi + 1e-9):
                            err(ln, f"hinge '{w}' flexion {v[0]} outside [{lo}, {hi}] deg")
                        cur["bones"][w] = ("hinge", v[0])
                    else:
                        cur["bones"][w] = ("euler",) + tuple(nums(ln, args, 3, 3, w))
                else:
                    err(ln, f"unknown bone or statement '{w}'")
    name_ok = os.path.splitext(os.path.basename(path))[0]
    if clip["name"] != name_ok:
        raise ClipError(f"{path}:1: 'name {name_ok}' missing or different from the file name")
    if not clip["tags"]:
        raise ClipError(f"{path}:1: 'tags' missing")
    if clip["loop"] is None:
        raise ClipError(f"{path}:1: 'loop' missing")
    if len(clip["keys"]) < 2:
        raise ClipError(f"{path}: needs at least two keys")
    if "punch" in clip["tags"] and (clip["glove"] is None or clip["impact"] is None):
        raise ClipError(f"{path}:1: punches need 'glove' and 'impact'")
    if clip["impact"] is not None and not (0.0 < clip["impact"] < clip["keys"][-1]["time"]):
        raise ClipError(f"{path}:1: impact {clip['impact']} outside the clip")
    return clip


def resolve(clips):
    """Apply 'base' references; returns per clip a list of flat key specs."""
    cache = {}

    def flat(cname, ki, stack):
        if (cname, ki) in cache:
            return cache[(cname, ki)]
        if (cname, ki) in stack:
            raise ClipError(f"base cycle through {cname} key {ki}")
        c = clips[cname]
        k = c["keys"][ki]
        spec = {"root": None, "bones": {}, "ik": {}}
        if k["base"]:
            bn, bi, ln = k["base"]
            if bn not in clips or bi >= len(clips[bn]["keys"]):
                raise ClipError(f"{c['file']}:{ln}: base {bn} {bi} does not exist")
            b = flat(bn, bi, stack | {(cname, ki)})
            spec = {"root": b["root"], "bones": dict(b["bones"]), "ik": dict(b["ik"])}
        if k["root"]:
            spec["root"] = k["root"]
        for side, v in k["ik"].items():
            spec["ik"][side] = v
        for bname, v in k["bones"].items():
            spec["bones"][bname] = v
            for side in ("l", "r"):  # explicit leg angles replace an inherited IK target
                if bname.endswith("_" + side) and bname.split("_")[0] in ("thigh", "shank", "foot") \
                        and side not in k["ik"]:
                    spec["ik"][side] = None
        if spec["root"] is None:
            raise ClipError(f"{c['file']}:{k['line']}: key has no 'root' (and no base)")
        cache[(cname, ki)] = spec
        return spec

    return {n: [flat(n, i, frozenset()) for i in range(len(c["keys"]))] for n, c in clips.items()}


# ---------------------------------------------------------------- posing
def world_frames(root_pos, rots):
    """FK: per bone world (position, rotation)."""
    pos, rot = [None] * 16, [None] * 16
    for i, (n, p, off, *_r) in enumerate(SKELETON):
        if p < 0:
            pos[i], rot[i] = root_pos, rots[i]
        else:
            pos[i] = add(pos[p], qrot(rot[p], off))
            rot[i] = qmul(rot[p], rots[i])
    return pos, rot


def solve_leg(side, root_pos, root_rot, target, where):
    """Analytic two-bone IK: returns local (thigh, shank, foot) quaternions and knee flexion (deg)."""
    x, y, z, yaw = target
    hip_i = INDEX["thigh_" + side]
    hip = add(root_pos, qrot(root_rot, SKELETON[hip_i][2]))
    foot_rot = qaxis((0, 0, 1), yaw)
    ankle = sub((x, y, z), qrot(foot_rot, SOLE))
    d_vec = sub(ankle, hip)
    d = math.sqrt(dot(d_vec, d_vec))
    if d > L_THIGH + L_SHANK - 1e-4:
        raise ClipError(f"{where}: ik {side}: target out of reach (hip-ankle {d:.3f} m > 0.85 m); "
                        f"lower the root")
    cos_inner = (L_THIGH ** 2 + L_SHANK ** 2 - d * d) / (2 * L_THIGH * L_SHANK)
    knee = math.pi - math.acos(max(-1.0, min(1.0, cos_inner)))
    cos_hip = (L_THIGH ** 2 + d * d - L_SHANK ** 2) / (2 * L_THIGH * d)
    alpha = math.acos(max(-1.0, min(1.0, cos_hip)))
    u = scale(d_vec, 1.0 / d)
    f = (math.cos(math.radians(yaw)), math.sin(math.radians(yaw)), 0.0)
    # knee pole: the foot direction when standing; blends to world up when the leg lies along the
    # foot direction (lying on the back with the feet flat, knees up)
    c = math.sqrt(dot(cross(f, u), cross(f, u)))
    f = normalize(add(scale(f, c), scale((0.0, 0.0, 1.0), 1.0 - c)))
    y_w = cross(f, u)
    if dot(y_w, y_w) < 1e-8:
        raise ClipError(f"{where}: ik {side}: leg parallel to the foot direction")
    y_w = normalize(y_w)
    t = qrot(qaxis(y_w, -math.degrees(alpha)), u)  # thigh direction hip -> knee
    z_w = scale(t, -1.0)
    y_w = normalize(sub(y_w, scale(z_w, dot(y_w, z_w))))
    x_w = cross(y_w, z_w)
    thigh_w = qfrommat([[x_w[0], y_w[0], z_w[0]], [x_w[1], y_w[1], z_w[1]], [x_w[2], y_w[2], z_w[2]]])
    shank_l = qaxis((0, 1, 0), math.degrees(knee))
    shank_w = qmul(thigh_w, shank_l)
    thigh_l = qmul(qconj(root_rot), thigh_w)
    foot_l = qmul(qconj(shank_w), foot_rot)
    return thigh_l, shank_l, foot_l, math.degrees(knee)


FOOT_POINTS = [(0.14, 0.0, -0.08), (-0.05, 0.0, -0.08), (0.14, 0.05, -0.08), (0.14, -0.05, -0.08), SOLE]


def solve_leg_free(side, root_pos, root_rot, ankle, foot_world, pole):
    """Two-bone IK to an ankle position with a given foot world orientation and knee pole direction
    (used where a foot moves between an IK-planted key and a free key). Reach is clamped."""
    hip = add(root_pos, qrot(root_rot, SKELETON[INDEX["thigh_" + side]][2]))
    d_vec = sub(ankle, hip)
    d = math.sqrt(dot(d_vec, d_vec))
    d = min(max(d, 0.02), L_THIGH + L_SHANK - 1e-3)
    u = normalize(d_vec)
    cos_inner = (L_THIGH ** 2 + L_SHANK ** 2 - d * d) / (2 * L_THIGH * L_SHANK)
    knee = math.pi - math.acos(max(-1.0, min(1.0, cos_inner)))
    cos_hip = (L_THIGH ** 2 + d * d - L_SHANK ** 2) / (2 * L_THIGH * d)
    alpha = math.acos(max(-1.0, min(1.0, cos_hip)))
    y_w = cross(pole, u)
    if dot(y_w, y_w) < 1e-10:
        y_w = cross((0.0, 0.0, 1.0), u)
    y_w = normalize(y_w)
    t = qrot(qaxis(y_w, -math.degrees(alpha)), u)
    z_w = scale(t, -1.0)
    y_w = normalize(sub(y_w, scale(z_w, dot(y_w, z_w))))
    x_w = cross(y_w, z_w)
    thigh_w = qfrommat([[x_w[0], y_w[0], z_w[0]], [x_w[1], y_w[1], z_w[1]], [x_w[2], y_w[2], z_w[2]]])
    shank_l = qaxis((0, 1, 0), math.degrees(knee))
    shank_w = qmul(thigh_w, shank_l)
    return qmul(qconj(root_rot), thigh_w), shank_l, qmul(qconj(shank_w), foot_world)


def blend_leg(side, pos, rots, key_a, key_b, u):
    """Leg of a resampled key between an IK key and a free key: the ankle moves on a straight line
    between the two keys' ankles, the foot orientation is slerped, the knee follows the slerped
    joint angles, and the foot is lifted where its toe/heel would go below the floor."""
    names = [b + side for b in ("thigh_", "shank_", "foot_")]
    ends = []
    for kp in (key_a, key_b):
        P, R = world_frames(kp[0], kp[1])
        ends.append((P[INDEX["foot_" + side]], R[INDEX["foot_" + side]]))
    for n in names:
        rots[INDEX[n]] = qslerp(key_a[1][INDEX[n]], key_b[1][INDEX[n]], u)
    P, R = world_frames(pos, rots)
    hip = P[INDEX["thigh_" + side]]
    pole = sub(P[INDEX["shank_" + side]], hip)
    ankle = add(scale(ends[0][0], 1 - u), scale(ends[1][0], u))
    foot_w = qslerp(ends[0][1], ends[1][1], u)
    low = min(add(ankle, qrot(foot_w, p))[2] for p in FOOT_POINTS)
    if low < 0.0:
        ankle = (ankle[0], ankle[1], ankle[2] - low)
    th, sh, ft = solve_leg_free(side, pos, rots[0], ankle, foot_w, pole)
    rots[INDEX[names[0]]], rots[INDEX[names[1]]], rots[INDEX[names[2]]] = th, sh, ft


BOXER = os.path.join(ROOT, "content", "boxer", "boxer.gltf")
# The committed clips were converted when the boxer's ankle cone was 0.6 rad. The physics limit is now
# 0.9 rad (boxer.gltf, since the control commit that raised it) but the clips keep the 0.6 rad clamp:
# with 0.9 the free (not IK-planted) feet of the fall / get-up clips come out differently and the
# game's goldens and balance results change. Drop this cap when the clips are re-tuned on purpose.
CLIP_SWING_CAP = {"foot_l": 0.6, "foot_r": 0.6}


def load_limits():
    """Ball-joint swing/twist limits (rad) from content/boxer/boxer.gltf (physics extras)."""
    try:
        with open(BOXER, encoding="utf-8") as f:
            doc = json.load(f)
    except (OSError, ValueError):
        return {}
    out = {}
    for n in doc.get("nodes", []):
        ph = (n.get("extras") or {}).get("physics") or {}
        if ph.get("joint") == "ball" and n.get("name") in INDEX:
            swing = min(float(ph.get("swing_limit", math.pi)), CLIP_SWING_CAP.get(n["name"], math.inf))
            out[n["name"]] = (swing, float(ph.get("twist_limit", math.pi)))
    return out


def clamp_swing_twist(q, swing_lim, twist_lim):
    """Swing-twist decomposition about the bone's Z axis; clamps both into the joint's limits."""
    w, x, y, z = q
    n = math.hypot(w, z)
    twist = (w / n, 0.0, 0.0, z / n) if n > 1e-9 else (1.0, 0.0, 0.0, 0.0)
    swing = qmul(q, qconj(twist))
    ta = 2 * math.atan2(twist[3], twist[0])
    ta = (ta + math.pi) % (2 * math.pi) - math.pi
    sa = 2 * math.acos(max(-1.0, min(1.0, abs(swing[0]))))
    changed = False
    if abs(ta) > twist_lim:
        ta = math.copysign(twist_lim, ta)
        twist = qaxis((0, 0, 1), math.degrees(ta))
        changed = True
    if sa > swing_lim:
        ax = swing[1:]
        ax = normalize(ax) if dot(ax, ax) > 1e-12 else (1.0, 0.0, 0.0)
        if swing[0] < 0:
            ax = scale(ax, -1.0)
        swing = qaxis(ax, math.degrees(swing_lim))
        changed = True
    return (qnorm(qmul(swing, twist)) if changed else q), changed


def pose_key(spec, where):
    x, y, z, hd, pt, rl = spec["root"]
    rots = [(1.0, 0.0, 0.0, 0.0)] * 16
    rots[0] = qeuler(rl, pt, hd)
    for bname, v in spec["bones"].items():
        b = SKELETON[INDEX[bname]]
        if v[0] == "hinge":
            rots[INDEX[bname]] = qaxis(b[4], v[1])
        else:
            rots[INDEX[bname]] = qeuler(v[1], v[2], v[3])
    knees = {}
    for side, tgt in spec["ik"].items():
        if tgt is None:
            continue
        th, sh, ft, kn = solve_leg(side, (x, y, z), rots[0], tgt, where)
        rots[INDEX["thigh_" + side]], rots[INDEX["shank_" + side]], rots[INDEX["foot_" + side]] = th, sh, ft
        knees[side] = kn
        if kn > SKELETON[INDEX["shank_" + side]][5][1]:
            raise ClipError(f"{where}: ik {side}: knee flexion {kn:.1f} deg beyond the hinge range")
    return (x, y, z), [qnorm(q) for q in rots], knees


def sole_heights(root_pos, rots):
    pos, rot = world_frames(root_pos, rots)
    return {s: add(pos[INDEX["foot_" + s]], qrot(rot[INDEX["foot_" + s]], SOLE))[2] for s in ("l", "r")}



# ---------------------------------------------------------------- densification
DENSE_HZ = 30.0


def _vec(spec, bones):
    v = list(spec["root"])
    for b in bones:
        val = spec["bones"].get(b)
        kind = SKELETON[INDEX[b]][3]
        if val is None:
            v += [0.0] if kind == "hinge" else [0.0, 0.0, 0.0]
        else:
            v += list(val[1:])
    for side in ("l", "r"):
        t = spec["ik"].get(side)
        v += list(t) if t is not None else [float("nan")] * 4
    return v


def _unvec(v, bones):
    spec = {"root": tuple(v[:6]), "bones": {}, "ik": {}}
    i = 6
    for b in bones:
        if SKELETON[INDEX[b]][3] == "hinge":
            spec["bones"][b] = ("hinge", v[i])
            i += 1
        else:
            spec["bones"][b] = ("euler", v[i], v[i + 1], v[i + 2])
            i += 3
    for side in ("l", "r"):
        t = v[i:i + 4]
        i += 4
        spec["ik"][side] = None if any(math.isnan(x) for x in t) else tuple(t)
    return spec


def densify(clip, specs):
    """Resample the authored keys at ~30 Hz: every numeric parameter (root, Euler angles, hinge angles,
    IK targets) follows a C1 cubic Hermite with the engine's tangent rule (time-weighted Catmull-Rom,
    zero velocity at the ends of non-looping clips, wrapped for loops), and planted feet are re-solved
    by IK at every resampled key, so the soles stay on the floor between authored keys too.
    Returns [(time, spec, where, leg_blend)], leg_blend = {side: (key_a, key_b, u)} where one end of
    the segment is IK-driven and the other is not (those legs are slerped between the posed keys)."""
    keys = clip["keys"]
    times = [k["time"] for k in keys]
    n = len(keys)
    bones = sorted({b for s in specs for b in s["bones"]}, key=lambda b: INDEX[b])
    vals = [_vec(s, bones) for s in specs]
    dim = len(vals[0])
    loop = clip["loop"]

    def tangent(k):
        if loop:
            kk = 0 if k == n - 1 else k
            pi, hp = (n - 2, times[n - 1] - times[n - 2]) if kk == 0 else (kk - 1, times[kk] - times[kk - 1])
            ni, hn = kk + 1, times[kk + 1] - times[kk]
        else:
            if k == 0 or k == n - 1:
                return [0.0] * dim
            pi, hp, ni, hn = k - 1, times[k] - times[k - 1], k + 1, times[k + 1] - times[k]
        out = []
        for d in range(dim):
            a, b, c = vals[pi][d], vals[k][d], vals[ni][d]
            if any(math.isnan(x) for x in (a, b, c)):
                out.append(0.0)
            else:
                out.append((hn * (b - a) / hp + hp * (c - b) / hn) / (hp + hn))
        return out

    tans = [tangent(k) for k in range(n)]
    dense = []
    for i in range(n - 1):
        h = times[i + 1] - times[i]
        m = max(1, int(math.ceil(h * DENSE_HZ - 1e-9)))
        for j in range(m):
            u = j / m
            h00, h10, h01, h11 = 2 * u**3 - 3 * u**2 + 1, u**3 - 2 * u**2 + u, -2 * u**3 + 3 * u**2, u**3 - u**2
            v = [h00 * vals[i][d] + h10 * h * tans[i][d] + h01 * vals[i + 1][d] + h11 * h * tans[i + 1][d]
                 for d in range(dim)]
            spec = specs[i] if j == 0 else _unvec(v, bones)  # (NaN * 0 would drop an IK target at u = 0)
            blend = {}
            for side in ("l", "r"):
                a_ik, b_ik = specs[i]["ik"].get(side), specs[i + 1]["ik"].get(side)
                if (a_ik is None) != (b_ik is None) and j > 0:
                    blend[side] = (i, i + 1, h00 * 0 + (3 * u**2 - 2 * u**3))
            where = f"{clip['file']}:{keys[i]['line']}(+{j}/{m})"
            dense.append((times[i] + u * h, spec, where, blend))
    dense.append((times[-1], specs[-1], f"{clip['file']}:{keys[-1]['line']}", {}))
    return dense


def qslerp(a, b, u):
    d = sum(x * y for x, y in zip(a, b))
    if d < 0:
        b, d = tuple(-x for x in b), -d
    if d > 0.9995:
        return qnorm(tuple(x + u * (y - x) for x, y in zip(a, b)))
    th = math.acos(d)
    sa, sb = math.sin((1 - u) * th) / math.sin(th), math.sin(u * th) / math.sin(th)
    return tuple(sa * x + sb * y for x, y in zip(a, b))


# ---------------------------------------------------------------- glTF writer
def to_gltf(v):
    """Engine frame (Z up, facing +X) -> glTF frame (+Y up, facing +Z): engine (x, y, z) = glTF (z, x, y).
    Same permutation as make_boxer.py's to_gltf; numbers are moved, never recomputed."""
    return [v[1], v[2], v[0]]


def write_gltf(clips, posed, path):
    blob = bytearray()
    accessors, views = [], []

    def add_accessor(values, comps, with_minmax=False):
        off = len(blob)
        for v in values:
            blob.extend(struct.pack("<f", v))
        while len(blob) % 4:
            blob.append(0)
        views.append({"buffer": 0, "byteOffset": off, "byteLength": 4 * len(values)})
        acc = {"bufferView": len(views) - 1, "componentType": 5126, "count": len(values) // comps,
               "type": {1: "SCALAR", 3: "VEC3", 4: "VEC4"}[comps]}
        if with_minmax:
            acc["min"], acc["max"] = [min(values)], [max(values)]
        accessors.append(acc)
        return len(accessors) - 1

    nodes = []
    for i, (n, p, off, kind, axis, rng) in enumerate(SKELETON):
        node = {"name": n, "translation": to_gltf(off), "extras": {"joint": kind}}
        if axis:
            node["extras"]["hinge_axis"] = to_gltf(axis)
            node["extras"]["hinge_range_deg"] = list(rng)
        kids = [j for j, b in enumerate(SKELETON) if b[1] == i]
        if kids:
            node["children"] = kids
        nodes.append(node)

    anims = []
    for cname in sorted(clips):
        c = clips[cname]
        keys = posed[cname]
        times = [k[0] for k in keys]
        t_acc = add_accessor(times, 1, True)
        samplers, channels = [], []
        # pelvis translation
        vals = [v for (_t, pos, _r, _k) in keys for v in to_gltf(pos)]
        samplers.append({"input": t_acc, "output": add_accessor(vals, 3), "interpolation": "LINEAR"})
        channels.append({"sampler": 0, "target": {"node": 0, "path": "translation"}})
        for b in range(16):
            vals = []
            prev = None
            for (_t, _p, rots, _k) in keys:
                q = rots[b]
                if prev is not None and sum(a * c2 for a, c2 in zip(q, prev)) < 0:
                    q = tuple(-c2 for c2 in q)  # same hemisphere as the previous key
                prev = q
                vals += to_gltf(q[1:]) + [q[0]]  # glTF order x,y,z,w, vector part in glTF axes
            samplers.append({"input": t_acc, "output": add_accessor(vals, 4), "interpolation": "LINEAR"})
            channels.append({"sampler": len(samplers) - 1, "target": {"node": b, "path": "rotation"}})
        extras = {"tags": c["tags"], "loop": c["loop"], "next": c["next"] or ["guard"],
                  "source": os.path.relpath(c["file"], ROOT)}
        if c["glove"]:
            extras["glove"] = c["glove"]
            extras["impact"] = c["impact"]
        anims.append({"name": cname, "samplers": samplers, "channels": channels, "extras": extras})

    doc = {
        "asset": {"version": "2.0", "generator": "scripts/content/make_clips.py"},
        "scene": 0,
        "scenes": [{"name": "boxer_clips", "nodes": [0]}],
        "nodes": nodes,
        "animations": anims,
        "buffers": [{"byteLength": len(blob),
                     "uri": "data:application/octet-stream;base64," + base64.b64encode(bytes(blob)).decode()}],
        "bufferViews": views,
        "accessors": accessors,
        "extras": {"skeleton": "boxer", "euler_order": "R = Rz*Ry*Rx (intrinsic Z-Y-X), of the .clip sources, engine frame (Z up, facing +X)",
                   "sole_point_in_foot_frame": to_gltf(SOLE),
                   "units": "metres, seconds; glTF frame: +Y up, facing +Z, left +X"},
    }
    with open(path, "w", encoding="utf-8") as f:
        json.dump(doc, f, indent=1)
        f.write("\n")


def main(argv):
    report = "--report" in argv
    check = "--check" in argv
    out = OUT
    args = argv[1:]
    if "--out" in args:  # write elsewhere (tests compare a fresh conversion with the committed file)
        i = args.index("--out")
        out = args[i + 1]
        del args[i:i + 2]
    files = [a for a in args if not a.startswith("--")] or sorted(glob.glob(os.path.join(SRC, "*.clip")))
    try:
        clips = {}
        for p in files:
            c = parse_file(p)
            clips[c["name"]] = c
        for c in clips.values():
            for n in c["next"] or []:
                if n not in clips:
                    raise ClipError(f"{c['file']}:1: next clip '{n}' does not exist")
        flat = resolve(clips)
        posed, worst = {}, 0.0
        limits, warned, clamped = load_limits(), set(), {}
        for n, c in sorted(clips.items()):
            posed[n] = []
            key_posed = [pose_key(spec, f"{c['file']}:{k['line']}") for k, spec in zip(c["keys"], flat[n])]
            for (t, spec, where, blend) in densify(c, flat[n]):
                pos, rots, knees = pose_key(spec, where)
                for side, (ka, kb, u) in blend.items():
                    blend_leg(side, pos, rots, key_posed[ka], key_posed[kb], u)
                # joint limits of the physical boxer: clamp free joints, warn about IK-driven ones
                planted = {("thigh_" + sd, "foot_" + sd) for sd, tg in spec["ik"].items() if tg is not None}
                ik_bones = {b for pair in planted for b in pair}
                for bname, (sl, tl) in limits.items():
                    bi = INDEX[bname]
                    q, changed = clamp_swing_twist(rots[bi], sl * 0.999, tl * 0.999)
                    if not changed:
                        continue
                    if bname in ik_bones:
                        warned.add(f"{c['file']}: {bname} beyond its joint limit (IK-driven, not clamped)")
                    else:
                        rots[bi] = q
                        clamped[n] = clamped.get(n, 0) + 1
                posed[n].append((t, pos, rots, knees))
                soles = sole_heights(pos, rots)
                for side, tgt in spec["ik"].items():
                    if tgt is not None:
                        e = abs(soles[side] - tgt[2])
                        worst = max(worst, e)
                        if e > 0.01:
                            raise ClipError(f"{where}: ik {side}: sole height error {e * 100:.2f} cm > 1 cm")
                if report:
                    ks = " ".join(f"knee_{s}={v:5.1f}" for s, v in sorted(knees.items()))
                    print(f"{n:16s} t={t:5.3f} sole_l={soles['l'] * 100:6.2f}cm "
                          f"sole_r={soles['r'] * 100:6.2f}cm {ks}")
            if c["loop"]:
                a, b = posed[n][0], posed[n][-1]
                dq = max(1 - abs(sum(x * y for x, y in zip(qa, qb))) for qa, qb in zip(a[2], b[2]))
                if dq > 1e-6 or math.dist(a[1], b[1]) > 1e-6:
                    raise ClipError(f"{c['file']}: loop clip must end with its first pose")
    except (ClipError, OSError) as e:
        print(f"error: {e}", file=sys.stderr)
        return 1
    for w in sorted(warned):
        print(f"warning: {w}")
    for n, k in sorted(clamped.items()):
        print(f"note: {n}: {k} joint rotations clamped to the boxer's joint limits")
    print(f"{len(clips)} clips ok; worst IK sole error {worst * 1000:.3f} mm")
    if not check:
        write_gltf(clips, posed, out)
        print(f"wrote {os.path.relpath(out, ROOT)}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
