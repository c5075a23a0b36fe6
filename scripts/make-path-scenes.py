"""Builds the scenes made for path tracing and for the comparison with Cycles
(bench/cycles/), from code, with Blender's glTF exporter:

  scenes/models/cornell-box.glb        the Cornell box lit by an area light: an emissive
                                       quad (glTF's only area light) in a hole of the ceiling
  scenes/models/cornell-box-point.glb  the same box lit by a point light under the ceiling
                                       (the quad a plain white panel): what a renderer
                                       without area lights can render
  scenes/models/street.glb             a street of the props of scenes/models/street/ (read
                                       with Blender's glTF importer and placed as linked
                                       duplicates, so each mesh is written once) with a road,
                                       a sidewalk, a lawn, a metal ball and a glass ball on a
                                       pedestal, under a sun, seen through a camera

Command (Blender 3.4.1 from Debian 12, whose glTF add-on also needs python3-numpy):

    blender -b --factory-startup --python scripts/make-path-scenes.py -- /work/main

Deterministic: every position, colour and strength is written here, the props are the
committed files (scripts/make-models.py makes them), and the helpers are make-models.py's.
Units are Blender's: lights in watts (W/m^2 for the sun), exported in glTF's photometric units
(candela, lux) by the exporter's "Standard" lighting mode; emission as Blender's radiance
(colour x strength), exported as emissiveFactor x KHR_materials_emissive_strength.
"""
import importlib.util
import math
import os
import sys

import numpy as np

if "bool" not in vars(np):  # Debian 12's NumPy removed np.bool; the glTF add-on calls it
    np.bool = bool

import bpy  # noqa: E402

_spec = importlib.util.spec_from_file_location(
    "make_models", os.path.join(os.path.dirname(os.path.abspath(__file__)), "make-models.py"))
mm = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(mm)


def reset(width, height):
    sc = mm.reset()
    sc.render.resolution_x, sc.render.resolution_y = width, height  # the camera's aspect ratio
    return sc


def perspective_camera(name, loc, target, yfov_degrees):
    o = mm.camera(name, loc, target)
    o.data.sensor_fit = 'VERTICAL'
    o.data.sensor_height = 24.0
    o.data.angle_y = math.radians(yfov_degrees)
    return o


# ----------------------------------------------------------------------------- Cornell box

# The room: x in [-1, 1] (red wall at -1, green at +1), y in [-1, 1] (open at -1, the back
# wall at +1), z in [0, 2]; the light's opening in the ceiling is 0.5 x 0.4 m at its centre.
# Reflectances are the classic box's (Goral et al. 1984 / the Cornell box data), roughness 1.
WHITE = (0.73, 0.71, 0.68)
RED = (0.63, 0.065, 0.05)
GREEN = (0.14, 0.45, 0.091)
LIGHT_HALF = (0.25, 0.2)
LIGHT_COLOUR = (1.0, 0.85, 0.65)
LIGHT_STRENGTH = 30.0  # radiance of the emissive quad, W / (m^2 sr) in Blender's units
POINT_WATTS = 40.0


def quad(b, corners, mat):
    b.face([b.vert(c) for c in corners], [(0, 0), (1, 0), (1, 1), (0, 1)], mat)


def rotated_box(b, centre, half, height, degrees, mat):
    """A box standing on the floor, turned about z; five faces (none on the floor)."""
    cx, cy = centre
    c, s = math.cos(math.radians(degrees)), math.sin(math.radians(degrees))
    ring = [(cx + c * x - s * y, cy + s * x + c * y)
            for x, y in ((-half, -half), (half, -half), (half, half), (-half, half))]
    for k in range(4):  # sides, counter-clockwise seen from outside
        (x0, y0), (x1, y1) = ring[k], ring[(k + 1) % 4]
        quad(b, [(x0, y0, 0), (x1, y1, 0), (x1, y1, height), (x0, y0, height)], mat)
    quad(b, [(x, y, height) for x, y in ring], mat)


