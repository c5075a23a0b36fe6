"""Builds PRT's Blender-exported example and test models from code and writes them with
Blender's own exporters (glTF 2.0, OBJ+MTL, FBX, COLLADA).

Nothing is downloaded: every mesh is generated here and every texture is an image whose
pixels this script computes (wood planks, marble, checkerboard, bricks, wood stripes, a
numbered grid). Geometry and pixels are deterministic (fixed seeds, no time-dependent
input); FBX and COLLADA files carry their exporters' timestamps.

Command (Blender 3.4.1 from Debian 12, whose glTF add-on also needs python3-numpy):

    blender -b --factory-startup --python scripts/make-models.py -- /work/main

(add -noaudio if Blender complains about audio). OUTROOT (the argument after --) gets:

  OUTROOT/scenes/models/crate.glb              crate + ball, camera, point + sun light
  OUTROOT/scenes/models/pawns.gltf (+ .bin, 'pawn marble.png', board-checker.png)
                                               16 linked-duplicate pawns on a board,
                                               glass material, spot + point light, camera
  OUTROOT/scenes/models/street/{lamp,bench,tree,house}.glb   props, no camera or lights
  OUTROOT/tests/models/blender-cube.glb / .gltf (embedded) / .obj + .mtl + .png
  OUTROOT/tests/models/blender-cube-winpath.obj/.mtl + textures/cube tex.png
  OUTROOT/tests/models/blender-scene.fbx / .dae
  OUTROOT/tests/models/blender-instances.glb, blender-ortho.glb, blender-lights.glb,
  OUTROOT/tests/models/blender-skinned.glb

At the end it reads every glTF file back (JSON / GLB header) and prints a summary.
"""
import json
import math
import os
import random
import shutil
import struct
import sys

import bmesh
import bpy
from mathutils import Vector

RES_X, RES_Y = 640, 480  # render resolution: the glTF camera's aspectRatio comes from it


# ----------------------------------------------------------------------------- textures

def hash01(ix, iy, seed):
    n = (ix * 374761393 + iy * 668265263 + seed * 1442695041) & 0xFFFFFFFF
    n = ((n ^ (n >> 13)) * 1274126177) & 0xFFFFFFFF
    return ((n ^ (n >> 16)) & 0xFFFF) / 65535.0


def vnoise(x, y, seed, px=0, py=0):
    """Value noise; px/py > 0 make it periodic with that many lattice cells."""
    ix, iy = math.floor(x), math.floor(y)
    fx, fy = x - ix, y - iy
    fx, fy = fx * fx * (3 - 2 * fx), fy * fy * (3 - 2 * fy)

    def h(a, b):
        if px:
            a %= px
        if py:
            b %= py
        return hash01(a, b, seed)

    a = h(ix, iy) + (h(ix + 1, iy) - h(ix, iy)) * fx
    b = h(ix, iy + 1) + (h(ix + 1, iy + 1) - h(ix, iy + 1)) * fx
    return a + (b - a) * fy


def fbm(x, y, seed, octaves=4, px=0, py=0):
    total, amp, norm = 0.0, 1.0, 0.0
    for o in range(octaves):
        total += amp * vnoise(x, y, seed + o, px, py)
        norm += amp
        x, y, px, py, amp = x * 2, y * 2, px * 2, py * 2, amp * 0.5
    return total / norm


def lerp3(a, b, t):
    return tuple(a[i] + (b[i] - a[i]) * t for i in range(3))


FONT = {  # 5x7 digits, rows top to bottom
    '0': ("01110", "10001", "10011", "10101", "11001", "10001", "01110"),
    '1': ("00100", "01100", "00100", "00100", "00100", "00100", "01110"),
    '2': ("01110", "10001", "00001", "00010", "00100", "01000", "11111"),
    '3': ("11111", "00010", "00100", "00010", "00001", "10001", "01110"),
    '4': ("00010", "00110", "01010", "10010", "11111", "00010", "00010"),
    '5': ("11111", "10000", "11110", "00001", "00001", "10001", "01110"),
    '6': ("00110", "01000", "10000", "11110", "10001", "10001", "01110"),
    '7': ("11111", "00001", "00010", "00100", "01000", "01000", "01000"),
    '8': ("01110", "10001", "10001", "01110", "10001", "10001", "01110"),
    '9': ("01110", "10001", "10001", "01111", "00001", "00010", "01100"),
}


def text_mask(text, cx, cy, scale):
    """Set of (x, y) pixels (y up) covered by `text` centred on (cx, cy)."""
    width = (len(text) * 6 - 1) * scale
    x0, y0 = cx - width // 2, cy - (7 * scale) // 2
    pts = set()
    for k, ch in enumerate(text):
        for r, row in enumerate(FONT[ch]):
            for c, bit in enumerate(row):
                if bit == '1':
                    for dx in range(scale):
                        for dy in range(scale):
                            pts.add((x0 + (k * 6 + c) * scale + dx, y0 + (6 - r) * scale + dy))
    return pts


def make_image(name, w, h, colour_fn):
    """colour_fn(x, y) -> (r, g, b) in 0..1 (sRGB), y = 0 is the bottom row (Blender's order)."""
    img = bpy.data.images.new(name, w, h, alpha=False)
    px = []
    for y in range(h):
        for x in range(w):
            r, g, b = colour_fn(x, y)
            px.extend((min(max(r, 0.0), 1.0), min(max(g, 0.0), 1.0), min(max(b, 0.0), 1.0), 1.0))
    img.pixels.foreach_set(px)
    img.update()
    return img


def save_image(img, path):
    img.filepath_raw = path
    img.file_format = 'PNG'
    img.save()


