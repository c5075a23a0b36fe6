"""Builds PRT's animated glTF example, scenes/models/animated.glb, in Blender from code and writes
it with Blender's own glTF exporter, keyframes unsampled, so that the file holds the three
interpolations glTF 2.0 defines as Blender writes them:

  Stepper  a cube whose location has CONSTANT keys          -> STEP
  Slider   a ball whose location and rotation have LINEAR keys -> LINEAR
  Spinner  a ring whose quaternion rotation and scale have Bezier keys -> CUBICSPLINE
  Moon     a small ball parented to the Spinner, never keyed: it moves with its parent
  Base     a board, never keyed
  Camera   a camera whose location has LINEAR keys (it dollies in), tracking nothing
  Lamp     a point light whose location has Bezier keys      -> CUBICSPLINE

Two seconds at 24 frames a second: frames 0 to 48, keyed at 0, 24 and 48 (Blender writes frame f
at f / 24 s, so the keys are at 0, 1 and 2 s). The key values are set here and checked by
src/scene/gltf_animation_test.cpp; change them together. Each object's action becomes one glTF
animation (the exporter's NLA mode), so the file also has several animations that play at once.
Nothing is downloaded; the output is deterministic.

Command (Blender 3.4.1 from Debian 12, whose glTF add-on also needs python3-numpy):

    blender -b --factory-startup --python scripts/make-animated-models.py -- /work/main

At the end it reads the file back and prints each animation's channels and interpolations.
"""
import json
import math
import os
import struct
import sys

import bmesh
import bpy

FPS = 24


def reset():
    bpy.ops.wm.read_factory_settings(use_empty=True)
    sc = bpy.context.scene
    sc.render.resolution_x, sc.render.resolution_y = 640, 480
    sc.render.fps = FPS
    sc.frame_start, sc.frame_end = 0, 48
    sc.frame_set(0)
    return sc


def material(name, base, metallic=0.0, roughness=0.5):
    m = bpy.data.materials.new(name)
    m.use_nodes = True
    bsdf = m.node_tree.nodes["Principled BSDF"]
    bsdf.inputs["Base Color"].default_value = (*base, 1.0)
    bsdf.inputs["Metallic"].default_value = metallic
    bsdf.inputs["Roughness"].default_value = roughness
    return m


def mesh(name, build):
    bm = bmesh.new()
    build(bm)
    me = bpy.data.meshes.new(name)
    bm.to_mesh(me)
    bm.free()
    return me


def obj(name, data, loc=(0, 0, 0), mat=None, parent=None):
    o = bpy.data.objects.new(name, data)
    o.location = loc
    if mat is not None:
        data.materials.append(mat)
    bpy.context.scene.collection.objects.link(o)
    if parent is not None:
        o.parent = parent
    return o


def key(o, path, frame, value, interpolation):
    """Sets o.<path> to value and keys it at frame with the given interpolation."""
    setattr(o, path, value)
    o.keyframe_insert(data_path=path, frame=frame)
    for fc in o.animation_data.action.fcurves:
        if fc.data_path == path:
            for kp in fc.keyframe_points:
                if kp.co[0] == frame:
                    kp.interpolation = interpolation


