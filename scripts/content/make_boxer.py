#!/usr/bin/env python3
"""Generate content/boxer/boxer.gltf: the boxer skeleton, per-bone physics and render meshes.

Standard library only. Run from anywhere:  python3 scripts/content/make_boxer.py
Writes one .gltf with an embedded base64 buffer; the JSON is indented with short number arrays
kept on one line so that regenerated files diff well. The output is deterministic.

Conventions: everything below is built in the engine's frame (Z up, facing +X, left = +Y,
metres / kg / s / rad) and turned into glTF's frame (+Y up, facing +Z, left = +X) only when the file
is written (to_gltf below; engine/assets/frame.h undoes it on load). Rest pose: standing straight,
arms hanging straight down. Every node's translation is its joint position in the parent's
frame and every rest rotation is identity, so bone frames are world-aligned at rest.
Physics lives in each bone node's extras["physics"]; the schema is documented in
content/README.md (an extension in the spirit of KHR_physics_rigid_bodies).
"""
import base64
import json
import math
import os
import struct
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
OUT = os.path.join(ROOT, "content", "boxer", "boxer.gltf")

TOTAL_MASS = 75.0  # kg, boxer with gloves
GLOVE_MASS = 0.30  # kg added to each hand segment
BODY_MASS = TOTAL_MASS - 2 * GLOVE_MASS  # de Leva fractions apply to the bare body

# de Leva (1996), "Adjustments to Zatsiorsky-Seluyanov's segment inertia parameters", male.
# Trunk 43.46% split into lower (pelvis) / middle (abdomen) / upper (chest) trunk.
DE_LEVA = {
    "head": 0.0694, "pelvis": 0.1117, "abdomen": 0.1633, "chest": 0.1596,
    "upper_arm": 0.0271, "forearm": 0.0162, "hand": 0.0061,
    "thigh": 0.1416, "shank": 0.0433, "foot": 0.0137,
}
assert abs(sum(DE_LEVA[k] * (1 if k in ("head", "pelvis", "abdomen", "chest") else 2) for k in DE_LEVA) - 1.0) < 1e-9

# Shape helpers: quaternions are [w, x, y, z]. Capsules are along their local Z.
S = math.sqrt(0.5)
Q_ID = [1.0, 0.0, 0.0, 0.0]
Q_Z_TO_Y = [S, -S, 0.0, 0.0]  # -90 deg about X: local Z -> bone +Y (capsule across the body)


def capsule(r, h, pos, quat=Q_ID):
    return {"type": "capsule", "radius": r, "half_length": h, "pos": pos, "quat": quat}


def sphere(r, pos):
    return {"type": "sphere", "radius": r, "pos": pos, "quat": Q_ID}


def box(he, pos):
    return {"type": "box", "half_extents": he, "pos": pos, "quat": Q_ID}


def limb(length, r, inset=0.01):
    """Capsule along -Z from the joint to the next joint, ends pulled in by `inset`."""
    return capsule(r, length / 2 - r - inset, [0.0, 0.0, -length / 2])


# Joint limits (rad): swing = cone half-angle about the rest bone axis, twist = about the bone axis.
# Shoulder swing 2.6 (~150 deg) covers raising the arm nearly overhead from hanging; hip 1.9 a high
# knee. Real joints are not symmetric cones (hip abduction ~0.8 vs flexion ~2.1, ankle plantar
# ~0.8 vs dorsi ~0.35), so these cones are generous sideways; the pose servo, not the limit,
# is what keeps the boxer in realistic poses.
BALL = {
    "abdomen": (0.5, 0.4), "chest": (0.4, 0.4), "head": (0.7, 1.0),
    "upper_arm": (2.6, 1.4), "thigh": (1.9, 0.8), "foot": (0.9, 0.3),
}

# name, parent, offset (joint in parent frame), segment key, joint, shapes
SIDE = {"l": 1.0, "r": -1.0}


