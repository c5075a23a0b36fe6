"""Renders a glTF 2.0 file with Blender's Cycles, unbiased and comparable with PRT, into a
linear float image (PFM). Runs inside Blender (3.4, from Debian 12):

    blender -b --factory-startup --python bench/cycles/render_cycles.py -- \
        MODEL.glb -o OUT.pfm [--width 160 --height 120] [--samples 512] [--threads 2]
        [--seed 0] [--bounces 12] [--world 0.05] [--camera NAME]

The file is imported by Blender's own glTF importer (its default "Standard" lighting units)
into an empty scene and rendered on the CPU through the file's first camera (depth first over
the default scene's nodes, as PRT picks it) or the one named by --camera. What is set, and
why (docs/benchmarks.md, "PRT against Cycles"):

  - sample clamping off (direct and indirect 0) and filter glossy 0: Cycles 3.4's defaults
    clamp indirect samples at 10 and blur glossy paths, both biased;
  - caustics on (reflective and refractive); adaptive sampling, the denoiser and the light
    sampling threshold (light_sampling_threshold 0) off; seed fixed;
  - at most --bounces bounces in all and of each kind (diffuse, glossy, transmission,
    volume, transparent);
  - every light punctual: point and spot radius 0, sun angle 0 (glTF's lights are points and
    directions; the importer gives them Blender's 0.25 m and sun angle);
  - the pixel filter a box of one pixel (each pixel the mean over its own area);
  - a world of uniform grey --world (0.05: what PRT gives a model file without an
    environment), strength 1;
  - KHR_materials_volume's absorption and KHR_materials_clearcoat's layer as glTF defines
    them (volumes_as_gltf, clearcoats_as_gltf: the importer maps them onto other models);
  - view transform Standard, look None, exposure 0, gamma 1, film exposure 1: the file holds
    the linear render itself, written by way of a 32-bit OpenEXR and read back.

Prints one line "CYCLES_RESULT {json}" with the settings and the time of
bpy.ops.render.render alone (Blender's start-up, the import and the writing excluded).
Exits non-zero with a message on bad input; the output is written whole or not at all.
"""
import json
import math
import os
import struct
import sys
import tempfile
import time

import numpy as np

# Debian 12's NumPy removed np.bool, which Blender 3.4's glTF add-on still calls.
if "bool" not in vars(np):
    np.bool = bool

import bpy  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import compare  # noqa: E402  (the atomic write; standard library only)


def fail(message):
    print("render_cycles: " + message, file=sys.stderr)
    sys.stdout.flush()
    sys.stderr.flush()
    os._exit(2)  # Blender would turn a Python exception into exit code 0


def parse_args(argv):
    import argparse
    p = argparse.ArgumentParser(prog="render_cycles.py",
                                description="Render a glTF file with Cycles into a PFM")
    p.add_argument("model")
    p.add_argument("-o", "--output", required=True, help="a .pfm file")
    p.add_argument("--width", type=int, default=160)
    p.add_argument("--height", type=int, default=120)
    p.add_argument("--samples", type=int, default=512)
    p.add_argument("--threads", type=int, default=2)
    p.add_argument("--seed", type=int, default=0)
    p.add_argument("--bounces", type=int, default=12)
    p.add_argument("--world", type=float, default=0.05)
    p.add_argument("--camera", default=None)
    a = p.parse_args(argv)
    if not a.output.lower().endswith(".pfm"):
        fail("the output must be a .pfm file: " + a.output)
    for name in ("width", "height", "samples", "threads"):
        if not 1 <= getattr(a, name) <= 1 << 16:
            fail("--%s must be in [1, 65536]" % name)
    if not 0 <= a.bounces <= 1024:
        fail("--bounces must be in [0, 1024]")
    return a


def read_gltf_json(path):
    with open(path, "rb") as f:
        data = f.read()
    if data[:4] == b"glTF":
        if len(data) < 20:
            fail("'%s': truncated GLB header" % path)
        length, kind = struct.unpack_from("<II", data, 12)
        if kind != 0x4E4F534A or 20 + length > len(data):
            fail("'%s': no JSON chunk" % path)
        data = data[20:20 + length]
    try:
        return json.loads(data.decode("utf-8"))
    except (UnicodeDecodeError, ValueError) as e:
        fail("'%s' is not a glTF file: %s" % (path, e))