def make_animated(path):
    reset()
    red = material("Red", (0.8, 0.1, 0.06), roughness=0.4)
    blue = material("Blue", (0.1, 0.25, 0.8), metallic=0.5, roughness=0.3)
    gold = material("Gold", (0.9, 0.7, 0.2), metallic=0.8, roughness=0.25)
    grey = material("Grey", (0.6, 0.6, 0.6), roughness=0.8)

    obj("Base", mesh("Base", lambda bm: bmesh.ops.create_cube(bm, size=1.0)), (0, 0, -0.05), grey).scale = (4, 3, 0.1)

    stepper = obj("Stepper", mesh("Stepper", lambda bm: bmesh.ops.create_cube(bm, size=0.5)),
                  (-1.5, 0, 0.25), red)
    key(stepper, "location", 0, (-1.5, 0.0, 0.25), 'CONSTANT')
    key(stepper, "location", 24, (-1.5, 1.0, 0.25), 'CONSTANT')
    key(stepper, "location", 48, (-1.5, 0.0, 0.75), 'CONSTANT')

    slider = obj("Slider", mesh("Slider", lambda bm: bmesh.ops.create_icosphere(
        bm, subdivisions=2, radius=0.3)), (0, -1, 0.3), blue)
    key(slider, "location", 0, (0.0, -1.0, 0.3), 'LINEAR')
    key(slider, "location", 48, (0.0, 1.0, 0.3), 'LINEAR')
    key(slider, "rotation_euler", 0, (0.0, 0.0, 0.0), 'LINEAR')
    key(slider, "rotation_euler", 48, (0.0, 0.0, math.radians(90)), 'LINEAR')

    spinner = obj("Spinner", mesh("Spinner", lambda bm: bmesh.ops.create_cone(
        bm, cap_ends=True, segments=12, radius1=0.4, radius2=0.4, depth=0.15)), (1.5, 0, 0.5), gold)
    spinner.rotation_mode = 'QUATERNION'
    key(spinner, "rotation_quaternion", 0, (1.0, 0.0, 0.0, 0.0), 'BEZIER')
    half = math.radians(90) / 2
    key(spinner, "rotation_quaternion", 48, (math.cos(half), 0.0, 0.0, math.sin(half)), 'BEZIER')
    key(spinner, "scale", 0, (1.0, 1.0, 1.0), 'BEZIER')
    key(spinner, "scale", 24, (1.5, 1.5, 1.5), 'BEZIER')
    key(spinner, "scale", 48, (1.0, 1.0, 1.0), 'BEZIER')

    obj("Moon", mesh("Moon", lambda bm: bmesh.ops.create_icosphere(bm, subdivisions=1, radius=0.12)),
        (0.7, 0, 0), red, parent=spinner)

    cam = bpy.data.cameras.new("Camera")
    cam.lens = 35.0
    camera = obj("Camera", cam, (0, -6, 3))
    camera.rotation_euler = (math.radians(65), 0, 0)
    key(camera, "location", 0, (0.0, -6.0, 3.0), 'LINEAR')
    key(camera, "location", 48, (0.0, -4.5, 2.5), 'LINEAR')
    bpy.context.scene.camera = camera

    lamp_data = bpy.data.lights.new("Lamp", 'POINT')
    lamp_data.energy = 500.0
    lamp = obj("Lamp", lamp_data, (-2, -2, 3))
    key(lamp, "location", 0, (-2.0, -2.0, 3.0), 'BEZIER')
    key(lamp, "location", 48, (2.0, -2.0, 3.0), 'BEZIER')

    bpy.context.scene.frame_set(0)
    os.makedirs(os.path.dirname(path), exist_ok=True)
    bpy.ops.export_scene.gltf(
        filepath=path, export_format='GLB', export_cameras=True, export_lights=True,
        convert_lighting_mode='SPEC', export_yup=True, export_apply=False,
        export_animations=True, export_force_sampling=False, export_nla_strips=True,
        export_frame_range=False, export_extras=False, use_selection=False)


def read_glb_json(path):
    with open(path, "rb") as f:
        data = f.read()
    length = struct.unpack_from("<I", data, 12)[0]
    return json.loads(data[20:20 + length])


def summarise(path):
    doc = read_glb_json(path)
    nodes = doc["nodes"]
    print("VERIFY %s %d B nodes=%d animations=%d" % (path, os.path.getsize(path), len(nodes),
                                                   len(doc.get("animations", []))))
    for a in doc.get("animations", []):
        for c in a["channels"]:
            s = a["samplers"][c["sampler"]]
            times = doc["accessors"][s["input"]]
            print("VERIFY   %-16s %-8s %-12s %-11s keys=%d t=[%g, %g]" % (
                a.get("name", "?"), nodes[c["target"]["node"]].get("name", "?"), c["target"]["path"],
                s.get("interpolation", "LINEAR"), times["count"], times["min"][0], times["max"][0]))


def main():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    if len(argv) != 1:
        raise SystemExit("usage: blender -b --factory-startup --python scripts/make-animated-models.py -- OUTROOT")
    path = os.path.join(os.path.abspath(argv[0]), "scenes", "models", "animated.glb")
    make_animated(path)
    summarise(path)


main()
