"""Manual check with Blender (not part of CI): import content/boxer/boxer.glb, check the boxer stands
upright and every clip is there and plays, and render the jab at impact into docs/boxer_jab_blender.png.

  xvfb-run -a blender -b --factory-startup -P scripts/content/blender_check.py [-- OUT.png]

(Debian's blender 3.4; xvfb-run gives the Workbench renderer an OpenGL context on a machine without a
display.) Prints one "check:" line per property and exits 1 when one fails.

Blender is Z up: its glTF importer turns glTF's +Y up into Blender's +Z and glTF's +Z (the boxer's
facing) into Blender's -Y, so "upright" here means the head near Blender z = 1.6 m.
"""
import math
import os
import sys

import warnings

import numpy

with warnings.catch_warnings():
    warnings.simplefilter("ignore")
    if not hasattr(numpy, "bool"):  # Debian's numpy 1.24 dropped numpy.bool; Blender 3.4's glTF importer uses it
        numpy.bool = bool

import bpy  # noqa: E402
from mathutils import Vector  # noqa: E402

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
GLB = os.path.join(ROOT, "content", "boxer", "boxer.glb")
argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
OUT = os.path.abspath(argv[0]) if argv else os.path.join(ROOT, "docs", "boxer_jab_blender.png")

failures = []


def check(ok, what):
    print(("check: ok   " if ok else "check: FAIL ") + what)
    if not ok:
        failures.append(what)


bpy.ops.wm.read_factory_settings(use_empty=True)
bpy.ops.import_scene.gltf(filepath=GLB)
scene = bpy.context.scene
fps = scene.render.fps / scene.render.fps_base
objs = {o.name: o for o in scene.objects}
check(all(n in objs for n in ("pelvis", "head", "glove_l", "foot_r")), "bone nodes imported as objects")


def world(name):
    bpy.context.view_layer.update()
    return objs[name].matrix_world.translation.copy()


# The importer makes one action per (animation, node), named "<animation>_<node>".
clips = sorted({a.name.rsplit("_" + n, 1)[0] for a in bpy.data.actions for n in objs if a.name.endswith("_" + n)})
print("clips:", " ".join(clips))
check(len(clips) == 23, "%d clips imported as actions (23)" % len(clips))


# Where the importer puts time 0: the first key of the jab's pelvis action.
jab_root = bpy.data.actions.get("jab_pelvis")
check(jab_root is not None, "jab action on the pelvis")
first = min(k.co.x for fc in jab_root.fcurves for k in fc.keyframe_points)
last = max(k.co.x for fc in jab_root.fcurves for k in fc.keyframe_points)
print("jab keys: frames %.2f..%.2f at %.1f fps" % (first, last, fps))


def play_at(clip, t):
    for name, o in objs.items():
        act = bpy.data.actions.get(clip + "_" + name)
        if act is not None:
            if o.animation_data is None:
                o.animation_data_create()
            o.animation_data.action = act
    frame = first + t * fps
    scene.frame_set(int(math.floor(frame)), subframe=frame - math.floor(frame))
    bpy.context.view_layer.update()


# Upright: in the guard (knees bent) the head joint (1.50 m at rest) is well above the pelvis, right
# over it, the feet on the floor, the left shoulder on +X (glTF's +X is the boxer's left).
for o in scene.objects:  # only the action we put on a node plays, not the importer's NLA tracks
    if o.animation_data:
        for tr in list(o.animation_data.nla_tracks):
            o.animation_data.nla_tracks.remove(tr)
play_at("guard", 0.0)
head, pelvis, foot = world("head"), world("pelvis"), world("foot_l")
check(1.35 < head.z < 1.55 and abs(head.x - pelvis.x) < 0.2 and abs(head.y - pelvis.y) < 0.2,
      "upright in the guard: head joint at Blender z = %.3f, over the pelvis (z = %.3f)" % (head.z, pelvis.z))
check(foot.z < 0.15, "feet on the floor: left ankle at z = %.3f" % foot.z)
check(world("upper_arm_l").x > 0.1, "left shoulder on +X")

# Every clip plays: some bone moves between its start and its middle.
for clip in clips:
    acts = [a for a in bpy.data.actions if a.name.startswith(clip + "_")]
    end = max(k.co.x for a in acts for fc in a.fcurves for k in fc.keyframe_points)
    play_at(clip, 0.0)
    p0 = {n: objs[n].matrix_world.translation.copy() for n in ("head", "glove_l", "glove_r", "foot_l")}
    play_at(clip, 0.5 * (end - first) / fps)
    moved = max((objs[n].matrix_world.translation - p0[n]).length for n in p0)
    check(moved > 0.01, "clip %s plays (a bone moves %.3f m by its middle)" % (clip, moved))

# The jab at impact (0.14 s, the clip's extras): the left glove well in front (-Y) of the chest.
play_at("guard", 0.0)
g0 = world("glove_l")
play_at("jab", 0.14)
g = world("glove_l")
chest = world("chest")
head = world("head")
check(chest.y - g.y > 0.35 and g0.y > g.y + 0.08,
      "jab at impact: left glove %.2f m in front of the chest (guard: %.2f)" % (chest.y - g.y, chest.y - g0.y))
check(head.z > 1.35, "upright during the jab: head joint at z = %.2f" % head.z)

# Render: Workbench, small, camera at the boxer's front-left looking at the chest.
scene.render.engine = "BLENDER_WORKBENCH"
scene.display.shading.light = "STUDIO"
scene.display.shading.color_type = "MATERIAL"
scene.render.resolution_x, scene.render.resolution_y = 480, 480
scene.render.resolution_percentage = 100
scene.render.film_transparent = False
world_bg = bpy.data.worlds.new("bg")
world_bg.color = (0.6, 0.65, 0.7)
scene.world = world_bg
bpy.ops.mesh.primitive_plane_add(size=30.0, location=(0.0, 0.0, 0.0))  # the floor, at z = 0
cam_data = bpy.data.cameras.new("cam")
cam_data.lens = 50
cam = bpy.data.objects.new("cam", cam_data)
scene.collection.objects.link(cam)
cam.location = Vector((2.9, -2.3, 1.35))  # the boxer's front-left (he faces -Y, his left is +X)
target = Vector((0.0, -0.25, 0.95))
cam.rotation_euler = (target - cam.location).to_track_quat("-Z", "Y").to_euler()
scene.camera = cam
scene.render.filepath = OUT
os.makedirs(os.path.dirname(OUT), exist_ok=True)
bpy.ops.render.render(write_still=True)
check(os.path.exists(OUT), "rendered " + OUT)

print("blender_check: %d failure(s)" % len(failures))
sys.stdout.flush()
os._exit(1 if failures else 0)
