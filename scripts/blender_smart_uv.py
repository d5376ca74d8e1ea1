# Runs inside Blender (blender -b --python scripts/blender_smart_uv.py -- IN.obj OUT.obj):
# imports a mesh, unwraps it with Smart UV Project at Blender's defaults
# (66 degrees, a tiny island margin, packed into one texture), writes an OBJ
# with texture coordinates and prints the time the unwrap took.
import math
import sys
import time

import bpy

args = sys.argv[sys.argv.index("--") + 1:]
if len(args) != 2:
    sys.exit("usage: blender -b --python blender_smart_uv.py -- IN.obj OUT.obj")
source, target = args
bpy.ops.wm.read_factory_settings(use_empty=True)
bpy.ops.wm.obj_import(filepath=source)
mesh = bpy.context.selected_objects[0]
bpy.context.view_layer.objects.active = mesh
bpy.ops.object.mode_set(mode="EDIT")
bpy.ops.mesh.select_all(action="SELECT")
start = time.perf_counter()
bpy.ops.uv.smart_project(angle_limit=math.radians(66), island_margin=0.002)
print("smart_project_seconds %.6f" % (time.perf_counter() - start))
bpy.ops.object.mode_set(mode="OBJECT")
# Same axes as the file read, so the OBJ's vertices are the input's.
bpy.ops.wm.obj_export(filepath=target, export_selected_objects=True, export_uv=True, export_normals=False,
                      export_materials=False, forward_axis="NEGATIVE_Z", up_axis="Y")