def skeleton():
    b = []
    b.append(("pelvis", None, [0.0, 0.0, 0.97], "pelvis", {"joint": "free"},
              [capsule(0.10, 0.06, [0.0, 0.0, 0.02], Q_Z_TO_Y)]))
    b.append(("abdomen", "pelvis", [0.0, 0.0, 0.10], "abdomen", {"joint": "ball"},
              [capsule(0.095, 0.055, [0.0, 0.0, 0.09], Q_Z_TO_Y)]))
    b.append(("chest", "abdomen", [0.0, 0.0, 0.18], "chest", {"joint": "ball"},
              [capsule(0.11, 0.07, [0.0, 0.0, 0.12], Q_Z_TO_Y)]))
    b.append(("head", "chest", [0.0, 0.0, 0.25], "head", {"joint": "ball"},
              [sphere(0.11, [0.0, 0.0, 0.12])]))
    for s in ("l", "r"):
        y = SIDE[s]
        b.append(("upper_arm_" + s, "chest", [0.0, 0.19 * y, 0.19], "upper_arm", {"joint": "ball"},
                  [limb(0.30, 0.055)]))
        # Elbow: positive rotation about (0,-1,0) swings the hanging forearm forward (+X) and up.
        b.append(("forearm_" + s, "upper_arm_" + s, [0.0, 0.0, -0.30], "forearm",
                  {"joint": "hinge", "axis": [0.0, -1.0, 0.0], "range": [0.0, 2.6]},
                  [limb(0.26, 0.05)]))
        b.append(("glove_" + s, "forearm_" + s, [0.0, 0.0, -0.26], "hand", {"joint": "fixed"},
                  [sphere(0.06, [0.0, 0.0, -0.08])]))
    for s in ("l", "r"):
        y = SIDE[s]
        b.append(("thigh_" + s, "pelvis", [0.0, 0.09 * y, -0.04], "thigh", {"joint": "ball"},
                  [limb(0.43, 0.065)]))
        # Knee: positive rotation about (0,1,0) swings the shank back (-X).
        b.append(("shank_" + s, "thigh_" + s, [0.0, 0.0, -0.43], "shank",
                  {"joint": "hinge", "axis": [0.0, 1.0, 0.0], "range": [0.0, 2.5]},
                  [limb(0.42, 0.055)]))
        # Foot box: sole flat at world z = 0 (ankle at z = 0.08), toes forward.
        b.append(("foot_" + s, "shank_" + s, [0.0, 0.0, -0.42], "foot", {"joint": "ball"},
                  [box([0.13, 0.05, 0.04], [0.05, 0.0, -0.04])]))
    # Node order: the bones above reordered so pelvis' children are abdomen, thigh_l, thigh_r and
    # chest's children head, upper_arm_l, upper_arm_r -> depth-first order = the documented order.
    order = ["pelvis", "abdomen", "chest", "head", "upper_arm_l", "forearm_l", "glove_l",
             "upper_arm_r", "forearm_r", "glove_r", "thigh_l", "shank_l", "foot_l",
             "thigh_r", "shank_r", "foot_r"]
    by_name = {x[0]: x for x in b}
    return [by_name[n] for n in order]


# ---------------------------------------------------------------- small linear algebra
def qmul(a, b):
    aw, ax, ay, az = a
    bw, bx, by, bz = b
    return [aw * bw - ax * bx - ay * by - az * bz, aw * bx + ax * bw + ay * bz - az * by,
            aw * by - ax * bz + ay * bw + az * bx, aw * bz + ax * by - ay * bx + az * bw]


def qrot(q, v):
    w, x, y, z = q
    r = qmul(qmul(q, [0.0] + list(v)), [w, -x, -y, -z])
    return r[1:]


def qmat(q):
    cols = [qrot(q, e) for e in ([1, 0, 0], [0, 1, 0], [0, 0, 1])]
    return [[cols[c][r] for c in range(3)] for r in range(3)]


def add(a, b):
    return [a[i] + b[i] for i in range(3)]


def sub(a, b):
    return [a[i] - b[i] for i in range(3)]


def scale(a, s):
    return [x * s for x in a]