def first_camera_name(doc):
    """The glTF name of the first camera met depth first over the default scene's nodes."""
    nodes = doc.get("nodes", [])
    scenes = doc.get("scenes", [])
    roots = scenes[doc.get("scene", 0)].get("nodes", []) if scenes else range(len(nodes))
    stack = list(reversed(list(roots)))
    while stack:
        i = stack.pop()
        node = nodes[i]
        if "camera" in node:
            return doc["cameras"][node["camera"]].get("name") or node.get("name")
        stack.extend(reversed(node.get("children", [])))
    return None


def choose_camera(doc, wanted):
    cameras = [o for o in bpy.context.scene.objects if o.type == 'CAMERA']
    if not cameras:
        fail("the file has no camera to render through")
    name = wanted if wanted is not None else first_camera_name(doc)
    for o in cameras:  # the importer names the camera data after the glTF camera
        if name is not None and (o.data.name == name or o.name == name):
            return o
    if wanted is not None:
        fail("no camera named %r (the file has %s)" % (wanted, [o.data.name for o in cameras]))
    return sorted(cameras, key=lambda o: o.name)[0]


def configure(scene, a):
    scene.render.engine = 'CYCLES'
    cy = scene.cycles
    cy.device = 'CPU'
    cy.samples = a.samples
    cy.use_adaptive_sampling = False
    cy.use_denoising = False
    cy.seed = a.seed
    cy.use_animated_seed = False
    cy.sample_clamp_direct = 0.0
    cy.sample_clamp_indirect = 0.0
    cy.blur_glossy = 0.0
    cy.caustics_reflective = True
    cy.caustics_refractive = True
    cy.max_bounces = a.bounces
    cy.diffuse_bounces = a.bounces
    cy.glossy_bounces = a.bounces
    cy.transmission_bounces = a.bounces
    cy.volume_bounces = a.bounces
    cy.transparent_max_bounces = a.bounces
    cy.min_light_bounces = 0
    cy.min_transparent_bounces = 0
    cy.light_sampling_threshold = 0.0
    cy.pixel_filter_type = 'BOX'
    cy.filter_width = 1.0
    cy.film_exposure = 1.0
    cy.time_limit = 0.0
    scene.render.film_transparent = False
    scene.render.use_persistent_data = False
    scene.render.resolution_x = a.width
    scene.render.resolution_y = a.height
    scene.render.resolution_percentage = 100
    scene.render.pixel_aspect_x = scene.render.pixel_aspect_y = 1.0
    scene.render.threads_mode = 'FIXED'
    scene.render.threads = a.threads
    scene.render.use_compositing = False
    scene.render.use_sequencer = False
    scene.display_settings.display_device = 'sRGB'
    scene.view_settings.view_transform = 'Standard'
    scene.view_settings.look = 'None'
    scene.view_settings.exposure = 0.0
    scene.view_settings.gamma = 1.0
    scene.view_settings.use_curve_mapping = False
    settings = scene.render.image_settings
    settings.file_format = 'OPEN_EXR'
    settings.color_depth = '32'
    settings.color_mode = 'RGBA'
    settings.exr_codec = 'ZIP'

    world = bpy.data.worlds.new("PRT grey")
    world.use_nodes = True
    background = world.node_tree.nodes["Background"]
    background.inputs["Color"].default_value = (a.world, a.world, a.world, 1.0)
    background.inputs["Strength"].default_value = 1.0
    scene.world = world

    lights = []
    for o in scene.objects:
        if o.type != 'LIGHT':
            continue
        light = o.data
        light.shadow_soft_size = 0.0  # point and spot radius (sun: angle below)
        if light.type == 'SUN':
            light.angle = 0.0
        lights.append({"name": o.name, "type": light.type, "watts": light.energy,
                       "color": list(light.color)})
    return lights


