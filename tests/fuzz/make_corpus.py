#!/usr/bin/env python3
"""Regenerate the fuzzers' seed corpora in tests/fuzz/corpus/<harness>/ (stdlib only, deterministic).

    python3 tests/fuzz/make_corpus.py

Seeds are small on purpose (libFuzzer mutates faster on small inputs): the tiny glTF fixtures of tests/assets/data,
the boxer's skeleton without its meshes (every bone's extras.physics, the scene's collision extras) as .gltf and .glb,
two of the boxer's clips (guard, jab) cut out of content/clips/boxing_clips.gltf, input-event files of every kind,
and command lines (arguments separated by NUL bytes, as fuzz_cli splits them).
"""
import base64
import json
import os
import shutil
import struct

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
CORPUS = os.path.join(HERE, "corpus")
FIXTURES = os.path.join(ROOT, "tests", "assets", "data")


def write(harness, name, data):
    os.makedirs(os.path.join(CORPUS, harness), exist_ok=True)
    if isinstance(data, str):
        data = data.encode()
    with open(os.path.join(CORPUS, harness, name), "wb") as f:
        f.write(data)


def dump(g):
    return json.dumps(g, separators=(",", ":"), sort_keys=True)


def glb(g, bin_chunk=b""):
    """A .glb of the JSON g (its buffer 0 the BIN chunk when given)."""
    js = dump(g).encode()
    js += b" " * ((4 - len(js) % 4) % 4)
    chunks = struct.pack("<I4s", len(js), b"JSON") + js
    if bin_chunk:
        bin_chunk += b"\0" * ((4 - len(bin_chunk) % 4) % 4)
        chunks += struct.pack("<I4s", len(bin_chunk), b"BIN\0") + bin_chunk
    return struct.pack("<4sII", b"glTF", 2, 12 + len(chunks)) + chunks


def boxer_skeleton():
    """The boxer without meshes, materials and buffers: nodes (names, translations, extras.physics, children) and
    the first scene with its character extras."""
    with open(os.path.join(ROOT, "content", "boxer", "boxer.gltf")) as f:
        g = json.load(f)
    nodes = []
    for n in g["nodes"]:
        n = {k: v for k, v in n.items() if k != "mesh"}
        nodes.append(n)
    return {"asset": {"version": "2.0", "generator": "tests/fuzz/make_corpus.py"}, "scene": 0,
            "scenes": [g["scenes"][0]], "nodes": nodes}


def clips_subset(keep):
    """content/clips/boxing_clips.gltf cut down to the animations named in keep, its buffer rebuilt with only the
    accessors they use (each in its own bufferView)."""
    with open(os.path.join(ROOT, "content", "clips", "boxing_clips.gltf")) as f:
        g = json.load(f)
    uri = g["buffers"][0]["uri"]
    data = base64.b64decode(uri.split(",", 1)[1])
    anims = [a for a in g["animations"] if a["name"] in keep]
    new_acc, new_views, blob, remap = [], [], b"", {}

    def take(i):
        if i in remap:
            return remap[i]
        a = dict(g["accessors"][i])
        v = g["bufferViews"][a["bufferView"]]
        n = {"SCALAR": 1, "VEC3": 3, "VEC4": 4}[a["type"]] * a["count"] * 4
        start = v.get("byteOffset", 0) + a.get("byteOffset", 0)
        nonlocal blob
        new_views.append({"buffer": 0, "byteOffset": len(blob), "byteLength": n})
        blob += data[start:start + n]
        a["bufferView"] = len(new_views) - 1
        a.pop("byteOffset", None)
        new_acc.append(a)
        remap[i] = len(new_acc) - 1
        return remap[i]

    for a in anims:
        for s in a["samplers"]:
            s["input"], s["output"] = take(s["input"]), take(s["output"])
        a["extras"]["next"] = [n for n in a["extras"].get("next", []) if n in keep]
    out = {k: g[k] for k in ("asset", "scene", "scenes", "nodes")}
    out["animations"] = anims
    out["accessors"] = new_acc
    out["bufferViews"] = new_views
    out["buffers"] = [{"byteLength": len(blob),
                       "uri": "data:application/octet-stream;base64," + base64.b64encode(blob).decode()}]
    return out, blob