def dot(a, b):
    return sum(a[i] * b[i] for i in range(3))


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def norm(a):
    return math.sqrt(dot(a, a))


def normalize(a):
    n = norm(a)
    return [x / n for x in a] if n > 0 else [0.0, 0.0, 1.0]


# ---------------------------------------------------------------- mass properties
def shape_volume_inertia(s):
    """Volume and unit-density inertia (about the shape centre, shape axes) of a solid shape."""
    if s["type"] == "sphere":
        r = s["radius"]
        v = 4.0 / 3.0 * math.pi * r ** 3
        i = 0.4 * v * r * r
        return v, [i, i, i]
    if s["type"] == "box":
        a, b, c = [2 * x for x in s["half_extents"]]
        v = a * b * c
        return v, [v / 12 * (b * b + c * c), v / 12 * (a * a + c * c), v / 12 * (a * a + b * b)]
    r, h = s["radius"], s["half_length"]
    H = 2 * h
    vc = math.pi * r * r * H  # cylinder
    vs = 4.0 / 3.0 * math.pi * r ** 3  # two hemispheres
    izz = vc * r * r / 2 + vs * 0.4 * r * r
    # hemisphere caps: own inertia 2/5 m r^2 about the flat face centre, shifted to H/2 + 3r/8
    ixx = vc * (r * r / 4 + H * H / 12) + vs * (0.4 * r * r + H * H / 4 + 3 * H * r / 8)
    return vc + vs, [ixx, ixx, izz]


def mass_properties(shapes, mass):
    """Solid shapes of uniform density scaled to `mass`: com (volume centroid) and the inertia
    tensor about the com in bone axes (parallel-axis theorem for several shapes)."""
    parts = [shape_volume_inertia(s) + (s,) for s in shapes]
    vol = sum(p[0] for p in parts)
    com = [sum(p[0] * p[2]["pos"][i] for p in parts) / vol for i in range(3)]
    rho = mass / vol
    I = [[0.0] * 3 for _ in range(3)]
    for v, idiag, s in parts:
        R = qmat(s["quat"])
        d = sub(s["pos"], com)
        for r in range(3):
            for c in range(3):
                rot = sum(R[r][k] * idiag[k] * R[c][k] for k in range(3))
                pa = v * ((dot(d, d) if r == c else 0.0) - d[r] * d[c])
                I[r][c] += rho * (rot + pa)
    off = max(abs(I[0][1]), abs(I[0][2]), abs(I[1][2]))
    assert off < 1e-9, "shapes of a bone must be axis aligned so the inertia is diagonal"
    return com, [I[0][0], I[1][1], I[2][2]]


# ---------------------------------------------------------------- rest-pose overlap check
def seg_seg(p1, q1, p2, q2):
    """Closest distance between segments p1q1 and p2q2 (Ericson, RTCD 5.1.9)."""
    d1, d2, r = sub(q1, p1), sub(q2, p2), sub(p1, p2)
    a, e, f = dot(d1, d1), dot(d2, d2), dot(d2, r)
    eps = 1e-12
    if a <= eps and e <= eps:
        return norm(r)
    if a <= eps:
        s, t = 0.0, min(max(f / e, 0.0), 1.0)
    else:
        c = dot(d1, r)
        if e <= eps:
            t, s = 0.0, min(max(-c / a, 0.0), 1.0)
        else:
            b = dot(d1, d2)
            den = a * e - b * b
            s = min(max((b * f - c * e) / den, 0.0), 1.0) if den > eps else 0.0
            t = (b * s + f) / e
            if t < 0.0:
                t, s = 0.0, min(max(-c / a, 0.0), 1.0)
            elif t > 1.0:
                t, s = 1.0, min(max((b - c) / a, 0.0), 1.0)
    return norm(sub(add(p1, scale(d1, s)), add(p2, scale(d2, t))))