def volumes_as_gltf(doc):
    """KHR_materials_volume as glTF defines it. Blender's importer gives a Volume Absorption
    node colour c = attenuationColor and density 1 / attenuationDistance, which Cycles reads
    as the absorption coefficient sigma = (1 - c) density; glTF's is sigma = -ln(c) / d
    (Beer-Lambert: c is what is left after d). Each such node is set to the same sigma per
    channel: density max(-ln c) / d and colour 1 - (-ln c) / (d density). Returns the
    materials changed."""
    changed = []
    for m in doc.get("materials", []):
        v = m.get("extensions", {}).get("KHR_materials_volume")
        if v is None or not v.get("thicknessFactor", 0) > 0 or "attenuationDistance" not in v:
            continue
        material = bpy.data.materials.get(m.get("name", ""))
        if material is None or not material.use_nodes:
            continue
        nodes = [n for n in material.node_tree.nodes if n.type == 'VOLUME_ABSORPTION']
        if not nodes:
            continue
        d = float(v["attenuationDistance"])
        sigma = [-math.log(max(c, 1e-30)) / d for c in v.get("attenuationColor", [1, 1, 1])]
        density = max(sigma)
        colour = [1 - s / density if density > 0 else 1.0 for s in sigma]
        for n in nodes:
            n.inputs["Color"].default_value = (*colour, 1.0)
            n.inputs["Density"].default_value = density
        changed.append(m.get("name", ""))
    return changed


def clearcoats_as_gltf(doc):
    """KHR_materials_clearcoat as glTF defines it: the base attenuated by 1 - clearcoat Fc and
    a GGX reflection of the coat's roughness, with no Fresnel factor of its own, weighted by
    clearcoat Fc, where Fc = 0.04 + 0.96 (1 - |N.V|)^5. Blender's importer gives the factor to
    the Principled BSDF's Clearcoat, Disney's coat (a GTR1 lobe at a quarter of the weight,
    the base not attenuated), another model. Each such material's Principled Clearcoat is
    set to 0 and its output mixed with a Glossy BSDF (GGX) by a Mix Shader whose factor is
    clearcoat Fc, computed from a Layer Weight node's Facing (1 - |N.V| at blend 0.5).
    Returns the materials changed."""
    changed = []
    for m in doc.get("materials", []):
        c = m.get("extensions", {}).get("KHR_materials_clearcoat")
        if c is None or not c.get("clearcoatFactor", 0) > 0:
            continue
        material = bpy.data.materials.get(m.get("name", ""))
        if material is None or not material.use_nodes:
            continue
        nt = material.node_tree
        principled = [n for n in nt.nodes if n.type == 'BSDF_PRINCIPLED']
        outputs = [n for n in nt.nodes if n.type == 'OUTPUT_MATERIAL']
        if len(principled) != 1 or not outputs:
            fail("material %r: no single Principled BSDF to coat" % m.get("name"))
        bsdf, output = principled[0], outputs[0]
        bsdf.inputs["Clearcoat"].default_value = 0.0
        glossy = nt.nodes.new("ShaderNodeBsdfGlossy")
        glossy.distribution = 'GGX'
        glossy.inputs["Color"].default_value = (1.0, 1.0, 1.0, 1.0)
        glossy.inputs["Roughness"].default_value = float(c.get("clearcoatRoughnessFactor", 0))
        layer = nt.nodes.new("ShaderNodeLayerWeight")
        layer.inputs["Blend"].default_value = 0.5
        value = layer.outputs["Facing"]
        for operation, operand in (('POWER', 5.0), ('MULTIPLY', 0.96), ('ADD', 0.04),
                                   ('MULTIPLY', float(c["clearcoatFactor"]))):
            node = nt.nodes.new("ShaderNodeMath")
            node.operation = operation
            nt.links.new(value, node.inputs[0])
            node.inputs[1].default_value = operand
            value = node.outputs[0]
        mix = nt.nodes.new("ShaderNodeMixShader")
        nt.links.new(value, mix.inputs["Fac"])
        nt.links.new(bsdf.outputs["BSDF"], mix.inputs[1])
        nt.links.new(glossy.outputs["BSDF"], mix.inputs[2])
        nt.links.new(mix.outputs["Shader"], output.inputs["Surface"])
        changed.append(m.get("name", ""))
    return changed