def main():
    shutil.rmtree(CORPUS, ignore_errors=True)
    fixtures = sorted(f for f in os.listdir(FIXTURES) if f.endswith((".gltf", ".glb")))
    skeleton = boxer_skeleton()
    clips, clips_blob = clips_subset({"guard", "jab"})
    clips_glb = dict(clips, buffers=[{"byteLength": len(clips_blob)}])

    # glTF loader: every fixture (good and broken), the skeleton, the clips, as text and binary.
    for f in fixtures:
        with open(os.path.join(FIXTURES, f), "rb") as src:
            write("gltf", f, src.read())
    write("gltf", "boxer_skeleton.gltf", dump(skeleton))
    write("gltf", "clips.glb", glb(clips_glb, clips_blob))

    # Character loader: the skeleton (text and binary) and the character fixtures.
    write("character", "boxer_skeleton.gltf", dump(skeleton))
    write("character", "boxer_skeleton.glb", glb(skeleton))
    for f in ("character_missing_mass.gltf", "hierarchy.gltf"):
        shutil.copy(os.path.join(FIXTURES, f), os.path.join(CORPUS, "character", f))

    # Clip loader (against the boxer's skeleton): guard (looping) and jab (a strike: glove, impact).
    write("clips", "guard_jab.gltf", dump(clips))
    write("clips", "guard_jab.glb", glb(clips_glb, clips_blob))
    guard, _ = clips_subset({"guard"})
    write("clips", "guard.gltf", dump(guard))

    # Input-event files.
    every = {"events": [
        {"t": 0.5, "drag": {"boxer": 0, "bone": "head", "offset": [0, 0.35, 0], "duration": 1.0}},
        {"t": 0.6, "drag": {"boxer": 1, "bone": "chest", "offset": [0, 0, -0.3], "duration": 1.5, "strong": True,
                            "point": [0.01, 0.02, 0.03]}},
        {"t": 1.0, "grab": {"boxer": 1, "bone": "hand_l", "point": [0.1, 0.2, 0.3], "strong": True}},
        {"t": 1.1, "move": {"target": [1, 2, 3]}},
        {"t": 1.2, "release": {}},
        {"t": 1.3, "grab": {"object": 2}},
        {"t": 2.0, "throw": {"object": "ball", "at_boxer": 1, "speed": 8.0}},
        {"t": 2.1, "throw": {"object": "crate", "from": [0, -3, 1], "velocity": [0, 8, 1.5]}},
        {"t": 2.5, "clear": {}},
        {"t": 3.0, "push": {"boxer": 0, "force": [300, 0, 0], "duration": 0.1}},
        {"t": 3.5, "key": {"action": "jab", "boxer": 1}},
        {"t": 4.0, "set": {"boxer": 0, "servo": "person", "balance": "pd", "omega_n": 12.5, "root_spring": "on",
                           "root_limit": 300, "control": "player", "consciousness": 0.5}}]}
    write("input_events", "every_kind.json", json.dumps(every, indent=1))
    write("input_events", "bare_array.json", json.dumps(every["events"][3:6]))
    write("input_events", "keys.json", json.dumps({"events": [
        {"t": 0.1 * i, "key": {"action": a, "boxer": i % 2}} for i, a in enumerate(
            ["jab", "cross", "lead_hook", "rear_hook", "lead_uppercut", "rear_uppercut", "block", "slip_left",
             "slip_right", "duck", "step_forward", "step_back"])]}))
    write("input_events", "out_of_order.json", '{"events": [{"t": 2, "release": {}}, {"t": 1, "clear": {}}]}')
    write("input_events", "broken.json", '{"events": [{"t": 1, "drag": {"boxer": 0,')

    # Command lines (NUL-separated arguments).
    for name, args in {
        "every_value_flag": ["--headless", "--width", "640", "--height=360", "--seconds", "2.5", "--seed", "42",
                             "--scenario", "push", "--screenshot", "a.png", "--report", "r.json", "--servo",
                             "parent-meathook", "--push-dir", "90", "--push-force", "150", "--push-duration", "0.1",
                             "--push-at", "3", "--camera", "closeup", "--ghost", "--render-every", "30",
                             "--root-spring", "on", "--root-spring-max", "80"],
        "match": ["--scenario=match", "--player", "1", "--round-seconds", "60", "--chaos", "2", "--debug",
                  "contacts,com,hits", "--slow", "4", "--input", "in.json", "--record", "out.json", "--balance", "pd",
                  "--servo-wn", "12", "--servo-zeta", "0.9", "--contact-gap", "0.01", "--clip", "jab",
                  "--no-vsync", "--no-validation", "--overlay", "--frames-dir", "f"],
        "graph": ["graph", "--report", "g.json", "--dot", "g.dot", "--content", "content"],
        "clips": ["clips", "--sheet", "sheets", "--width=320"],
        "help": ["--help"],
    }.items():
        write("cli", name, "\0".join(args))


if __name__ == "__main__":
    main()