def world_segment(shape, origin):
    """Shape as a swept sphere (segment + radius) in the rest pose; boxes conservatively."""
    c = add(origin, shape["pos"])
    if shape["type"] == "sphere":
        return c, c, shape["radius"]
    if shape["type"] == "box":
        he = shape["half_extents"]
        r = max(he[1], he[2])
        a = [max(he[0] - r, 0.0), 0.0, 0.0]
        return sub(c, a), add(c, a), math.sqrt(he[1] ** 2 + he[2] ** 2)
    axis = qrot(shape["quat"], [0.0, 0.0, shape["half_length"]])
    return sub(c, axis), add(c, axis), shape["radius"]


# ---------------------------------------------------------------- meshes
def blob(rings, segs, radii, h=0.0):
    """Closed UV surface: an ellipsoid (radii) stretched into a capsule by +-h along local Z.
    Shared poles, no seam duplicates, so averaged normals are smooth everywhere."""
    pos = [[0.0, 0.0, radii[2] + h]]
    lats = [math.pi * k / rings for k in range(1, rings)]
    ring_z = []
    for th in lats:
        if abs(th - math.pi / 2) < 1e-9 and h > 0:
            ring_z += [(th, h), (th, -h)]
        else:
            ring_z.append((th, h if th < math.pi / 2 else -h))
    for th, off in ring_z:
        for j in range(segs):
            ph = 2 * math.pi * j / segs
            pos.append([radii[0] * math.sin(th) * math.cos(ph), radii[1] * math.sin(th) * math.sin(ph),
                        radii[2] * math.cos(th) + off])
    pos.append([0.0, 0.0, -radii[2] - h])
    south = len(pos) - 1
    idx = []
    nr = len(ring_z)
    for j in range(segs):
        idx += [0, 1 + j, 1 + (j + 1) % segs]
    for k in range(nr - 1):
        a0, b0 = 1 + k * segs, 1 + (k + 1) * segs
        for j in range(segs):
            j1 = (j + 1) % segs
            idx += [a0 + j, b0 + j, b0 + j1, a0 + j, b0 + j1, a0 + j1]
    last = 1 + (nr - 1) * segs
    for j in range(segs):
        idx += [south, last + (j + 1) % segs, last + j]
    return pos, idx


def rounded_box(he, e=0.25, rings=10, segs=16):
    """Superellipsoid-ish rounded box: sphere directions pushed towards the box faces."""
    pos, idx = blob(rings, segs, [1.0, 1.0, 1.0])
    out = []
    for p in pos:
        out.append([he[i] * math.copysign(abs(p[i]) ** e, p[i]) for i in range(3)])
    return out, idx


def smooth_normals(pos, idx):
    acc = [[0.0, 0.0, 0.0] for _ in pos]
    for t in range(0, len(idx), 3):
        a, b, c = idx[t:t + 3]
        n = cross(sub(pos[b], pos[a]), sub(pos[c], pos[a]))  # area weighted, CCW outward
        for v in (a, b, c):
            acc[v] = add(acc[v], n)
    return [normalize(n) for n in acc]


def place(pos, quat, offset):
    return [add(qrot(quat, p), offset) for p in pos]


def prim(material, pos, idx):
    return {"material": material, "pos": pos, "idx": idx}


MATERIALS = [  # name, base colour, roughness, metallic
    ("skin", [0.80, 0.60, 0.47, 1.0], 0.7, 0.0),
    ("team", [0.80, 0.08, 0.08, 1.0], 0.5, 0.0),  # the game recolours this per boxer (red / blue)
    ("glove", [0.72, 0.06, 0.06, 1.0], 0.35, 0.0),
    ("shoe", [0.08, 0.08, 0.10, 1.0], 0.6, 0.0),
    ("shorts", [0.92, 0.92, 0.90, 1.0], 0.8, 0.0),
]
MAT = {m[0]: i for i, m in enumerate(MATERIALS)}


def capsule_mesh(material, r, h, pos, quat, rings=8, segs=16, radii=None):
    p, i = blob(rings, segs, radii or [r, r, r], h)
    return prim(material, place(p, quat, pos), i)


