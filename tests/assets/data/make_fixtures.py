#!/usr/bin/env python3
"""Regenerate the tiny glTF fixtures used by tests/assets/*_test.cpp (stdlib only).

    python3 tests/assets/data/make_fixtures.py

Each fixture is small enough to read by eye; the broken ones are broken on purpose.
Numbers here are in glTF's frame (+Y up, +Z forward); load_gltf returns them in the engine's
(engine (x, y, z) = glTF (z, x, y), engine/assets/frame.h), which is what the tests expect.
"""
import base64
import json
import os
import struct

HERE = os.path.dirname(os.path.abspath(__file__))

# Unit cube: 24 vertices (flat normals per face), 36 indices, centred at the origin.
FACES = [((1, 0, 0), (0, 1, 0), (0, 0, 1)), ((-1, 0, 0), (0, 0, 1), (0, 1, 0)),
         ((0, 1, 0), (0, 0, 1), (1, 0, 0)), ((0, -1, 0), (1, 0, 0), (0, 0, 1)),
         ((0, 0, 1), (1, 0, 0), (0, 1, 0)), ((0, 0, -1), (0, 1, 0), (1, 0, 0))]


def cube():
    pos, nrm, idx = [], [], []
    for n, u, v in FACES:
        base = len(pos)
        for su, sv in ((-1, -1), (1, -1), (1, 1), (-1, 1)):
            pos.append(tuple(0.5 * (n[i] + su * u[i] + sv * v[i]) for i in range(3)))
            nrm.append(n)
        idx += [base, base + 1, base + 2, base, base + 2, base + 3]
    return pos, nrm, idx


def pad4(b, fill=b"\0"):
    return b + fill * ((4 - len(b) % 4) % 4)


def cube_model(index_ctype=5123):
    """Interleaved POSITION/NORMAL (byteStride 24) plus an index view."""
    pos, nrm, idx = cube()
    inter = b"".join(struct.pack("<6f", *(p + n)) for p, n in zip(pos, nrm))
    fmt = {5121: "B", 5123: "H", 5125: "I"}[index_ctype]
    ib = pad4(struct.pack("<%d%s" % (len(idx), fmt), *idx))
    data = inter + ib
    g = {
        "asset": {"version": "2.0", "generator": "tests/assets/data/make_fixtures.py"},
        "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": [{"name": "cube", "mesh": 0}],
        "meshes": [{"name": "cube", "primitives": [
            {"attributes": {"POSITION": 0, "NORMAL": 1}, "indices": 2, "material": 0}]}],
        "materials": [{"name": "red", "pbrMetallicRoughness": {
            "baseColorFactor": [1.0, 0.0, 0.0, 1.0], "roughnessFactor": 0.5, "metallicFactor": 0.0}}],
        "accessors": [
            {"bufferView": 0, "byteOffset": 0, "componentType": 5126, "count": 24, "type": "VEC3",
             "min": [-0.5, -0.5, -0.5], "max": [0.5, 0.5, 0.5]},
            {"bufferView": 0, "byteOffset": 12, "componentType": 5126, "count": 24, "type": "VEC3"},
            {"bufferView": 1, "componentType": index_ctype, "count": 36, "type": "SCALAR"},
        ],
        "bufferViews": [
            {"buffer": 0, "byteOffset": 0, "byteLength": len(inter), "byteStride": 24, "target": 34962},
            {"buffer": 0, "byteOffset": len(inter), "byteLength": len(ib), "target": 34963},
        ],
        "buffers": [{"byteLength": len(data)}],
    }
    return g, data


def embed(g, data):
    g["buffers"][0]["uri"] = "data:application/octet-stream;base64," + base64.b64encode(data).decode()
    return g


def write(name, g):
    with open(os.path.join(HERE, name), "w", newline="\n") as f:
        f.write(json.dumps(g, indent=1) + "\n")


def write_glb(name, g, data):
    js = pad4(json.dumps(g, separators=(",", ":")).encode(), b" ")
    bin_ = pad4(data)
    body = struct.pack("<I4s", len(js), b"JSON") + js + struct.pack("<I4s", len(bin_), b"BIN\0") + bin_
    with open(os.path.join(HERE, name), "wb") as f:
        f.write(struct.pack("<4sII", b"glTF", 2, 12 + len(body)) + body)


