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
  scenes/models/maps.glb               a floor (its map repeated by KHR_texture_transform) and
                                       a ball with a tangent-space normal map, and
                                       a ball banded by a metallic-roughness texture (both
                                       64 x 64 data textures made here), under a sun and a
                                       point light; its images are checked texel by texel
  scenes/models/volume.glb             KHR_materials_volume: an amber glass ball and a blue
                                       glass block that absorb inside (the extension written
                                       into the exported file's JSON)
  scenes/models/specular.glb           KHR_materials_specular: a glossy red ball reflecting
                                       three times the default, a teal block a quarter of it
  scenes/models/clearcoat.glb          KHR_materials_clearcoat: a red ball under a glossy coat,
                                       a blue block under a smooth one
  tests/models/blender-tangents.glb    the normal-mapped ball alone, with the tangents Blender
                                       computes (MikkTSpace) written as TANGENT

Command (Blender 3.4.1 from Debian 12, whose glTF add-on also needs python3-numpy):

    blender -b --factory-startup --python scripts/make-path-scenes.py -- /work/main [maps ...]

(the names after the root pick some of cornell, street, maps, volume, specular and
clearcoat; default all).

Deterministic: every position, colour and strength is written here, the props are the
committed files (scripts/make-models.py makes them), and the helpers are make-models.py's.
Units are Blender's: lights in watts (W/m^2 for the sun), exported in glTF's photometric units
(candela, lux) by the exporter's "Standard" lighting mode; emission as Blender's radiance
(colour x strength), exported as emissiveFactor x KHR_materials_emissive_strength.
"""
import importlib.util
import json
import math
import os
import struct
import sys
import tempfile

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


# ----------------------------------------------------------------------------- maps

# Two textures of data (non-colour, no sRGB curve), 64 x 64, made here texel by texel:
#   bumps  a tangent-space normal map of round bumps on a 4 x 4 grid (+X right, +Y up the
#          image, as glTF and Blender read it);
#   bands  a metallic-roughness texture as glTF lays it out: G roughness, B metallic (R, the
#          occlusion's channel, 1): four vertical bands, metal or not, rough or smooth.
MAPS_SIZE = 64


def bumps_normal(x, y):
    """The bump map's normal at texel (x, y) (y = 0 the bottom row), encoded in [0, 1]."""
    cell = MAPS_SIZE / 4
    u = ((x + 0.5) % cell) / cell * 2 - 1  # -1..1 across a cell
    v = ((y + 0.5) % cell) / cell * 2 - 1
    r2 = u * u + v * v
    dx = dy = 0.0
    if r2 < 0.8:  # a bump of height 0.35 (1 - r^2 / 0.8)^2 in cell units
        k = 0.35 * 2 * (1 - r2 / 0.8) * (-2 / 0.8) * (2 / cell) * cell / 2
        dx, dy = k * u, k * v
    n = (-dx, -dy, 1.0)
    s = math.sqrt(sum(c * c for c in n))
    return tuple(0.5 + 0.5 * c / s for c in n)


def bands_texel(x, y):
    band = x * 4 // MAPS_SIZE  # 0..3
    metallic = 1.0 if band % 2 == 1 else 0.0
    roughness = (0.25, 0.25, 0.7, 0.7)[band]
    return (1.0, roughness, metallic)


def data_image(name, fn, folder):
    """A non-colour image saved as PNG and loaded back (file-backed, as the exporter wants)."""
    img = mm.make_image(name, MAPS_SIZE, MAPS_SIZE, fn)
    path = os.path.join(folder, name + ".png")
    mm.save_image(img, path)
    bpy.data.images.remove(img)
    loaded = bpy.data.images.load(path)
    loaded.colorspace_settings.name = 'Non-Color'
    return loaded


def maps_material(name, base, roughness, metallic=0.0, normal_image=None, strength=1.0,
                  mr_image=None, normal_scale=None):
    m = mm.material(name, base=base, metallic=metallic, roughness=roughness)
    nt = m.node_tree
    bsdf = nt.nodes["Principled BSDF"]
    if normal_image is not None:
        tex = nt.nodes.new("ShaderNodeTexImage")
        tex.image = normal_image
        if normal_scale is not None:  # written as KHR_texture_transform's scale
            coords = nt.nodes.new("ShaderNodeTexCoord")
            mapping = nt.nodes.new("ShaderNodeMapping")
            mapping.inputs["Scale"].default_value = (normal_scale, normal_scale, 1.0)
            nt.links.new(coords.outputs["UV"], mapping.inputs["Vector"])
            nt.links.new(mapping.outputs["Vector"], tex.inputs["Vector"])
        nm = nt.nodes.new("ShaderNodeNormalMap")
        nm.space = 'TANGENT'
        nm.inputs["Strength"].default_value = strength
        nt.links.new(tex.outputs["Color"], nm.inputs["Color"])
        nt.links.new(nm.outputs["Normal"], bsdf.inputs["Normal"])
    if mr_image is not None:
        # What the exporter writes as metallicRoughnessTexture: one image, green to Roughness
        # and blue to Metallic through a Separate Color node (3.4's exporter knows no other:
        # through the older Separate RGB it writes an image of white).
        tex = nt.nodes.new("ShaderNodeTexImage")
        tex.image = mr_image
        sep = nt.nodes.new("ShaderNodeSeparateColor")
        sep.mode = 'RGB'
        nt.links.new(tex.outputs["Color"], sep.inputs["Color"])
        nt.links.new(sep.outputs["Green"], bsdf.inputs["Roughness"])
        nt.links.new(sep.outputs["Blue"], bsdf.inputs["Metallic"])
    return m


def check_maps_images(path):
    """The exported file's images hold the texels made here (Blender's exporter has been seen
    to write an empty metallic-roughness image): fails loudly otherwise."""
    with open(path, "rb") as f:
        data = f.read()
    clen = struct.unpack_from("<I", data, 12)[0]
    doc = json.loads(data[20:20 + clen].decode("utf-8"))
    blob = data[20 + clen + 8:]
    folder = os.path.dirname(path)
    wanted = {"bumps": bumps_normal, "bands": bands_texel}
    found = set()
    for k, image in enumerate(doc.get("images", [])):
        view = doc["bufferViews"][image["bufferView"]]
        data = blob[view.get("byteOffset", 0):view.get("byteOffset", 0) + view["byteLength"]]
        tmp = os.path.join(folder, ".maps-check-%d.png" % k)
        with open(tmp, "wb") as f:
            f.write(data)
        img = bpy.data.images.load(tmp)
        img.colorspace_settings.name = 'Non-Color'
        w, h = img.size
        px = list(img.pixels)
        ch = img.channels
        name = image.get("name", "")
        fn = wanted.get(name)
        if fn is None or (w, h) != (MAPS_SIZE, MAPS_SIZE):
            raise SystemExit("maps: unexpected image %r %dx%d" % (name, w, h))
        worst = 0.0
        for y in range(h):
            for x in range(w):
                want = fn(x, y)
                got = px[(y * w + x) * ch:(y * w + x) * ch + 3]
                # bands: R is the occlusion's, which the exporter fills as it likes
                pairs = list(zip(want, got))[1 if name == "bands" else 0:]
                worst = max(worst, max(abs(a - b) for a, b in pairs))
                if worst > 1.0 / 255:
                    raise SystemExit("maps: image %s at (%d, %d): %s, made %s"
                                     % (name, x, y, got, want))
        bpy.data.images.remove(img)
        os.remove(tmp)
        if worst > 1.0 / 255:
            raise SystemExit("maps: image %s differs from what was made by %.4f" % (name, worst))
        print("MAPS image %s %dx%d matches (worst %.4f)" % (name, w, h, worst))
        found.add(name)
    if found != set(wanted):
        raise SystemExit("maps: images %s exported, %s expected" % (sorted(found), sorted(wanted)))


def make_maps(out, tmp, tests):
    """scenes/models/maps.glb: a normal-mapped floor and ball, a ball banded by a
    metallic-roughness texture, under a sun and a point light; and tests/models/
    blender-tangents.glb, the normal-mapped ball alone with the tangents Blender computes
    (MikkTSpace) written as its TANGENT attribute."""
    reset(160, 120)
    bumps = data_image("bumps", bumps_normal, tmp)
    bands = data_image("bands", bands_texel, tmp)
    floor = maps_material("BumpyFloor", (0.6, 0.55, 0.5), 0.5, normal_image=bumps,
                          normal_scale=2.0)
    ball = maps_material("BumpyBall", (0.3, 0.45, 0.7), 0.35, normal_image=bumps, strength=0.8)
    banded = maps_material("BandedBall", (0.9, 0.75, 0.45), 1.0, metallic=1.0, mr_image=bands)

    b = mm.Builder()
    b.face([b.vert(c) for c in ((-2, -1.5, 0), (2, -1.5, 0), (2, 2.5, 0), (-2, 2.5, 0))],
           [(0, 0), (1.5, 0), (1.5, 1.5), (0, 1.5)], 0)  # times 2 by the texture transform
    mm.obj("Floor", b.mesh("Floor"), mats=[floor])
    bs = mm.Builder()
    bs.sphere(0.6, (0, 0, 0), 32, 16)
    bumpy = mm.obj("BumpyBall", bs.mesh("BumpyBall", smooth=True), loc=(0.75, 0.4, 0.6),
                   mats=[ball])
    bs = mm.Builder()
    bs.sphere(0.6, (0, 0, 0), 32, 16)
    mm.obj("BandedBall", bs.mesh("BandedBall", smooth=True), loc=(-0.75, 0.4, 0.6),
           rot=(0, 0, 60), mats=[banded])

    perspective_camera("Camera", (0, -3.6, 2.0), (0, 0.4, 0.45), 40.0)
    sun = mm.light("Sun", 'SUN', 3.0, (0, 0, 5), colour=(1.0, 0.96, 0.9))
    mm.look_at(sun, (1.5, 2.5, 0))
    mm.light("Fill", 'POINT', 60.0, (-1.8, -1.6, 2.2), colour=(0.9, 0.95, 1.0))
    path = os.path.join(out, "maps.glb")
    mm.export_gltf(path)
    check_maps_images(path)
    bpy.ops.object.select_all(action='DESELECT')
    bumpy.select_set(True)
    bpy.ops.export_scene.gltf(
        filepath=os.path.join(tests, "blender-tangents.glb"), export_format='GLB',
        export_tangents=True, export_cameras=False, export_lights=False, export_yup=True,
        export_apply=False, export_animations=False, export_extras=False, use_selection=True)
    return {"maps.glb": sum(mm.triangles(o.data) for o in bpy.context.scene.objects
                            if o.type == 'MESH'), "../../tests/models/blender-tangents.glb":
            mm.triangles(bumpy.data)}


# ----------------------------------------------------------------------------- extensions

# Small scenes of glTF's material extensions, one each, for the comparison with Cycles: a floor
# and a back wall lit by a sun and a point light, with two objects of the extension's
# material. Blender's exporter writes some extensions from the Principled BSDF's inputs and not
# others (KHR_materials_volume needs its "glTF Material Output" node group): each extension is
# written by patch_materials into the exported file's JSON, with the values here, so that the
# file says exactly what is checked; Blender's importer reads them back for Cycles.


def patch_materials(path, extensions):
    """Rewrites the GLB at `path` with extensions[material name] added to that material's
    extensions (and to extensionsUsed)."""
    with open(path, "rb") as f:
        data = f.read()
    clen = struct.unpack_from("<I", data, 12)[0]
    doc = json.loads(data[20:20 + clen].decode("utf-8"))
    rest = data[20 + clen:]
    used = set(doc.get("extensionsUsed", []))
    found = set()
    for m in doc.get("materials", []):
        for name, value in extensions.get(m.get("name"), {}).items():
            m.setdefault("extensions", {})[name] = value
            used.add(name)
            found.add(m.get("name"))
    if found != set(extensions):
        raise SystemExit("%s: materials %s not found" % (path, sorted(set(extensions) - found)))
    doc["extensionsUsed"] = sorted(used)
    text = json.dumps(doc, separators=(",", ":")).encode("utf-8")
    text += b" " * (-len(text) % 4)
    out = b"glTF" + struct.pack("<II", 2, 12 + 8 + len(text) + len(rest))
    out += struct.pack("<I", len(text)) + b"JSON" + text + rest
    with open(path, "wb") as f:
        f.write(out)


def extension_stage(a, b, lift=0.0):
    """The room of the extension scenes and its lights (after reset(160, 120), which the
    materials a and b follow); a goes on a ball (left), b on a block (right) `lift` above the
    floor."""
    floor = mm.material("Floor", base=(0.6, 0.55, 0.5), roughness=0.6)
    wall = mm.material("Wall", base=(0.3, 0.45, 0.7), roughness=0.8)
    bf = mm.Builder()
    quad(bf, [(-3, -2, 0), (3, -2, 0), (3, 2, 0), (-3, 2, 0)], 0)
    mm.obj("Floor", bf.mesh("Floor"), mats=[floor])
    bw = mm.Builder()
    quad(bw, [(-3, 2, 0), (3, 2, 0), (3, 2, 3), (-3, 2, 3)], 0)
    mm.obj("Wall", bw.mesh("Wall"), mats=[wall])
    bs = mm.Builder()
    bs.sphere(0.6, (0, 0, 0), 48, 24)
    mm.obj("Ball", bs.mesh("Ball", smooth=True), loc=(-0.75, 0.3, 0.6), mats=[a])
    bb = mm.Builder()
    bb.box((-0.45, -0.45, 0.0), (0.45, 0.45, 0.9), mat=0)
    mm.obj("Block", bb.mesh("Block"), loc=(0.8, 0.2, lift), rot=(0, 0, 25), mats=[b])
    perspective_camera("Camera", (0, -3.6, 1.9), (0, 0.3, 0.5), 40.0)
    sun = mm.light("Sun", 'SUN', 3.0, (0, 0, 5), colour=(1.0, 0.96, 0.9))
    mm.look_at(sun, (1.2, 2.5, 0))
    mm.light("Fill", 'POINT', 60.0, (-1.8, -1.6, 2.2), colour=(0.9, 0.95, 1.0))


def make_volume(out):
    """scenes/models/volume.glb: KHR_materials_volume, two smooth absorbing glasses (thick:
    Blender has no thin-walled glass to compare with), a ball and a block 2 mm above the floor
    (standing on it, the block's bottom and the floor are one plane, and which of them a ray
    meets first is the renderer's guess: Cycles' and PRT's differ). Smooth, so that the check
    is of the absorption: a rough glass block differs from Cycles' by itself (22 dB at 80 x 60
    without the extension)."""
    reset(160, 120)
    ball = mm.material("AmberGlass", base=(1, 1, 1), roughness=0.0, transmission=1.0, ior=1.5)
    block = mm.material("BlueGlass", base=(1, 1, 1), roughness=0.0, transmission=1.0, ior=1.5)
    extension_stage(ball, block, lift=0.002)
    path = os.path.join(out, "volume.glb")
    mm.export_gltf(path)
    patch_materials(path, {
        "AmberGlass": {"KHR_materials_volume": {"thicknessFactor": 1.2,
                                                "attenuationColor": [0.9, 0.45, 0.15],
                                                "attenuationDistance": 0.4}},
        "BlueGlass": {"KHR_materials_volume": {"thicknessFactor": 0.9,
                                               "attenuationColor": [0.3, 0.6, 0.95],
                                               "attenuationDistance": 0.5}}})
    return {"volume.glb": sum(mm.triangles(o.data) for o in bpy.context.scene.objects
                              if o.type == 'MESH')}


def make_specular(out):
    """scenes/models/specular.glb: KHR_materials_specular on two dark dielectrics, a glossy
    ball reflecting three times glTF's default (specularColorFactor 3: F0 0.12) and a rougher
    block a quarter of it (0.25: F0 0.01). Grey colours and a factor of 1: Blender's importer
    turns the extension into the Principled BSDF's Specular (the colour's luminance times the
    index's F0 over 0.08) and Specular Tint, and leaves the factor out."""
    reset(160, 120)
    ball = mm.material("ShinyRed", base=(0.3, 0.05, 0.05), roughness=0.15)
    block = mm.material("DullTeal", base=(0.05, 0.2, 0.3), roughness=0.3)
    extension_stage(ball, block)
    path = os.path.join(out, "specular.glb")
    mm.export_gltf(path)
    patch_materials(path, {
        "ShinyRed": {"KHR_materials_specular": {"specularFactor": 1.0,
                                                "specularColorFactor": [3.0, 3.0, 3.0]}},
        "DullTeal": {"KHR_materials_specular": {"specularFactor": 1.0,
                                                "specularColorFactor": [0.25, 0.25, 0.25]}}})
    return {"specular.glb": sum(mm.triangles(o.data) for o in bpy.context.scene.objects
                                if o.type == 'MESH')}


def make_clearcoat(out):
    """scenes/models/clearcoat.glb: KHR_materials_clearcoat, a rough red ball under a glossy
    coat (roughness 0.2) and a dull blue block under a smooth one, a mirror-like varnish."""
    reset(160, 120)
    ball = mm.material("CoatedRed", base=(0.5, 0.05, 0.05), roughness=0.6)
    block = mm.material("VarnishedBlue", base=(0.05, 0.1, 0.3), roughness=0.8)
    extension_stage(ball, block)
    path = os.path.join(out, "clearcoat.glb")
    mm.export_gltf(path)
    patch_materials(path, {
        "CoatedRed": {"KHR_materials_clearcoat": {"clearcoatFactor": 1.0,
                                                  "clearcoatRoughnessFactor": 0.2}},
        "VarnishedBlue": {"KHR_materials_clearcoat": {"clearcoatFactor": 1.0,
                                                      "clearcoatRoughnessFactor": 0.0}}})
    return {"clearcoat.glb": sum(mm.triangles(o.data) for o in bpy.context.scene.objects
                                 if o.type == 'MESH')}


def main():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    makers = ("cornell", "street", "maps", "volume", "specular", "clearcoat")
    if len(argv) < 1 or any(a not in makers for a in argv[1:]):
        raise SystemExit("usage: blender -b --factory-startup --python scripts/make-path-scenes.py -- "
                         "OUTROOT [%s ...] (default: all)" % " ".join(makers))
    root = os.path.abspath(argv[0])
    wanted = argv[1:] or makers
    scn = os.path.join(root, "scenes", "models")
    tris = {}
    if "cornell" in wanted:
        tris.update(make_cornell(scn, point_light=False))
        tris.update(make_cornell(scn, point_light=True))
    if "street" in wanted:
        tris.update(make_street(scn, os.path.join(scn, "street")))
    if "maps" in wanted:
        with tempfile.TemporaryDirectory() as tmp:
            tris.update(make_maps(scn, tmp, os.path.join(root, "tests", "models")))
    if "volume" in wanted:
        tris.update(make_volume(scn))
    if "specular" in wanted:
        tris.update(make_specular(scn))
    if "clearcoat" in wanted:
        tris.update(make_clearcoat(scn))
    for name, t in tris.items():
        print("TRIS %-28s blender-side triangles=%d" % (name, t))
        mm.summarise(os.path.join(scn, name), name)


if __name__ == "__main__":
    main()