def bone_mesh(name, shapes):
    s = shapes[0]
    out = []
    if name == "head":  # rounder and a little taller than the collision sphere, plus a neck
        out.append(capsule_mesh(MAT["skin"], 0, 0.0, s["pos"], Q_ID, rings=10, segs=20,
                                radii=[0.105, 0.095, 0.12]))
        out.append(capsule_mesh(MAT["skin"], 0.05, 0.04, [0.0, 0.0, 0.0], Q_ID))
    elif name.startswith("glove"):
        out.append(capsule_mesh(MAT["glove"], 0, 0.0, [0.01, 0.0, -0.09], Q_ID, rings=10, segs=20,
                                radii=[0.08, 0.07, 0.085]))
        out.append(capsule_mesh(MAT["team"], 0.058, 0.025, [0.0, 0.0, -0.01], Q_ID))  # cuff
    elif name.startswith("foot"):
        he = [s["half_extents"][0] + 0.005, s["half_extents"][1] + 0.008, s["half_extents"][2]]
        p, i = rounded_box(he)
        out.append(prim(MAT["shoe"], place(p, Q_ID, s["pos"]), i))
        out.append(capsule_mesh(MAT["shoe"], 0.055, 0.02, [0.0, 0.0, 0.01], Q_ID))  # boot collar
    elif name == "pelvis":
        out.append(capsule_mesh(MAT["shorts"], s["radius"] + 0.012, s["half_length"], s["pos"], s["quat"]))
        out.append(capsule_mesh(MAT["team"], 0.0, 0.0, [0.0, 0.0, 0.09], Q_ID, segs=24,
                                radii=[0.118, 0.175, 0.03], rings=8))  # waistband, flattened
    elif name.startswith("thigh"):
        # Render limbs reach joint to joint (cap centres on the joints) so knees/elbows show no gap.
        out.append(capsule_mesh(MAT["skin"], s["radius"], -s["pos"][2], s["pos"], s["quat"]))
        out.append(capsule_mesh(MAT["shorts"], s["radius"] + 0.012, 0.08, [0.0, 0.0, -0.13], Q_ID))
    else:
        for sh in shapes:
            if sh["type"] == "capsule":
                limb_like = sh["quat"] == Q_ID and sh["pos"][0] == 0.0 and sh["pos"][1] == 0.0 and sh["pos"][2] < 0
                h = -sh["pos"][2] if limb_like else sh["half_length"]
                out.append(capsule_mesh(MAT["skin"], sh["radius"], h, sh["pos"], sh["quat"]))
            elif sh["type"] == "sphere":
                out.append(capsule_mesh(MAT["skin"], sh["radius"], 0.0, sh["pos"], Q_ID))
    return out


# ---------------------------------------------------------------- glTF writing
# Engine frame -> glTF frame. The engine is Z up facing +X (left +Y); glTF 2.0 is +Y up with the asset
# facing +Z (so its left is +X). Engine (x, y, z) = glTF (z, x, y): a cyclic permutation of the axes,
# i.e. a proper rotation (120 deg about (1, 1, 1)) with no sign flips. Applied to every position,
# direction, quaternion vector part and principal-moment triple, it only moves numbers, so the loader's
# inverse (engine/assets/frame.h) returns the engine's values bit for bit. Keep the two in step.
def to_gltf(v):
    return [v[1], v[2], v[0]]


def quat_to_gltf(q):  # [w, x, y, z] -> [w, x, y, z] with the vector part in glTF axes
    return [q[0]] + to_gltf(q[1:])


def physics_to_gltf(phys):
    out = dict(phys)
    for key in ("axis", "com", "inertia"):  # inertia: principal moments about the frame's axes
        if key in out:
            out[key] = to_gltf(out[key])
    shapes = []
    for sh in phys["shapes"]:
        sh = dict(sh)
        sh["pos"] = to_gltf(sh["pos"])
        sh["quat"] = quat_to_gltf(sh["quat"])
        if "half_extents" in sh:
            sh["half_extents"] = to_gltf(sh["half_extents"])
        shapes.append(sh)
    out["shapes"] = shapes
    return out