def tex_crate(size=256, number="42"):
    plank_h = size / 5
    frame = size * 0.09
    paint = text_mask(number, size // 2, size // 2, 9)

    def fn(x, y):
        dark, light = (0.30, 0.17, 0.08), (0.62, 0.42, 0.22)
        in_frame = x < frame or x >= size - frame or y < frame or y >= size - frame
        if in_frame:
            vertical = (x < frame or x >= size - frame) and frame <= y < size - frame
            along, across = (y, x) if vertical else (x, y)
            g = 0.5 + 0.5 * math.sin(across * 0.9 + 6 * fbm(along * 0.03, across * 0.2, 11))
            c = lerp3(dark, light, 0.35 + 0.4 * g)
            c = tuple(v * 0.8 for v in c)
            edge = min(x, y, size - 1 - x, size - 1 - y)
            if edge < 2 or (abs(edge - frame) < 1.5 and frame - 2 < edge):
                c = tuple(v * 0.5 for v in c)
            for nx, ny in ((frame / 2, frame / 2), (size - frame / 2, frame / 2),
                           (frame / 2, size - frame / 2), (size - frame / 2, size - frame / 2)):
                if (x - nx) ** 2 + (y - ny) ** 2 < 6:
                    c = (0.2, 0.2, 0.22)
            return c
        p = int(y // plank_h)
        yl = y - p * plank_h
        tone = 0.75 + 0.5 * hash01(p, 3, 5)
        g = 0.5 + 0.5 * math.sin(yl * 0.7 + 8 * fbm(x * 0.02 + p * 7, yl * 0.15, 3))
        c = lerp3(dark, light, (0.25 + 0.6 * g) * min(tone, 1.0))
        if yl < 2:
            c = (0.12, 0.07, 0.03)
        if (x, y) in paint and fbm(x * 0.15, y * 0.15, 21) < 0.68:
            c = (0.86, 0.84, 0.74)
        return c
    return fn


def tex_marble(size=128):
    def fn(x, y):
        t = math.sin((x / size * 4 + y / size * 2.5 + 3.0 * fbm(x / 16.0, y / 16.0, 7, 4, size // 16, size // 16)) * math.pi)
        vein = (1 - abs(t)) ** 6
        base = (0.93, 0.91, 0.87)
        c = lerp3(base, (0.45, 0.48, 0.46), vein * 0.8)
        k = 0.96 + 0.04 * vnoise(x / 4.0, y / 4.0, 9, size // 4, size // 4)
        return tuple(v * k for v in c)
    return fn


def tex_checker(size=256, cells=8):
    cell = size // cells

    def fn(x, y):
        light = ((x // cell) + (y // cell)) % 2 == 1
        c = (0.86, 0.80, 0.66) if light else (0.22, 0.13, 0.08)
        k = 0.93 + 0.07 * fbm(x * 0.05, y * 0.4, 13, 3)
        return tuple(v * k for v in c)
    return fn


def tex_bricks(size=128, rows=4, cols=2):
    bh, bw, mortar = size // rows, size // cols, 3
    rng = random.Random(2024)
    tones = [[0.75 + 0.35 * rng.random() for _ in range(cols)] for _ in range(rows)]

    def fn(x, y):
        r = y // bh
        xs = (x + (bw // 2 if r % 2 else 0)) % size
        c_ = xs // bw
        if y % bh < mortar or xs % bw < mortar:
            k = 0.9 + 0.1 * vnoise(x / 3.0, y / 3.0, 4, size // 3, size // 3)
            return (0.72 * k, 0.70 * k, 0.66 * k)
        t = tones[r][c_]
        n = 0.85 + 0.3 * fbm(x / 8.0, y / 8.0, 17, 3, size // 8, size // 8)
        return (0.58 * t * n, 0.24 * t * n, 0.16 * t * n)
    return fn


def tex_wood_stripes(w=128, h=64):
    def fn(x, y):
        g = 0.5 + 0.5 * math.sin(y * 0.8 + 5 * fbm(x / 16.0, y / 6.0, 31, 3, w // 16, 0))
        return lerp3((0.36, 0.21, 0.10), (0.70, 0.50, 0.30), 0.2 + 0.7 * g)
    return fn


def tex_numbered_grid(size=128, cells=4):
    cell = size // cells
    masks = {}
    for n in range(cells * cells):
        col, row_from_top = n % cells, n // cells
        cx = col * cell + cell // 2
        cy = size - (row_from_top * cell + cell // 2)
        masks.update({p: n for p in text_mask(str(n + 1), cx, cy, 2)})

    def fn(x, y):
        col, row_from_top = x // cell, (size - 1 - y) // cell
        n = row_from_top * cells + col
        if x % cell == 0 or y % cell == 0 or x == size - 1 or y == size - 1:
            return (0.05, 0.05, 0.05)
        if masks.get((x, y)) == n:
            return (0.02, 0.02, 0.02)
        hue = n / (cells * cells)
        import colorsys
        return colorsys.hsv_to_rgb(hue, 0.45, 0.95)
    return fn


def grid_cell_uv(n, cells=4):
    """UV rectangle (u0, v0, u1, v1) of cell n (0-based, row-major from the top) of the numbered grid."""
    col, row_from_top = n % cells, n // cells
    u0 = col / cells
    v1 = 1 - row_from_top / cells
    return u0, v1 - 1 / cells, u0 + 1 / cells, v1


# ----------------------------------------------------------------------------- meshes

class Builder:
    """Accumulates polygons with per-corner UVs and material indices."""

    def __init__(self):
        self.verts, self.faces, self.uvs, self.mats = [], [], [], []

    def vert(self, co):
        self.verts.append(tuple(co))
        return len(self.verts) - 1

    def face(self, idx, uv, mat=0):
        self.faces.append(tuple(idx))
        self.uvs.append(tuple(uv))
        self.mats.append(mat)

    def box(self, lo, hi, mat=0, uv_scale=None, cell_uvs=None, face_mats=None):
        """Axis-aligned box. UVs: a box projection, u/v = metres * uv_scale (None: each face
        gets 0..1), or cell_uvs[face] = (u0, v0, u1, v1). Faces: +X -X +Y -Y +Z -Z."""
        x0, y0, z0 = lo
        x1, y1, z1 = hi
        # each face: 4 corners counter-clockwise seen from outside, with its (u, v) axes
        quads = [
            ([(x1, y0, z0), (x1, y1, z0), (x1, y1, z1), (x1, y0, z1)], (1, 2), (1, 1)),
            ([(x0, y1, z0), (x0, y0, z0), (x0, y0, z1), (x0, y1, z1)], (1, 2), (-1, 1)),
            ([(x1, y1, z0), (x0, y1, z0), (x0, y1, z1), (x1, y1, z1)], (0, 2), (-1, 1)),
            ([(x0, y0, z0), (x1, y0, z0), (x1, y0, z1), (x0, y0, z1)], (0, 2), (1, 1)),
            ([(x0, y0, z1), (x1, y0, z1), (x1, y1, z1), (x0, y1, z1)], (0, 1), (1, 1)),
            ([(x0, y1, z0), (x1, y1, z0), (x1, y0, z0), (x0, y0, z0)], (0, 1), (1, -1)),
        ]
        for f, (corners, axes, signs) in enumerate(quads):
            idx = [self.vert(c) for c in corners]
            if cell_uvs is not None:
                u0, v0, u1, v1 = cell_uvs[f]
                uv = [(u0, v0), (u1, v0), (u1, v1), (u0, v1)]
            elif uv_scale is None:
                uv = [(0, 0), (1, 0), (1, 1), (0, 1)]
            else:
                uv = [(signs[0] * c[axes[0]] * uv_scale, signs[1] * c[axes[1]] * uv_scale) for c in corners]
            self.face(idx, uv, face_mats[f] if face_mats else mat)

    def lathe(self, profile, segments, centre=(0, 0, 0), mats=None):
        """Surface of revolution about the local Z axis; profile = [(r, z)] from bottom
        to top; r == 0 makes a pole. mats[i] is the material of profile segment i."""
        cx, cy, cz = centre
        lengths = [0.0]
        for (r0, z0), (r1, z1) in zip(profile, profile[1:]):
            lengths.append(lengths[-1] + math.hypot(r1 - r0, z1 - z0))
        rings = []
        for r, z in profile:
            if r == 0:
                rings.append([self.vert((cx, cy, cz + z))])
            else:
                rings.append([self.vert((cx + r * math.cos(2 * math.pi * j / segments),
                                         cy + r * math.sin(2 * math.pi * j / segments),
                                         cz + z)) for j in range(segments)])
        for i in range(len(profile) - 1):
            a, b = rings[i], rings[i + 1]
            va, vb = lengths[i] / lengths[-1], lengths[i + 1] / lengths[-1]
            m = mats[i] if mats else 0
            for j in range(segments):
                j1 = (j + 1) % segments
                ua, ub = j / segments, (j + 1) / segments
                if len(a) == 1:
                    self.face((a[0], b[j1], b[j]), [((ua + ub) / 2, va), (ub, vb), (ua, vb)], m)
                elif len(b) == 1:
                    self.face((a[j], a[j1], b[0]), [(ua, va), (ub, va), ((ua + ub) / 2, vb)], m)
                else:
                    self.face((a[j], a[j1], b[j1], b[j]), [(ua, va), (ub, va), (ub, vb), (ua, vb)], m)

    def sphere(self, radius, centre, segments=24, rings=12, mat=0):
        prof = [(radius * math.sin(math.pi * i / rings), -radius * math.cos(math.pi * i / rings))
                for i in range(rings + 1)]
        prof[0] = (0, -radius)
        prof[-1] = (0, radius)
        self.lathe(prof, segments, centre, [mat] * rings)

    def cylinder(self, r, z0, z1, segments=16, centre=(0, 0), mat=0, r_top=None):
        rt = r if r_top is None else r_top
        self.lathe([(0, z0), (r, z0), (rt, z1), (0, z1)], segments, (centre[0], centre[1], 0), [mat] * 3)

    def mesh(self, name, smooth=False, auto_smooth=None):
        me = bpy.data.meshes.new(name)
        me.from_pydata(self.verts, [], self.faces)
        uvl = me.uv_layers.new(name="UVMap")
        li = 0
        for p, uv in zip(me.polygons, self.uvs):
            assert p.loop_start == li and p.loop_total == len(uv)
            for k in range(p.loop_total):
                uvl.data[li + k].uv = uv[k]
            li += p.loop_total
            p.material_index = self.mats[p.index]
            p.use_smooth = smooth
        # weld coincident corners (UVs and normals stay per corner), as modelled meshes are
        bm = bmesh.new()
        bm.from_mesh(me)
        bmesh.ops.remove_doubles(bm, verts=list(bm.verts), dist=1e-6)
        bm.to_mesh(me)
        bm.free()
        if auto_smooth is not None:
            me.use_auto_smooth = True
            me.auto_smooth_angle = math.radians(auto_smooth)
        me.update()
        return me


def triangles(me):
    return sum(len(p.vertices) - 2 for p in me.polygons)


# ----------------------------------------------------------------------------- scene helpers

def reset():
    bpy.ops.wm.read_factory_settings(use_empty=True)
    sc = bpy.context.scene
    sc.render.resolution_x, sc.render.resolution_y = RES_X, RES_Y
    sc.render.resolution_percentage = 100
    sc.render.pixel_aspect_x = sc.render.pixel_aspect_y = 1.0
    sc.frame_start, sc.frame_end = 1, 24
    sc.frame_set(1)
    return sc


def link(obj, parent=None):
    bpy.context.scene.collection.objects.link(obj)
    if parent is not None:
        obj.parent = parent
    return obj


def obj(name, data, loc=(0, 0, 0), rot=(0, 0, 0), scale=(1, 1, 1), mats=(), parent=None):
    o = bpy.data.objects.new(name, data)
    o.location, o.rotation_euler, o.scale = loc, [math.radians(a) for a in rot], scale
    if data is not None and hasattr(data, "materials") and not data.materials:
        for m in mats:
            data.materials.append(m)
    return link(o, parent)


def look_at(o, target):
    d = Vector(target) - Vector(o.location)
    o.rotation_euler = d.to_track_quat('-Z', 'Y').to_euler()


def camera(name, loc, target, lens=35.0, ortho_scale=None):
    cam = bpy.data.cameras.new(name)
    cam.sensor_fit = 'AUTO'
    cam.sensor_width = 36.0
    cam.lens = lens
    cam.clip_start, cam.clip_end = 0.1, 100.0
    if ortho_scale is not None:
        cam.type = 'ORTHO'
        cam.ortho_scale = ortho_scale
    o = obj(name, cam, loc)
    look_at(o, target)
    bpy.context.scene.camera = o
    return o


def light(name, kind, energy, loc, target=None, colour=(1, 1, 1), spot_deg=None, blend=0.15,
          cutoff=None):
    ld = bpy.data.lights.new(name, kind)
    ld.energy = energy
    ld.color = colour
    if kind == 'SPOT':
        ld.spot_size = math.radians(spot_deg)
        ld.spot_blend = blend
    if cutoff is not None:
        ld.use_custom_distance = True
        ld.cutoff_distance = cutoff
    o = obj(name, ld, loc)
    if target is not None:
        look_at(o, target)
    return o


def material(name, base=(0.8, 0.8, 0.8), metallic=0.0, roughness=0.5, image=None,
             transmission=0.0, ior=1.45, emission=None, strength=0.0, vertex_colour=None):
    m = bpy.data.materials.new(name)
    m.use_nodes = True
    nt = m.node_tree
    bsdf = nt.nodes["Principled BSDF"]
    bsdf.inputs["Base Color"].default_value = (*base, 1.0)
    bsdf.inputs["Metallic"].default_value = metallic
    bsdf.inputs["Roughness"].default_value = roughness
    bsdf.inputs["Transmission"].default_value = transmission
    bsdf.inputs["IOR"].default_value = ior
    if emission is not None:
        bsdf.inputs["Emission"].default_value = (*emission, 1.0)
        bsdf.inputs["Emission Strength"].default_value = strength
    if image is not None:
        tex = nt.nodes.new("ShaderNodeTexImage")
        tex.image = image
        tex.location = (-400, 200)
        nt.links.new(tex.outputs["Color"], bsdf.inputs["Base Color"])
    if vertex_colour is not None:
        vc = nt.nodes.new("ShaderNodeVertexColor")
        vc.layer_name = vertex_colour
        vc.location = (-400, 200)
        nt.links.new(vc.outputs["Color"], bsdf.inputs["Base Color"])
    m.diffuse_color = (*base, 1.0)
    m.metallic, m.roughness = metallic, roughness
    return m


def export_gltf(path, fmt='GLB', cameras=True, lights=True, animations=False):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    bpy.ops.export_scene.gltf(
        filepath=path, export_format=fmt, export_cameras=cameras, export_lights=lights,
        convert_lighting_mode='SPEC', export_image_format='AUTO', export_yup=True,
        export_apply=False, export_animations=animations, export_extras=False,
        use_selection=False)


# ----------------------------------------------------------------------------- A. scenes

def make_crate(out):
    reset()
    img = make_image("crate planks", 256, 256, tex_crate())
    wood = material("CrateWood", base=(1, 1, 1), roughness=0.75, image=img)
    paint = material("BallPaint", base=(0.80, 0.10, 0.06), metallic=0.6, roughness=0.25)

    bm = bmesh.new()
    bmesh.ops.create_cube(bm, size=1.0)
    bmesh.ops.bevel(bm, geom=list(bm.edges), offset=0.04, segments=3, affect='EDGES',
                    profile=0.5, clamp_overlap=True)
    uvl = bm.loops.layers.uv.new("UVMap")
    for f in bm.faces:
        n = f.normal
        ax = max(range(3), key=lambda i: (abs(n[i]), -i))
        for lp in f.loops:
            x, y, z = lp.vert.co
            if ax == 0:
                u, v = (y if n.x > 0 else -y), z
            elif ax == 1:
                u, v = (-x if n.y > 0 else x), z
            else:
                u, v = x, (y if n.z > 0 else -y)
            lp[uvl].uv = (u + 0.5, v + 0.5)
    me = bpy.data.meshes.new("Crate")
    bm.to_mesh(me)
    bm.free()
    for p in me.polygons:
        p.use_smooth = True
    me.use_auto_smooth = True
    me.auto_smooth_angle = math.radians(35)
    crate = obj("Crate", me, loc=(0, 0, 0.5), rot=(0, 0, 15), mats=[wood])

    b = Builder()
    b.sphere(0.3, (0, 0, 0), 32, 16)
    ball = obj("Ball", b.mesh("Ball", smooth=True), loc=(0.95, -0.55, 0.3), mats=[paint])

    camera("Camera", (3.2, -3.6, 2.1), (0.3, -0.2, 0.45), lens=35)
    light("PointLight", 'POINT', 600.0, (1.8, -2.2, 2.6), colour=(1.0, 0.92, 0.8))
    light("Sun", 'SUN', 2.5, (-2, 1, 4), target=(0, 0, 0), colour=(1.0, 1.0, 0.97))
    export_gltf(os.path.join(out, "crate.glb"))
    return {"crate.glb": triangles(crate.data) + triangles(ball.data)}


def pawn_mesh():
    prof = [(0, 0), (0.12, 0), (0.12, 0.035), (0.11, 0.05),          # base ring (material 1)
            (0.095, 0.06), (0.08, 0.085), (0.066, 0.13), (0.055, 0.18),
            (0.047, 0.235), (0.078, 0.255), (0.078, 0.272), (0.042, 0.29)]
    hc, hr = 0.355, 0.07
    for k in range(1, 8):  # head: sphere arc from below to the top pole
        a = -math.radians(66) + (math.radians(156) * k / 8)
        prof.append((hr * math.cos(a), hc + hr * math.sin(a)))
    prof.append((0, hc + hr))
    mats = [1, 1, 1] + [0] * (len(prof) - 4)
    b = Builder()
    b.lathe(prof, 24, (0, 0, 0), mats)
    return b.mesh("Pawn", smooth=True, auto_smooth=50)


def make_pawns(out):
    reset()
    marble_img = make_image("pawn marble", 128, 128, tex_marble())
    board_img = make_image("board-checker", 256, 256, tex_checker())
    marble = material("PawnMarble", base=(1, 1, 1), roughness=0.3, image=marble_img)
    glass = material("PawnGlass", base=(0.85, 0.95, 1.0), roughness=0.05, transmission=1.0, ior=1.45)
    ring = material("PawnRing", base=(1.0, 0.76, 0.33), metallic=1.0, roughness=0.3)
    checker = material("BoardChecker", base=(1, 1, 1), roughness=0.4, image=board_img)
    frame = material("BoardFrame", base=(0.18, 0.09, 0.04), roughness=0.55)

    board = obj("Board", None, loc=(0.1, 0.05, 0.12), rot=(0, 0, 20))
    board.empty_display_type = 'PLAIN_AXES'
    b = Builder()
    b.box((-1.2, -1.2, -0.12), (1.2, 1.2, 0.0), face_mats=[1, 1, 1, 1, 0, 1])
    top = obj("BoardTop", b.mesh("BoardTop"), mats=[checker, frame], parent=board)

    pawn = pawn_mesh()
    pawn.materials.append(marble)
    pawn.materials.append(ring)
    sides = []
    for name, y, rz, body in (("MarbleSide", -0.75, 0, None), ("GlassSide", 0.75, 180, glass)):
        side = obj(name, None, loc=(0, y, 0), rot=(0, 0, rz), parent=board)
        sides.append(side)
        for i in range(8):
            p = obj("%s.%d" % (name.replace("Side", "Pawn"), i + 1), pawn,
                    loc=(-1.05 + 0.3 * i, 0, 0), rot=(0, 0, 15 * i), parent=side)
            if body is not None:  # same mesh data, body slot overridden per object
                p.material_slots[0].link = 'OBJECT'
                p.material_slots[0].material = body

    camera("Camera", (2.9, -3.7, 2.5), (0.1, 0.0, 0.2), lens=40)
    light("Spot", 'SPOT', 900.0, (-1.8, -2.4, 3.6), target=(0.1, 0.0, 0.1), spot_deg=50, blend=0.3)
    light("PointLight", 'POINT', 250.0, (2.2, 2.0, 2.4), colour=(0.85, 0.9, 1.0))
    export_gltf(os.path.join(out, "pawns.gltf"), fmt='GLTF_SEPARATE')
    return {"pawns.gltf": triangles(top.data) + 16 * triangles(pawn)}


def make_lamp(out):
    reset()
    metal = material("LampMetal", base=(0.08, 0.16, 0.10), metallic=0.8, roughness=0.4)
    bulb = material("LampBulb", base=(1.0, 0.9, 0.7), roughness=0.2,
                    emission=(1.0, 0.8, 0.5), strength=5.0)
    b = Builder()
    b.cylinder(0.16, 0.0, 0.12, 16, mat=0, r_top=0.12)         # foot
    b.cylinder(0.055, 0.12, 2.9, 16, mat=0, r_top=0.04)        # post
    b.cylinder(0.09, 2.9, 2.95, 16, mat=0)                     # collar
    b.sphere(0.15, (0, 0, 3.08), 16, 8, mat=1)                 # bulb
    b.lathe([(0, 3.18), (0.22, 3.18), (0.0, 3.38)], 16, (0, 0, 0), [0, 0])  # cap
    lamp = obj("Lamp", b.mesh("Lamp", smooth=True, auto_smooth=40), mats=[metal, bulb])
    export_gltf(os.path.join(out, "lamp.glb"), cameras=False, lights=False)
    return {"street/lamp.glb": triangles(lamp.data)}


def make_bench(out):
    reset()
    img = make_image("bench wood", 128, 64, tex_wood_stripes())
    wood = material("BenchWood", base=(1, 1, 1), roughness=0.6, image=img)
    iron = material("BenchIron", base=(0.05, 0.05, 0.05), metallic=0.9, roughness=0.45)
    b = Builder()
    for k in range(3):  # seat slats
        y0 = -0.22 + k * 0.15
        b.box((-0.8, y0, 0.42), (0.8, y0 + 0.12, 0.46), mat=0, uv_scale=0.6)
    for k in range(2):  # back slats
        z0 = 0.58 + k * 0.17
        b.box((-0.8, 0.20, z0), (0.8, 0.24, z0 + 0.12), mat=0, uv_scale=0.6)
    for x in (-0.68, 0.62):  # cast-iron side frames
        b.box((x, -0.22, 0.0), (x + 0.06, -0.17, 0.42), mat=1)    # front leg
        b.box((x, 0.22, 0.0), (x + 0.06, 0.27, 0.92), mat=1)      # back leg / back support
        b.box((x, -0.22, 0.38), (x + 0.06, 0.27, 0.42), mat=1)    # seat rail
        b.box((x - 0.02, -0.26, 0.58), (x + 0.08, 0.2, 0.62), mat=1)  # arm rest
        b.box((x, -0.22, 0.42), (x + 0.06, -0.18, 0.58), mat=1)   # arm support
    bench = obj("Bench", b.mesh("Bench"), mats=[wood, iron])
    export_gltf(os.path.join(out, "bench.glb"), cameras=False, lights=False)
    return {"street/bench.glb": triangles(bench.data)}


def make_tree(out):
    reset()
    bark = material("Bark", base=(0.28, 0.17, 0.09), roughness=0.9)
    leaves = material("Leaves", base=(1, 1, 1), roughness=0.8, vertex_colour="Col")
    b = Builder()
    b.lathe([(0, 0), (0.16, 0), (0.11, 0.6), (0.08, 1.4), (0, 1.4)], 8, (0, 0, 0), [0, 0, 0, 0])
    trunk = obj("Trunk", b.mesh("Trunk", smooth=True, auto_smooth=60), mats=[bark])

    rng = random.Random(7)
    bm = bmesh.new()
    bmesh.ops.create_icosphere(bm, subdivisions=3, radius=0.9)
    bm.verts.ensure_lookup_table()
    for v in bm.verts:
        d = 1.0 + rng.uniform(-0.12, 0.12)
        v.co = Vector((v.co.x * d, v.co.y * d, v.co.z * d * 1.15))
    me = bpy.data.meshes.new("Crown")
    bm.to_mesh(me)
    bm.free()
    col = me.color_attributes.new("Col", 'FLOAT_COLOR', 'POINT')
    for i, v in enumerate(me.vertices):
        t = (v.co.z + 1.05) / 2.1
        j = rng.uniform(-0.06, 0.06)
        col.data[i].color = (0.10 + 0.25 * t + j, 0.30 + 0.35 * t + j, 0.06 + 0.08 * t, 1.0)
    me.color_attributes.active_color = col
    me.color_attributes.render_color_index = me.color_attributes.find("Col")
    me.update()
    crown = obj("Crown", me, loc=(0, 0, 2.15), mats=[leaves], parent=trunk)
    export_gltf(os.path.join(out, "tree.glb"), cameras=False, lights=False)
    return {"street/tree.glb": triangles(trunk.data) + triangles(crown.data)}


def make_house(out):
    reset()
    img = make_image("house bricks", 128, 128, tex_bricks())
    bricks = material("Bricks", base=(1, 1, 1), roughness=0.85, image=img)
    roof = material("RoofTiles", base=(0.35, 0.10, 0.07), roughness=0.7)
    door = material("DoorWood", base=(0.25, 0.14, 0.07), roughness=0.5)
    glass = material("WindowGlass", base=(0.10, 0.14, 0.20), metallic=0.0, roughness=0.05)
    W, D, H, R = 2.0, 1.5, 2.6, 1.3     # half width, half depth, wall height, roof rise
    b = Builder()
    b.box((-W, -D, 0), (W, D, H), mat=0, uv_scale=1.0)       # 1 texture repeat per metre
    for s in (-1, 1):                                          # gable triangles
        x = s * W
        idx = [b.vert((x, -D, H)), b.vert((x, D, H)), b.vert((x, 0, H + R))]
        if s < 0:
            idx = [idx[1], idx[0], idx[2]]
        b.face(idx, [(b.verts[i][1] * s, b.verts[i][2]) for i in idx], 0)
    o = 0.25                                                   # roof overhang
    for s in (-1, 1):                                          # two roof slabs
        t = 0.08
        y0, z0 = s * (D + o), H - R * o / D
        pts = [(-W - o, y0, z0), (W + o, y0, z0), (W + o, 0, H + R), (-W - o, 0, H + R)]
        up = [(x, y, z + t) for x, y, z in pts]
        ring = [b.vert(p) for p in pts] + [b.vert(p) for p in up]
        lo, hi = ring[:4], ring[4:]
        quads = [hi, lo[::-1]] + [[lo[k], lo[(k + 1) % 4], hi[(k + 1) % 4], hi[k]] for k in range(4)]
        for q in quads:
            if s < 0:
                q = q[::-1]
            b.face(q, [(0, 0), (1, 0), (1, 1), (0, 1)], 1)
    b.box((-0.45, -D - 0.04, 0.0), (0.45, -D, 2.0), mat=2)    # door
    for x in (-1.3, 1.3):                                      # front and back windows
        b.box((x - 0.35, -D - 0.03, 1.1), (x + 0.35, -D, 1.9), mat=3)
        b.box((x - 0.35, D, 1.1), (x + 0.35, D + 0.03, 1.9), mat=3)
    for y in (-0.6, 0.6):                                      # side windows
        b.box((W, y - 0.3, 1.1), (W + 0.03, y + 0.3, 1.9), mat=3)
    b.box((0.9, 0.3, H + 0.5), (1.3, 0.7, H + R + 0.6), mat=0, uv_scale=1.0)  # chimney
    house = obj("House", b.mesh("House", auto_smooth=30), mats=[bricks, roof, door, glass])
    export_gltf(os.path.join(out, "house.glb"), cameras=False, lights=False)
    return {"street/house.glb": triangles(house.data)}


# ----------------------------------------------------------------------------- B. tests

CUBE_CELLS = [grid_cell_uv(n) for n in range(6)]   # faces +X -X +Y -Y +Z -Z show 1..6


def cube_scene(tst, with_camera_light=True):
    img = make_image("blender-cube", 128, 128, tex_numbered_grid())
    save_image(img, os.path.join(tst, "blender-cube.png"))
    mat = material("CubeGrid", base=(1, 1, 1), roughness=0.5, image=img)
    b = Builder()
    b.box((-1, -1, -1), (1, 1, 1), cell_uvs=CUBE_CELLS)
    cube = obj("Cube", b.mesh("Cube"), mats=[mat])
    if with_camera_light:
        camera("Camera", (4.0, -5.0, 3.5), (0, 0, 0), lens=35)
        light("PointLight", 'POINT', 1000.0, (3.0, -2.0, 4.0))
    return cube


def make_test_cube(tst):
    reset()
    cube = cube_scene(tst)
    export_gltf(os.path.join(tst, "blender-cube.glb"))
    export_gltf(os.path.join(tst, "blender-cube.gltf"), fmt='GLTF_EMBEDDED')
    bpy.ops.object.select_all(action='DESELECT')
    cube.select_set(True)
    bpy.context.view_layer.objects.active = cube
    obj_path = os.path.join(tst, "blender-cube.obj")
    if hasattr(bpy.ops.wm, "obj_export"):
        bpy.ops.wm.obj_export(filepath=obj_path, export_selected_objects=True, export_uv=True,
                              export_normals=True, export_materials=True,
                              export_triangulated_mesh=False, path_mode='STRIP',
                              forward_axis='NEGATIVE_Z', up_axis='Y')
    else:
        bpy.ops.export_scene.obj(filepath=obj_path, use_selection=True, use_materials=True,
                                 use_triangles=False, path_mode='STRIP')
    # Windows-style copy: MTL pointing at textures\cube tex.png
    with open(obj_path) as f:
        obj_text = f.read()
    with open(os.path.join(tst, "blender-cube.mtl")) as f:
        mtl_text = f.read()
    assert "mtllib blender-cube.mtl" in obj_text and "map_Kd blender-cube.png" in mtl_text
    with open(os.path.join(tst, "blender-cube-winpath.obj"), "w", newline="\n") as f:
        f.write(obj_text.replace("mtllib blender-cube.mtl", "mtllib blender-cube-winpath.mtl"))
    with open(os.path.join(tst, "blender-cube-winpath.mtl"), "w", newline="\n") as f:
        f.write(mtl_text.replace("map_Kd blender-cube.png", "map_Kd textures\\cube tex.png"))
    os.makedirs(os.path.join(tst, "textures"), exist_ok=True)
    shutil.copyfile(os.path.join(tst, "blender-cube.png"), os.path.join(tst, "textures", "cube tex.png"))
    t = triangles(cube.data)
    return {"blender-cube.glb": t, "blender-cube.gltf": t, "blender-cube.obj": t,
            "blender-cube-winpath.obj": t}


def make_test_scene(tst):
    reset()
    cube = cube_scene(tst, with_camera_light=False)
    red = material("RedPaint", base=(0.8, 0.12, 0.08), roughness=0.35)
    b = Builder()
    b.cylinder(0.6, 0.0, 1.4, 24, mat=0)
    cyl = obj("Cylinder", b.mesh("Cylinder", smooth=True, auto_smooth=45), loc=(2.6, 0.4, -1.0),
              mats=[red])
    camera("Camera", (5.0, -6.0, 4.0), (1.2, 0, 0), lens=35)
    light("PointLight", 'POINT', 1000.0, (3.0, -3.0, 5.0))
    bpy.ops.export_scene.fbx(filepath=os.path.join(tst, "blender-scene.fbx"), path_mode='COPY',
                             embed_textures=False, mesh_smooth_type='FACE', bake_anim=False,
                             use_selection=False)
    bpy.ops.wm.collada_export(filepath=os.path.join(tst, "blender-scene.dae"),
                              use_texture_copies=True, selected=False)
    t = triangles(cube.data) + triangles(cyl.data)
    return {"blender-scene.fbx": t, "blender-scene.dae": t}


def make_test_instances(tst):
    reset()
    blue = material("Blue", base=(0.1, 0.25, 0.8), roughness=0.4)
    orange = material("Orange", base=(0.95, 0.45, 0.05), roughness=0.4)
    b = Builder()
    b.box((0.0, -0.15, 0.0), (0.3, 0.15, 1.2), mat=0)   # upright bar
    b.box((0.3, -0.15, 0.0), (0.8, 0.15, 0.3), mat=1)   # foot to +X: the L is chiral
    me = b.mesh("LShape")
    me.materials.append(blue)
    me.materials.append(orange)
    placements = [  # (name, location, rotation degrees, scale)
        ("L.identity", (-3.0, 0, 0), (0, 0, 0), (1, 1, 1)),
        ("L.rotZ90", (-1.5, 0, 0), (0, 0, 90), (1, 1, 1)),
        ("L.half", (0.0, 0, 0.3), (30, 0, 0), (0.5, 0.5, 0.5)),
        ("L.stretched", (1.3, 0, 0), (0, -30, 0), (1.0, 1.0, 1.6)),
        ("L.mirrorX", (3.2, 0, 0), (0, 0, 0), (-1, 1, 1)),
    ]
    for name, loc, rot, sc in placements:
        obj(name, me, loc, rot, sc)
    camera("Camera", (0.0, -8.0, 3.0), (0.0, 0.0, 0.6), lens=35)
    light("Sun", 'SUN', 3.0, (0, -3, 5), target=(0.5, 0, 0))
    export_gltf(os.path.join(tst, "blender-instances.glb"))
    return {"blender-instances.glb": 5 * triangles(me)}


def make_test_ortho(tst):
    reset()
    img = make_image("ortho-grid", 128, 128, tex_numbered_grid())
    mat = material("CubeGrid", base=(1, 1, 1), image=img)
    b = Builder()
    b.box((-1, -1, -1), (1, 1, 1), cell_uvs=CUBE_CELLS)
    cube = obj("Cube", b.mesh("Cube"), mats=[mat])
    camera("OrthoCamera", (6.0, -6.0, 6.0), (0, 0, 0), ortho_scale=5.0)
    light("Sun", 'SUN', 3.0, (2, -1, 4), target=(0, 0, 0))
    export_gltf(os.path.join(tst, "blender-ortho.glb"))
    return {"blender-ortho.glb": triangles(cube.data)}


def make_test_lights(tst):
    reset()
    grey = material("Floor", base=(0.6, 0.6, 0.6), roughness=0.8)
    white = material("Sphere", base=(0.9, 0.9, 0.9), roughness=0.35)
    b = Builder()
    b.box((-4, -4, -0.05), (4, 4, 0.0), mat=0, face_mats=[0] * 6)
    b2 = Builder()
    b2.sphere(1.0, (0, 0, 0), 24, 12)
    floor = obj("Floor", b.mesh("Floor"), mats=[grey])
    ball = obj("Sphere", b2.mesh("Sphere", smooth=True), loc=(0, 0, 1.0), mats=[white])
    light("Point", 'POINT', 500.0, (-3.0, -2.0, 3.0), colour=(1.0, 0.85, 0.7), cutoff=20.0)
    light("Spot", 'SPOT', 1500.0, (3.0, -3.0, 4.0), target=(0, 0, 1.0), colour=(0.7, 0.85, 1.0),
          spot_deg=40, blend=0.25)
    light("Sun", 'SUN', 1.5, (0, 3, 6), target=(-1, 1, 0))
    camera("Camera", (0.0, -7.0, 3.0), (0.0, 0.0, 0.8), lens=35)
    export_gltf(os.path.join(tst, "blender-lights.glb"))
    return {"blender-lights.glb": triangles(floor.data) + triangles(ball.data)}


def make_test_skinned(tst):
    reset()
    skin_mat = material("Skin", base=(0.3, 0.7, 0.4), roughness=0.5)
    b = Builder()
    rings = []
    for k in range(5):
        z = 0.5 * k
        rings.append([b.vert((x, y, z)) for x, y in ((-0.2, -0.2), (0.2, -0.2), (0.2, 0.2), (-0.2, 0.2))])
    for k in range(4):
        a, c = rings[k], rings[k + 1]
        for j in range(4):
            j1 = (j + 1) % 4
            b.face((a[j], a[j1], c[j1], c[j]), [(j / 4, k / 4), ((j + 1) / 4, k / 4),
                                                 ((j + 1) / 4, (k + 1) / 4), (j / 4, (k + 1) / 4)])
    b.face(rings[0][::-1], [(0, 0), (0, 1), (1, 1), (1, 0)])
    b.face(rings[4], [(0, 0), (1, 0), (1, 1), (0, 1)])
    me = b.mesh("Column")

    arm = bpy.data.armatures.new("Rig")
    rig = obj("Rig", arm)
    bpy.context.view_layer.objects.active = rig
    rig.select_set(True)
    bpy.ops.object.mode_set(mode='EDIT')
    lower = arm.edit_bones.new("Lower")
    lower.head, lower.tail = (0, 0, 0), (0, 0, 1)
    upper = arm.edit_bones.new("Upper")
    upper.head, upper.tail = (0, 0, 1), (0, 0, 2)
    upper.parent = lower
    upper.use_connect = True
    bpy.ops.object.mode_set(mode='OBJECT')

    col = obj("Column", me, mats=[skin_mat], parent=rig)
    g_lo, g_up = col.vertex_groups.new(name="Lower"), col.vertex_groups.new(name="Upper")
    for v in me.vertices:
        w = min(max((v.co.z - 0.5) / 1.0, 0.0), 1.0)
        if w < 1:
            g_lo.add([v.index], 1 - w, 'REPLACE')
        if w > 0:
            g_up.add([v.index], w, 'REPLACE')
    mod = col.modifiers.new("Armature", 'ARMATURE')
    mod.object = rig
    col.shape_key_add(name="Basis")
    bulge = col.shape_key_add(name="Bulge", from_mix=False)
    for v in me.vertices:
        if abs(v.co.z - 1.0) < 1e-6:
            bulge.data[v.index].co = (v.co.x * 1.8, v.co.y * 1.8, v.co.z)
    bulge.value = 0.5

    pb = rig.pose.bones["Upper"]
    pb.rotation_mode = 'QUATERNION'
    pb.rotation_quaternion = (1, 0, 0, 0)
    pb.keyframe_insert("rotation_quaternion", frame=1)
    pb.rotation_quaternion = (math.cos(math.radians(20)), math.sin(math.radians(20)), 0, 0)
    pb.keyframe_insert("rotation_quaternion", frame=24)
    bpy.context.scene.frame_set(1)

    camera("Camera", (3.0, -5.0, 2.5), (0, 0, 1.0), lens=35)
    light("PointLight", 'POINT', 800.0, (2.0, -3.0, 4.0))
    export_gltf(os.path.join(tst, "blender-skinned.glb"), animations=True)
    return {"blender-skinned.glb": triangles(me)}


# ----------------------------------------------------------------------------- verification

def read_gltf(path):
    with open(path, "rb") as f:
        data = f.read()
    if path.endswith(".glb"):
        magic, version, length = struct.unpack_from("<III", data, 0)
        assert magic == 0x46546C67 and version == 2 and length == len(data), path
        clen, ctype = struct.unpack_from("<II", data, 12)
        assert ctype == 0x4E4F534A, path
        doc = json.loads(data[20:20 + clen].decode("utf-8"))
        if 20 + clen < length:
            blen, btype = struct.unpack_from("<II", data, 20 + clen)
            assert btype == 0x004E4942, path
    else:
        doc = json.loads(data.decode("utf-8"))
    return doc


def mesh_triangles(doc, m):
    t = 0
    for p in doc["meshes"][m]["primitives"]:
        assert p.get("mode", 4) == 4
        t += doc["accessors"][p["indices"]]["count"] // 3
    return t


def summarise(path, label):
    doc = read_gltf(path)
    nodes = doc.get("nodes", [])
    lights = doc.get("extensions", {}).get("KHR_lights_punctual", {}).get("lights", [])
    unique = sum(mesh_triangles(doc, m) for m in range(len(doc.get("meshes", []))))
    drawn = sum(mesh_triangles(doc, n["mesh"]) for n in nodes if "mesh" in n)
    if path.endswith(".gltf"):
        base = os.path.dirname(path)
        from urllib.parse import unquote
        for item in doc.get("buffers", []) + doc.get("images", []):
            uri = item.get("uri")
            if uri and not uri.startswith("data:"):
                assert os.path.exists(os.path.join(base, unquote(uri))), uri
    print("VERIFY %-28s %7d B  nodes=%d meshes=%d prims=%d materials=%d textures=%d images=%d "
          "lights=%d cameras=%d skins=%d animations=%d tris(unique)=%d tris(drawn)=%d ext=%s" % (
              label, os.path.getsize(path), len(nodes), len(doc.get("meshes", [])),
              sum(len(m["primitives"]) for m in doc.get("meshes", [])),
              len(doc.get("materials", [])), len(doc.get("textures", [])),
              len(doc.get("images", [])), len(lights), len(doc.get("cameras", [])),
              len(doc.get("skins", [])), len(doc.get("animations", [])), unique, drawn,
              ",".join(doc.get("extensionsUsed", []))))


def main():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    if len(argv) != 1:
        raise SystemExit("usage: blender -b --factory-startup --python scripts/make-models.py -- OUTROOT")
    root = os.path.abspath(argv[0])
    scn = os.path.join(root, "scenes", "models")
    street = os.path.join(scn, "street")
    tst = os.path.join(root, "tests", "models")
    for d in (scn, street, tst):
        os.makedirs(d, exist_ok=True)

    tris = {}
    tris.update(make_crate(scn))
    tris.update(make_pawns(scn))
    tris.update(make_lamp(street))
    tris.update(make_bench(street))
    tris.update(make_tree(street))
    tris.update(make_house(street))
    tris.update(make_test_cube(tst))
    tris.update(make_test_scene(tst))
    tris.update(make_test_instances(tst))
    tris.update(make_test_ortho(tst))
    tris.update(make_test_lights(tst))
    tris.update(make_test_skinned(tst))

    for name, t in tris.items():
        base = tst if name.startswith("blender-") else scn
        path = os.path.join(base, name)
        print("TRIS %-28s blender-side triangles=%d" % (name, t))
        if name.endswith((".glb", ".gltf")):
            summarise(path, name)
    for mtl in ("blender-cube.mtl", "blender-cube-winpath.mtl"):
        with open(os.path.join(tst, mtl)) as f:
            lines = [l.strip() for l in f if l.startswith("map_Kd")]
        assert lines, mtl
        print("VERIFY %-28s %s" % (mtl, lines))


if __name__ == "__main__":  # scripts/make-path-scenes.py imports the helpers
    main()
