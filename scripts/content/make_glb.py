#!/usr/bin/env python3
"""Generate content/boxer/boxer.glb: the boxer you open in a viewer, with every clip as an animation.

Standard library only.  Run after make_boxer.py and make_clips.py:  python3 scripts/content/make_glb.py
(`--check` exits 1 when the committed .glb differs from what the two source files give).

The .glb is not a third source of truth: it is boxer.gltf (nodes, meshes, materials, scene extras)
plus boxing_clips.gltf's animations retargeted by node name onto the boxer's bone nodes, the binary
data copied byte for byte. The bones' physics extras stay in boxer.gltf (what the game loads): any
array or object in a node's extras makes assimp 5.2's exporter abort (SceneCombiner cannot copy
nested metadata), and the .glb is the file for other tools. The render meshes are rigid parts of the bone nodes (no skin), so the
animated node transforms move them. Both inputs are already in glTF's frame (+Y up, facing +Z); the
.glb is too. The game reads the two .gltf files; tests/assets checks that the three agree.
"""
import base64
import json
import os
import struct
import sys

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
BOXER = os.path.join(ROOT, "content", "boxer", "boxer.gltf")
CLIPS = os.path.join(ROOT, "content", "clips", "boxing_clips.gltf")
OUT = os.path.join(ROOT, "content", "boxer", "boxer.glb")


def load(path):
    with open(path, encoding="utf-8") as f:
        doc = json.load(f)
    (buf,) = doc["buffers"]
    prefix = "data:application/octet-stream;base64,"
    assert buf["uri"].startswith(prefix), path + ": expected one embedded base64 buffer"
    data = base64.b64decode(buf["uri"][len(prefix):])
    assert len(data) == buf["byteLength"], path
    return doc, data


def pad4(b, fill=b"\0"):
    return b + fill * (-len(b) % 4)


def build():
    boxer, bdata = load(BOXER)
    clips, cdata = load(CLIPS)
    base = len(pad4(bdata))
    data = pad4(bdata) + cdata
    views = [dict(v) for v in boxer["bufferViews"]]
    view_base = len(views)
    for v in clips["bufferViews"]:
        v = dict(v)
        v["byteOffset"] = v.get("byteOffset", 0) + base
        views.append(v)
    accessors = [dict(a) for a in boxer["accessors"]]
    acc_base = len(accessors)
    for a in clips["accessors"]:
        a = dict(a)
        a["bufferView"] += view_base
        accessors.append(a)
    node_of = {n["name"]: i for i, n in enumerate(boxer["nodes"])}
    anims = []
    for an in clips["animations"]:
        samplers = [dict(s, input=s["input"] + acc_base, output=s["output"] + acc_base) for s in an["samplers"]]
        channels = []
        for ch in an["channels"]:
            name = clips["nodes"][ch["target"]["node"]]["name"]
            if name not in node_of:
                raise SystemExit(f"make_glb: clip '{an['name']}' animates node '{name}', not in {BOXER}")
            channels.append({"sampler": ch["sampler"], "target": dict(ch["target"], node=node_of[name])})
        anims.append({"name": an["name"], "channels": channels, "samplers": samplers, "extras": an["extras"]})
    doc = {
        "asset": {"version": "2.0", "generator": "scripts/content/make_glb.py (boxer.gltf + boxing_clips.gltf)"},
        "scene": boxer["scene"],
        "scenes": boxer["scenes"],
        "nodes": [{k: v for k, v in n.items() if k != "extras"} for n in boxer["nodes"]],
        "meshes": boxer["meshes"],
        "materials": boxer["materials"],
        "animations": anims,
        "accessors": accessors,
        "bufferViews": views,
        "buffers": [{"byteLength": len(data)}],
        "extras": {"clips": clips["extras"],
                   "physics": "per-bone physics: extras.physics of the nodes of content/boxer/boxer.gltf"},
    }
    js = pad4(json.dumps(doc, separators=(",", ":")).encode(), b" ")
    bin_ = pad4(data)
    out = struct.pack("<4sII", b"glTF", 2, 12 + 8 + len(js) + 8 + len(bin_))
    out += struct.pack("<I4s", len(js), b"JSON") + js + struct.pack("<I4s", len(bin_), b"BIN\0") + bin_
    return out


def main(argv):
    out = build()
    if "--check" in argv:
        with open(OUT, "rb") as f:
            same = f.read() == out
        print(("up to date: " if same else "stale (run make_glb.py): ") + os.path.relpath(OUT, ROOT))
        return 0 if same else 1
    with open(OUT, "wb") as f:
        f.write(out)
    print(f"wrote {os.path.relpath(OUT, ROOT)} ({len(out)} bytes)")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