def main():
    g, data = cube_model(5123)
    write("cube.gltf", embed(g, data))

    g, data = cube_model(5125)  # .glb, uint32 indices
    write_glb("cube.glb", g, data)

    g, data = cube_model(5121)  # external .bin, ubyte indices
    g["buffers"][0]["uri"] = "cube_external.bin"
    write("cube_external.gltf", g)
    with open(os.path.join(HERE, "cube_external.bin"), "wb") as f:
        f.write(data)

    text = open(os.path.join(HERE, "cube.gltf")).read()
    with open(os.path.join(HERE, "broken_json.gltf"), "w") as f:
        f.write(text[: len(text) // 2])  # truncated mid-file

    g, data = cube_model(5123)
    g["accessors"][0]["count"] = 1000  # reads far beyond bufferView 0
    write("accessor_out_of_range.gltf", embed(g, data))

    g, data = cube_model(5123)
    pos, nrm, idx = cube()
    idx[7] = 99  # only 24 vertices
    ib = pad4(struct.pack("<%dH" % len(idx), *idx))
    data = data[: g["bufferViews"][1]["byteOffset"]] + ib
    write("bad_indices.gltf", embed(g, data))

    g, data = cube_model(5123)
    del g["meshes"][0]["primitives"][0]["attributes"]["POSITION"]
    write("no_position.gltf", embed(g, data))

    # Two-node hierarchy with extras; no meshes.
    write("hierarchy.gltf", {
        "asset": {"version": "2.0"},
        "scene": 0,
        "scenes": [{"nodes": [0], "extras": {"level": "test", "version": 2}}],
        "nodes": [
            {"name": "root", "translation": [1.0, 0.0, 0.0], "children": [1],
             "extras": {"tag": "root", "count": 3, "list": [1, 2.5, "x"], "obj": {"flag": True, "none": None}}},
            {"name": "child", "translation": [0.0, 2.0, 0.0], "rotation": [0.0, 0.0, 0.7071068, 0.7071068],
             "scale": [2.0, 2.0, 2.0], "extras": {"physics": {"mass": 1.5}}},
        ],
    })

    # Animation: LINEAR rotation (3 keys) and STEP translation (2 keys) on node "bone".
    times = [0.0, 0.5, 1.0]
    s = 0.7071068
    rots = [0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.3826834, 0.9238795, 0.0, 0.0, s, s]
    ttimes = [0.0, 1.0]
    trans = [0.0, 0.0, 0.0, 0.0, 0.0, 1.0]
    chunks = [struct.pack("<3f", *times), struct.pack("<12f", *rots), struct.pack("<2f", *ttimes),
              struct.pack("<6f", *trans)]
    views, data = [], b""
    for c in chunks:
        views.append({"buffer": 0, "byteOffset": len(data), "byteLength": len(c)})
        data += c
    write("anim.gltf", embed({
        "asset": {"version": "2.0"},
        "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": [{"name": "bone"}],
        "animations": [{"name": "wave", "extras": {"loop": True},
                        "channels": [{"sampler": 0, "target": {"node": 0, "path": "rotation"}},
                                     {"sampler": 1, "target": {"node": 0, "path": "translation"}}],
                        "samplers": [{"input": 0, "output": 1, "interpolation": "LINEAR"},
                                     {"input": 2, "output": 3, "interpolation": "STEP"}]}],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": 3, "type": "SCALAR", "min": [0.0], "max": [1.0]},
            {"bufferView": 1, "componentType": 5126, "count": 3, "type": "VEC4"},
            {"bufferView": 2, "componentType": 5126, "count": 2, "type": "SCALAR", "min": [0.0], "max": [1.0]},
            {"bufferView": 3, "componentType": 5126, "count": 2, "type": "VEC3"},
        ],
        "bufferViews": views,
        "buffers": [{"byteLength": len(data)}],
    }, data))

    # Two-bone character whose second bone has no mass.
    shape = {"type": "capsule", "radius": 0.05, "half_length": 0.1, "pos": [0.0, 0.0, -0.15]}
    write("character_missing_mass.gltf", {
        "asset": {"version": "2.0"},
        "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": [
            {"name": "pelvis", "translation": [0.0, 0.0, 1.0], "children": [1],
             "extras": {"physics": {"joint": "free", "mass": 5.0, "com": [0.0, 0.0, 0.0],
                                    "inertia": [0.1, 0.1, 0.1], "shapes": [shape]}}},
            {"name": "thigh_l", "translation": [0.0, 0.1, 0.0],
             "extras": {"physics": {"joint": "ball", "swing_limit": 1.0, "twist_limit": 0.5,
                                    "com": [0.0, 0.0, -0.15], "inertia": [0.1, 0.1, 0.02], "shapes": [shape]}}},
        ],
    })


if __name__ == "__main__":
    main()
