"""The scene, written for prt by Blender's own glTF exporter (io_scene_gltf2)."""
import contextlib
import io
import os
import threading
import time

import bpy

from . import commands


def _numpy_bool_workaround():
    """Blender 3.4's glTF exporter calls np.bool, which NumPy 1.24 removed (Debian 12's
    Blender uses the system's NumPy). Set it only where it is missing, so that a Blender that
    ships its own, older NumPy is left as it is."""
    try:
        import numpy as np
    except ImportError:
        return
    if "bool" not in vars(np):
        np.bool = bool


def camera_name(scene):
    """The glTF name of the scene's camera (the exporter names a glTF camera after the camera
    data), for prt's --camera; empty when the scene has none."""
    return scene.camera.data.name if scene.camera is not None else ""


def export_gltf(scene, path, animation):
    """Writes SCENE to PATH (.glb) with its cameras, lights, materials and textures, modifiers
    applied; ANIMATION: with the frame range's animation sampled at every frame (the exporter
    writes frame N at N / fps seconds), else as it is at the current frame. Returns the
    exporter's warning lines. Raises RuntimeError with the exporter's message on failure."""
    _numpy_bool_workaround()
    if not hasattr(bpy.ops.export_scene, "gltf"):
        import addon_utils
        addon_utils.enable("io_scene_gltf2", default_set=True)
    out = io.StringIO()
    window = bpy.context.window_manager.windows[0] if bpy.context.window_manager and \
        bpy.context.window_manager.windows else None
    override = {"scene": scene}
    if window is not None:
        override["window"] = window
    with contextlib.redirect_stdout(out):
        try:
            with bpy.context.temp_override(**override):
                result = bpy.ops.export_scene.gltf(
                    filepath=path, export_format='GLB', use_active_scene=True,
                    use_renderable=True, export_cameras=True, export_lights=True,
                    export_apply=True, export_materials='EXPORT', export_image_format='AUTO',
                    export_animations=animation, export_frame_range=True,
                    export_force_sampling=True, export_frame_step=1,
                    export_current_frame=not animation, export_nla_strips=False,
                    export_extras=False, will_save_settings=False)
        except Exception as e:  # the exporter's own errors arrive as RuntimeError
            raise RuntimeError("the glTF export failed: %s" % str(e).strip()) from None
    if 'FINISHED' not in result or not os.path.isfile(path):
        raise RuntimeError("the glTF export wrote nothing (%s)" % ", ".join(sorted(result)))
    return [l for l in out.getvalue().splitlines() if commands.is_warning(l)]


def unexported_warnings(scene):
    """What the glTF exporter leaves out of SCENE without a word, named here instead."""
    warnings = []
    world = scene.world
    if world is not None:
        colour = None
        if world.use_nodes and world.node_tree is not None:
            background = world.node_tree.nodes.get("Background")
            if background is not None:
                if background.inputs["Color"].is_linked:
                    warnings.append("the world's node setup is not exported: PRT lights the "
                                    "scene with its own grey world (0.05)")
                else:
                    c = background.inputs["Color"].default_value
                    s = background.inputs["Strength"].default_value
                    colour = (c[0] * s, c[1] * s, c[2] * s)
        else:
            colour = tuple(world.color)
        if colour is not None and max(abs(v - 0.05) for v in colour) > 0.002:
            warnings.append("the world colour (%.3g, %.3g, %.3g) is not exported: PRT lights "
                            "the scene with its own grey world (0.05)" % colour)
    for o in scene.objects:
        if o.hide_render:
            continue
        if o.type == 'VOLUME' or any(m.type == 'PARTICLE_SYSTEM' for m in getattr(o, "modifiers", [])):
            warnings.append("object '%s': volumes, hair and particles are not exported" % o.name)
        elif o.type in ('CURVE', 'FONT', 'SURFACE', 'META'):
            pass  # the exporter turns these into meshes
        elif o.type == 'MESH':
            for slot in o.material_slots:
                m = slot.material
                if m is not None and m.use_nodes and m.node_tree is not None and any(
                        n.type in ('VOLUME_PRINCIPLED', 'VOLUME_ABSORPTION', 'VOLUME_SCATTER')
                        for n in m.node_tree.nodes):
                    warnings.append("material '%s': its volume shader is not exported" % m.name)
    if scene.camera is None:
        warnings.append("the scene has no camera: PRT frames the scene with a camera of its own")
    return warnings


class NotOnMainThread(RuntimeError):
    pass


def on_main_thread(function, should_stop, timeout=300.0):
    """FUNCTION() run on Blender's main thread, its result returned (its exception raised).

    F12 in Blender's window renders on a job thread, where an operator (the glTF exporter)
    must not run: it evaluates and changes the scene, which the main thread owns (Blender
    3.4 crashes in the exporter's first import). From there the call is handed to the main
    thread with a timer, while the render thread waits; a render in the foreground (blender
    -b, bpy.ops.render.render() from a script) is on the main thread already and calls it
    directly. SHOULD_STOP() (Esc) ends the wait; the main thread then finishes the call
    alone. Raises NotOnMainThread when the main thread did not take the call within TIMEOUT
    seconds."""
    if threading.current_thread() is threading.main_thread():
        return function()
    outcome = {}
    finished = threading.Event()

    def call():
        outcome["started"] = True
        try:
            outcome["value"] = function()
        except BaseException as e:  # handed to the waiting render thread
            outcome["error"] = e
        finished.set()
        return None  # once

    bpy.app.timers.register(call, first_interval=0.0)
    deadline = time.monotonic() + timeout
    while not finished.wait(0.1):
        if should_stop():
            return None
        if time.monotonic() > deadline and "started" not in outcome:
            raise NotOnMainThread("Blender's main thread did not take the export within %d s "
                                  "(is Render > Lock Interface on?)" % timeout)
    if "error" in outcome:
        raise outcome["error"]
    return outcome.get("value")
