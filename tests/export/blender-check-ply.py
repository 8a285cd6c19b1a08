# blender -b --factory-startup --python-exit-code 1 --python blender-check-ply.py -- PLY VERTICES
# FACES: imports one of lacrima-player --export-tears's files with Blender's own PLY importer and
# checks that it holds VERTICES vertices, FACES triangles and a colour attribute.
import sys

import bpy

ply, vertices, faces = sys.argv[sys.argv.index("--") + 1:]
bpy.ops.wm.read_factory_settings(use_empty=True)
bpy.ops.import_mesh.ply(filepath=ply)
meshes = [o for o in bpy.context.scene.objects if o.type == "MESH"]
if len(meshes) != 1:
    raise SystemExit("expected one mesh, got %d" % len(meshes))
mesh = meshes[0].data
got = (len(mesh.vertices), len(mesh.polygons))
if got != (int(vertices), int(faces)):
    raise SystemExit("Blender read %d vertices and %d faces, expected %s and %s" % (*got, vertices, faces))
if not any(a.data_type in ("BYTE_COLOR", "FLOAT_COLOR") for a in mesh.attributes):
    raise SystemExit("no vertex colours: %s" % [a.name for a in mesh.attributes])
if any(len(p.vertices) != 3 for p in mesh.polygons):
    raise SystemExit("not all faces are triangles")
print("PLY OK", *got)