def write_pfm(path, pixels, width, height):
    """pixels: Blender's RGBA floats, bottom row first, which is PFM's order too."""
    rgb = pixels.reshape(height, width, 4)[:, :, :3].astype("<f4")
    compare.atomic_write(path, b"PF\n%d %d\n-1.0\n" % (width, height) + rgb.tobytes())


def main():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    a = parse_args(argv)
    if not os.path.isfile(a.model):
        fail("model file '%s' does not exist" % a.model)
    doc = read_gltf_json(a.model)

    bpy.ops.wm.read_factory_settings(use_empty=True)
    try:
        result = bpy.ops.import_scene.gltf(filepath=os.path.abspath(a.model))
    except RuntimeError as e:
        fail("Blender could not import '%s': %s" % (a.model, e))
    if 'FINISHED' not in result:
        fail("Blender could not import '%s'" % a.model)
    scene = bpy.context.scene
    camera = choose_camera(doc, a.camera)
    scene.camera = camera
    lights = configure(scene, a)
    volumes = volumes_as_gltf(doc)
    clearcoats = clearcoats_as_gltf(doc)

    start = time.perf_counter()
    bpy.ops.render.render(write_still=False)
    seconds = time.perf_counter() - start

    with tempfile.TemporaryDirectory(prefix="render_cycles.") as tmp:
        exr = os.path.join(tmp, "render.exr")
        bpy.data.images["Render Result"].save_render(filepath=exr, scene=scene)
        image = bpy.data.images.load(exr)
        if tuple(image.size) != (a.width, a.height) or image.channels != 4:
            fail("the saved render has size %s and %d channels" % (tuple(image.size), image.channels))
        pixels = np.empty(a.width * a.height * 4, dtype=np.float32)
        image.pixels.foreach_get(pixels)
        bpy.data.images.remove(image)
    write_pfm(a.output, pixels, a.width, a.height)

    cy = scene.cycles
    report = {
        "model": a.model, "output": a.output, "camera": camera.data.name,
        "width": a.width, "height": a.height, "samples": a.samples, "threads": a.threads,
        "render_seconds": round(seconds, 3),
        "blender": bpy.app.version_string,
        "settings": {
            "seed": cy.seed, "sampling_pattern": cy.sampling_pattern,
            "max_bounces": cy.max_bounces, "diffuse_bounces": cy.diffuse_bounces,
            "glossy_bounces": cy.glossy_bounces,
            "transmission_bounces": cy.transmission_bounces,
            "volume_bounces": cy.volume_bounces,
            "transparent_max_bounces": cy.transparent_max_bounces,
            "sample_clamp_direct": cy.sample_clamp_direct,
            "sample_clamp_indirect": cy.sample_clamp_indirect,
            "blur_glossy": cy.blur_glossy, "caustics_reflective": cy.caustics_reflective,
            "caustics_refractive": cy.caustics_refractive,
            "light_sampling_threshold": cy.light_sampling_threshold,
            "adaptive_sampling": cy.use_adaptive_sampling, "denoising": cy.use_denoising,
            "pixel_filter": cy.pixel_filter_type, "filter_width": cy.filter_width,
            "world": a.world, "view_transform": scene.view_settings.view_transform,
        },
        "lights": lights,
    }
    if volumes:
        report["volumes_as_gltf"] = volumes
    if clearcoats:
        report["clearcoats_as_gltf"] = clearcoats
    print("CYCLES_RESULT " + json.dumps(report, sort_keys=True))
    sys.stdout.flush()


try:
    main()
except SystemExit as e:  # argparse's usage errors: keep their code
    sys.stdout.flush()
    sys.stderr.flush()
    os._exit(e.code if isinstance(e.code, int) else 2)
except Exception as e:  # noqa: BLE001 - anything else is a failure, never exit code 0
    import traceback
    traceback.print_exc()
    fail("%s: %s" % (type(e).__name__, e))
