# blender -b --factory-startup --python-exit-code 1 --python blender-check-glb.py -- GLB EXPECTED
# RESULT: imports GLB with Blender's own glTF importer and checks it against EXPECTED (JSON
# written by GltfExportTest.cpp from Lacrima's playback of the same file): the shape keys by FAP
# name, the shape-key action's length, the shape-key values, the eyes' turns and the deformed
# head at chosen frames, and which tear objects show at every frame. Writes what it measured to
# RESULT (JSON); any failed check raises, so Blender exits with status 1.
import json
import sys

# Blender 3.4's importer still uses numpy.bool, which numpy 1.24 removed.
import numpy

numpy.bool = bool

import bpy
import mathutils

glb, expected_path, result_path = sys.argv[sys.argv.index("--") + 1:]
with open(expected_path) as f:
    expected = json.load(f)

bpy.ops.wm.read_factory_settings(use_empty=True)
scene = bpy.context.scene
# The importer puts a key at time t on frame t * fps: at the file's rate, frame k is frame k.
scene.render.fps = expected["fps"]
bpy.ops.import_scene.gltf(filepath=glb)

failures = []
result = {}


def check(condition, message):
    if not condition:
        failures.append(message)


heads = [o for o in scene.objects if o.type == "MESH" and o.data.shape_keys]
check(len(heads) == 1, "expected one mesh with shape keys, found %d" % len(heads))
head = heads[0]
keys = head.data.shape_keys
names = [k.name for k in keys.key_blocks]
for name in expected["weights"][0]["values"]:
    check(name in names, "no shape key named %s (have %s)" % (name, names[:8]))
action = keys.animation_data.action if keys.animation_data else None
check(action is not None, "the shape keys have no action")
if action:
    result["shapeKeyActionRange"] = list(action.frame_range)
    check(tuple(action.frame_range) == (0.0, expected["lastFrame"]),
          "shape-key action covers %s, expected 0 to %d" % (tuple(action.frame_range),
                                                            expected["lastFrame"]))

armature = next((o for o in scene.objects if o.type == "ARMATURE"), None)
check(armature is not None, "no armature")


def blender_axes(v):  # glTF's Y-up to Blender's Z-up, as the importer converts
    return mathutils.Vector((v[0], -v[2], v[1]))


def world_turn(bone_name):
    """The rotation that takes the bone from its rest to its pose, in world axes."""
    pose_bone = armature.pose.bones[bone_name]
    rest = armature.matrix_world @ pose_bone.bone.matrix_local
    posed = armature.matrix_world @ pose_bone.matrix
    return (posed @ rest.inverted()).to_quaternion()


result["frames"] = []
depsgraph = bpy.context.evaluated_depsgraph_get()
for sample in expected["weights"]:
    frame = sample["frame"]
    scene.frame_set(frame)
    measured = {"frame": frame, "weights": {}, "eyes": {}}
    for name, value in sample["values"].items():
        got = keys.key_blocks[name].value
        measured["weights"][name] = got
        check(abs(got - value) <= expected["weightTolerance"],
              "frame %d: %s is %.6f, expected %.6f" % (frame, name, got, value))
    for bone, q in sample["eyes"].items():
        want = mathutils.Quaternion((q[3], q[0], -q[2], q[1]))  # (w, x, y, z), Blender axes
        got = world_turn(bone)
        angle = got.rotation_difference(want).angle
        measured["eyes"][bone] = {"angleError": angle, "angle": got.angle}
        check(angle <= expected["angleTolerance"],
              "frame %d: %s turned %.5f rad away from the FAP file's turn" % (frame, bone, angle))
    # The deformed head against Lacrima's own: every vertex Blender shows near one of Lacrima's.
    positions = sample.get("positions")
    if positions:
        tree = mathutils.kdtree.KDTree(len(positions))
        for i, p in enumerate(positions):
            tree.insert(blender_axes(p), i)
        tree.balance()
        evaluated = head.evaluated_get(depsgraph)
        mesh = evaluated.to_mesh()
        world = head.matrix_world
        worst = 0.0
        for v in mesh.vertices:
            worst = max(worst, tree.find(world @ v.co)[2])
        evaluated.to_mesh_clear()
        measured["worstVertexMetres"] = worst
        check(worst <= expected["positionTolerance"],
              "frame %d: a vertex is %.6f m from Lacrima's head" % (frame, worst))
    result["frames"].append(measured)

# Tears: at every frame exactly the objects of that frame's tears show (scale 1), no others.
tear_objects = {o.name: o for o in scene.objects if o.name.startswith("tears_")}
result["tearObjects"] = len(tear_objects)
with_tears = set(expected["tearFrames"])
check(len(tear_objects) == len(with_tears),
      "%d tear objects for %d frames with tears" % (len(tear_objects), len(with_tears)))
for frame in range(expected["lastFrame"] + 1):
    scene.frame_set(frame)
    shown = sorted(name for name, o in tear_objects.items()
                   if o.matrix_world.to_scale().length > 0.5)
    want = ["tears_%04d" % frame] if frame in with_tears else []
    check(shown == want, "frame %d shows %s, expected %s" % (frame, shown, want))

result["failures"] = failures
with open(result_path, "w") as f:
    json.dump(result, f, indent=1)
if failures:
    raise SystemExit("\n".join(failures[:20]))