def r6(x):
    if isinstance(x, float):  # drop float noise below 1e-9, then keep 6 significant digits
        v = float("%.6g" % round(x, 9))
        return 0.0 if v == 0 else v
    if isinstance(x, list):
        return [r6(v) for v in x]
    if isinstance(x, dict):
        return {k: r6(v) for k, v in x.items()}
    return x


def dumps(obj, indent=0):
    """JSON with 2-space indent, arrays of scalars on one line (diff friendly)."""
    pad = "  " * indent
    if isinstance(obj, dict):
        if not obj:
            return "{}"
        items = [pad + "  " + json.dumps(k) + ": " + dumps(v, indent + 1) for k, v in obj.items()]
        return "{\n" + ",\n".join(items) + "\n" + pad + "}"
    if isinstance(obj, list):
        if all(not isinstance(v, (dict, list)) for v in obj) or all(
                isinstance(v, list) and all(not isinstance(w, (dict, list)) for w in v) for v in obj):
            return "[" + ", ".join(dumps(v, indent) for v in obj) + "]"
        return "[\n" + ",\n".join(pad + "  " + dumps(v, indent + 1) for v in obj) + "\n" + pad + "]"
    return json.dumps(obj)


class Buffer:
    def __init__(self):
        self.data = bytearray()
        self.views = []
        self.accessors = []

    def add(self, raw, target, ctype, count, type_, minv=None, maxv=None):
        while len(self.data) % 4:
            self.data.append(0)
        self.views.append({"buffer": 0, "byteOffset": len(self.data), "byteLength": len(raw), "target": target})
        self.data += raw
        acc = {"bufferView": len(self.views) - 1, "componentType": ctype, "count": count, "type": type_}
        if minv is not None:
            acc["min"], acc["max"] = minv, maxv
        self.accessors.append(acc)
        return len(self.accessors) - 1

    def vec3(self, vs):
        """Bounds from the stored float32 values, written exactly (build() keeps r6 away from them):
        the validator checks min/max against the data bit for bit."""
        vs = [to_gltf(v) for v in vs]
        raw = b"".join(struct.pack("<3f", *v) for v in vs)
        f32 = [[struct.unpack("<f", struct.pack("<f", c))[0] for c in v] for v in vs]
        mn = [min(v[i] for v in f32) for i in range(3)]
        mx = [max(v[i] for v in f32) for i in range(3)]
        return self.add(raw, 34962, 5126, len(vs), "VEC3", mn, mx)

    def indices(self, idx):
        raw = struct.pack("<%dH" % len(idx), *idx)
        return self.add(raw, 34963, 5123, len(idx), "SCALAR")


def segment_mass(seg):
    return DE_LEVA[seg] * BODY_MASS + (GLOVE_MASS if seg == "hand" else 0.0)


def subtree_mass(bones, name):
    seg = next(b[3] for b in bones if b[0] == name)
    return segment_mass(seg) + sum(subtree_mass(bones, b[0]) for b in bones if b[1] == name)