def make_cornell(out, point_light):
    reset(512, 512)
    white = mm.material("White", base=WHITE, roughness=1.0)
    red = mm.material("Red", base=RED, roughness=1.0)
    green = mm.material("Green", base=GREEN, roughness=1.0)
    if point_light:
        panel = mm.material("LightPanel", base=(0.78, 0.78, 0.78), roughness=1.0)
    else:
        panel = mm.material("Light", base=(0.78, 0.78, 0.78), roughness=1.0,
                            emission=LIGHT_COLOUR, strength=LIGHT_STRENGTH)

    b = mm.Builder()  # faces towards the inside of the room
    quad(b, [(-1, -1, 0), (1, -1, 0), (1, 1, 0), (-1, 1, 0)], 0)        # floor
    quad(b, [(-1, 1, 0), (1, 1, 0), (1, 1, 2), (-1, 1, 2)], 0)          # back
    quad(b, [(-1, -1, 0), (-1, 1, 0), (-1, 1, 2), (-1, -1, 2)], 1)      # left, red
    quad(b, [(1, 1, 0), (1, -1, 0), (1, -1, 2), (1, 1, 2)], 2)          # right, green
    lx, ly = LIGHT_HALF
    xs, ys = (-1, -lx, lx, 1), (-1, -ly, ly, 1)
    for i in range(3):  # the ceiling around the light's opening, facing down
        for j in range(3):
            if i == 1 and j == 1:
                continue
            x0, x1, y0, y1 = xs[i], xs[i + 1], ys[j], ys[j + 1]
            quad(b, [(x0, y0, 2), (x0, y1, 2), (x1, y1, 2), (x1, y0, 2)], 0)
    room = mm.obj("Room", b.mesh("Room"), mats=[white, red, green])

    b = mm.Builder()
    rotated_box(b, (0.33, -0.32), 0.3, 0.6, -17, 0)   # the short box, right front
    rotated_box(b, (-0.34, 0.3), 0.3, 1.2, 17, 0)     # the tall box, left back
    boxes = mm.obj("Boxes", b.mesh("Boxes"), mats=[white])

    b = mm.Builder()  # the light: the opening's quad, facing down
    quad(b, [(-lx, -ly, 2), (-lx, ly, 2), (lx, ly, 2), (lx, -ly, 2)], 0)
    light = mm.obj("Light" if not point_light else "LightPanel", b.mesh("LightQuad"), mats=[panel])

    perspective_camera("Camera", (0, -3.9, 1.0), (0, 0, 1.0), 39.0)
    if point_light:
        mm.light("PointLight", 'POINT', POINT_WATTS, (0, 0, 1.7), colour=LIGHT_COLOUR)
    name = "cornell-box-point.glb" if point_light else "cornell-box.glb"
    mm.export_gltf(os.path.join(out, name))
    return {name: sum(mm.triangles(o.data) for o in (room, boxes, light))}


# ----------------------------------------------------------------------------- street

def prt_to_blender(x, y, z):
    """scenes/street.scene's coordinates (y up, looking along +z) to Blender's (z up)."""
    return (x, -z, y)


def import_prop(path):
    before = set(bpy.data.objects)
    bpy.ops.import_scene.gltf(filepath=path)
    new = [o for o in bpy.data.objects if o not in before]
    roots = [o for o in new if o.parent is None]
    for o in new:  # kept out of the scene; placed below as linked duplicates
        for c in list(o.users_collection):
            c.objects.unlink(o)
    return roots


def place(roots, translate, degrees=0.0, scale=1.0):
    """Linked duplicates of a prop's object trees, as street.scene places them."""
    holder = bpy.data.objects.new("Prop", None)
    bpy.context.scene.collection.objects.link(holder)
    holder.location = prt_to_blender(*translate)
    holder.rotation_euler = (0, 0, math.radians(degrees))
    holder.scale = (scale, scale, scale)

    def copy(o, parent):
        d = o.copy()  # shares the mesh data
        bpy.context.scene.collection.objects.link(d)
        d.parent = parent
        for child in o.children:
            copy(child, d)

    for r in roots:
        copy(r, holder)
    return holder