def build():
    bones = skeleton()
    names = [b[0] for b in bones]
    world = {}
    nodes, meshes, bone_extras = [], [], []
    buf = Buffer()
    for name, parent, offset, seg, joint, shapes in bones:
        world[name] = offset if parent is None else add(world[parent], offset)
        mass = segment_mass(seg)
        com, inertia = mass_properties(shapes, mass)
        phys = dict(joint)
        key = seg if seg in BALL else None
        if phys["joint"] == "ball":
            phys["swing_limit"], phys["twist_limit"] = BALL[key]
        phys["mass"] = mass
        phys["com"] = com
        phys["inertia"] = inertia
        # Damping ~1-3 N m s/rad and armature ~0.01-0.05 kg m^2, scaled by the mass the joint moves
        # (the bone and everything below it; 15 kg and more -> the top of the range).
        size = min(subtree_mass(bones, name) / 15.0, 1.0)
        if phys["joint"] == "free":
            phys["damping"], phys["armature"] = 0.0, 0.0
        elif phys["joint"] == "fixed":
            phys["damping"], phys["armature"] = 0.0, 0.0
        else:
            phys["damping"] = 1.0 + 2.0 * size
            phys["armature"] = 0.01 + 0.04 * size
        phys["shapes"] = shapes
        prims = []
        for p in bone_mesh(name, shapes):
            n = smooth_normals(p["pos"], p["idx"])
            prims.append({"attributes": {"POSITION": buf.vec3(p["pos"]), "NORMAL": buf.vec3(n)},
                          "indices": buf.indices(p["idx"]), "material": p["material"], "mode": 4})
        meshes.append({"name": name + "_mesh", "primitives": prims})
        node = {"name": name, "translation": to_gltf(offset), "mesh": len(meshes) - 1,
                "extras": {"physics": physics_to_gltf(phys)}}
        kids = [names.index(b[0]) for b in bones if b[1] == name]
        if kids:
            node["children"] = kids
        nodes.append(node)

    # Pairs (not parent/child: the engine always excludes those) whose shapes touch at rest.
    exclude = []
    for i, a in enumerate(bones):
        for b in bones[i + 1:]:
            if b[1] == a[0] or a[1] == b[0]:
                continue
            close = False
            for sa in a[5]:
                for sb in b[5]:
                    pa, qa, ra = world_segment(sa, world[a[0]])
                    pb, qb, rb = world_segment(sb, world[b[0]])
                    if seg_seg(pa, qa, pb, qb) < ra + rb + 0.005:
                        close = True
            if close:
                exclude.append([a[0], b[0]])

    lowest = min(world[b[0]][2] + s["pos"][2] - s["half_extents"][2] for b in bones for s in b[5]
                 if s["type"] == "box")
    assert abs(lowest) < 1e-9, lowest
    total = sum(n["extras"]["physics"]["mass"] for n in nodes)  # (scalars: frame-free)
    assert abs(total - TOTAL_MASS) < 1e-9, total
    dof = sum({"free": 6, "ball": 3, "hinge": 1, "fixed": 0}[n["extras"]["physics"]["joint"]] for n in nodes)
    assert dof == 37, dof

    gltf = {
        "asset": {"version": "2.0", "generator": "scripts/content/make_boxer.py"},
        "scene": 0,
        "scenes": [{"name": "boxer", "nodes": [0], "extras": {"character": {
            "name": "boxer",
            "root": "pelvis",
            "schema": "content/README.md#bone-physics-extras",
            "units": "metres, kilograms, seconds, radians; glTF frame: +Y up, facing +Z, left +X",
            "total_mass": total,
            "dof": dof,
            "mass_model": "de Leva (1996) male segment fractions of %.1f kg body + %.1f kg per glove; "
                          "inertia of the solid collision shapes scaled to the segment mass" % (BODY_MASS, GLOVE_MASS),
            "team_material": "team",
            "collision": {
                "group_bit": 1, "group_mask": 2,
                "note": "all bones of one character are in collision group bit 1 (mask 1 << 1); "
                        "parent/child pairs are always excluded by the engine; exclude_pairs lists "
                        "the other pairs whose shapes touch in the rest pose",
                "exclude_pairs": exclude,
            },
        }}}],
        "nodes": nodes,
        "meshes": meshes,
        "materials": [{"name": n, "pbrMetallicRoughness": {"baseColorFactor": c, "roughnessFactor": r,
                                                          "metallicFactor": m}} for n, c, r, m in MATERIALS],
        "accessors": None,  # set below, unrounded
        "bufferViews": buf.views,
        "buffers": [{"byteLength": len(buf.data),
                     "uri": "data:application/octet-stream;base64," + base64.b64encode(bytes(buf.data)).decode()}],
    }
    gltf = r6(gltf)
    gltf["accessors"] = buf.accessors
    return gltf


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else OUT
    text = dumps(build()) + "\n"
    os.makedirs(os.path.dirname(out), exist_ok=True)
    with open(out, "w", newline="\n") as f:
        f.write(text)
    print("wrote %s (%d bytes)" % (os.path.relpath(out, ROOT) if out.startswith(ROOT) else out, len(text)))


if __name__ == "__main__":
    main()