def make_street(out, props):
    reset(640, 480)
    road = mm.material("Road", base=(0.22, 0.22, 0.24), roughness=0.9)
    stone = mm.material("Sidewalk", base=(0.62, 0.60, 0.56), roughness=0.85)
    grass = mm.material("Lawn", base=(0.32, 0.42, 0.22), roughness=0.95)
    # Polished, not a perfect mirror: the sun's glint in a ball of roughness 0.05 is a spot
    # smaller than a pixel holding a tenth of the image's mean luminance, which no renderer
    # estimates to a few per cent at hundreds of samples; at 0.3 it spans pixels.
    metal = mm.material("MetalBall", base=(0.9, 0.9, 0.92), metallic=1.0, roughness=0.3)
    glass = mm.material("GlassBall", base=(0.95, 0.97, 1.0), roughness=0.0, transmission=1.0,
                        ior=1.5)
    pedestal_stone = mm.material("Pedestal", base=(0.70, 0.68, 0.64), roughness=0.8)

    b = mm.Builder()
    quad(b, [prt_to_blender(-60, 0, 3), prt_to_blender(60, 0, 3), prt_to_blender(60, 0, -40),
             prt_to_blender(-60, 0, -40)], 0)   # the road up to the kerb, facing up
    mm.obj("Road", b.mesh("Road"), mats=[road])

    def box_prt(name, lo, hi, mat):
        (x0, y0, z0), (x1, y1, z1) = lo, hi
        bb = mm.Builder()
        bb.box((x0, -z1, y0), (x1, -z0, y1), mat=0)
        return mm.obj(name, bb.mesh(name), mats=[mat])

    box_prt("Sidewalk", (-16, 0, 3), (16, 0.15, 6.5), stone)
    box_prt("Lawn", (-40, 0, 6.5), (40, 0.05, 60), grass)
    box_prt("Pedestal", (0.9, 0.15, 4.6), (1.7, 1.05, 5.4), pedestal_stone)
    bs = mm.Builder()
    bs.sphere(0.9, (0, 0, 0), 32, 16)
    mm.obj("MetalBall", bs.mesh("MetalBall", smooth=True), loc=prt_to_blender(-1.2, 0.9, 0.8),
           mats=[metal])
    bs = mm.Builder()
    bs.sphere(0.45, (0, 0, 0), 32, 16)
    mm.obj("GlassBall", bs.mesh("GlassBall", smooth=True), loc=prt_to_blender(1.3, 1.5, 5.0),
           mats=[glass])

    prop = {name: import_prop(os.path.join(props, name + ".glb"))
            for name in ("house", "lamp", "bench", "tree")}
    for t, r, s in (((-6.5, 0.05, 9.2), -6, 1.0), ((0, 0.05, 9.6), 0, 1.1),
                    ((6.8, 0.05, 9.2), 7, 1.0)):
        place(prop["house"], t, r, s)
    for x in (-8.5, -3, 2.6, 8):
        place(prop["lamp"], (x, 0.15, 3.6))
    place(prop["bench"], (-5.2, 0.15, 5.6))
    place(prop["bench"], (4.6, 0.15, 5.6), 180)
    for t, r, s in (((-10.5, 0.05, 7.2), 0, 1.0), ((-3.4, 0.05, 7.4), 0, 1.2),
                    ((3.3, 0.05, 7.3), 40, 0.9), ((10.2, 0.05, 7.1), 0, 1.1)):
        place(prop["tree"], t, r, s)

    perspective_camera("Camera", prt_to_blender(0.5, 1.9, -4.5), prt_to_blender(0, 2.2, 8), 45.0)
    # The sun shines along street.scene's direction (-0.45, -0.8, 0.4).
    sun = mm.light("Sun", 'SUN', 3.0, (0, 0, 10), colour=(1.0, 0.95, 0.87))
    mm.look_at(sun, tuple(a + b for a, b in zip((0, 0, 10), prt_to_blender(-0.45, -0.8, 0.4))))
    mm.export_gltf(os.path.join(out, "street.glb"))
    meshes = {o.data.name: o.data for o in bpy.context.scene.objects if o.type == 'MESH'}
    drawn = sum(mm.triangles(o.data) for o in bpy.context.scene.objects if o.type == 'MESH')
    print("STREET meshes=%d triangles(drawn)=%d" % (len(meshes), drawn))
    return {"street.glb": drawn}


def main():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    if len(argv) != 1:
        raise SystemExit("usage: blender -b --factory-startup --python scripts/make-path-scenes.py -- OUTROOT")
    root = os.path.abspath(argv[0])
    scn = os.path.join(root, "scenes", "models")
    tris = {}
    tris.update(make_cornell(scn, point_light=False))
    tris.update(make_cornell(scn, point_light=True))
    tris.update(make_street(scn, os.path.join(scn, "street")))
    for name, t in tris.items():
        print("TRIS %-28s blender-side triangles=%d" % (name, t))
        mm.summarise(os.path.join(scn, name), name)


if __name__ == "__main__":
    main()
