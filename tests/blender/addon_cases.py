"""The PRT add-on inside Blender, one case per run (tests/blender/addon_test.py starts it):

    blender -b --factory-startup --python addon_cases.py -- --case CASE --zip ZIP --prt PRT
            --out DIR

Cases: install (from the zip into BLENDER_USER_SCRIPTS, enabled, registered, disabled and
enabled again), still (F12 equals `prt render` of the same exported glTF), animation (two
frames as one job, each equal to the frame rendered on its own), cancel (Esc: the engine's
break check, forced by PRT_BLENDER_TEST_BREAK_AFTER_POLLS), missing-prt and failed-prt (a
clear error, no traceback). Prints "PASS ..." or "FAIL: ..." and exits 0 or 1.
"""
import argparse
import os
import subprocess
import sys
import tempfile
import threading
import time

import numpy as np

import bpy
import addon_utils


def fail(message):
    print("FAIL: " + message)
    sys.stdout.flush()
    os._exit(1)


def done(message):
    print("PASS " + message)
    sys.stdout.flush()
    os._exit(0)


def install(zip_path):
    bpy.ops.preferences.addon_install(filepath=zip_path, overwrite=True)
    installed = os.path.join(bpy.utils.user_resource('SCRIPTS', path="addons"), "prt_render")
    if not os.path.isfile(os.path.join(installed, "__init__.py")):
        fail("the zip did not install into %s" % installed)
    addon_utils.enable("prt_render", default_set=True, handle_error=lambda e: fail(repr(e)))
    if "PRT" not in {e.bl_idname for e in bpy.types.RenderEngine.__subclasses__()}:
        fail("no render engine PRT after enabling the add-on")
    if not hasattr(bpy.types.Scene, "prt"):
        fail("scene.prt is not registered")
    return installed


def make_scene(width, height, samples, prt):
    """A cube, a light and a camera, made here (not the factory scene's)."""
    scene = bpy.context.scene
    for o in list(bpy.data.objects):  # the factory scene's cube, light and camera go
        bpy.data.objects.remove(o)
    bpy.ops.mesh.primitive_cube_add(size=2, location=(0, 0, 0))
    cube = bpy.context.active_object
    material = bpy.data.materials.new("Orange")
    material.use_nodes = True
    material.node_tree.nodes["Principled BSDF"].inputs["Base Color"].default_value = (
        0.8, 0.3, 0.1, 1)
    cube.data.materials.append(material)
    bpy.ops.object.light_add(type='POINT', location=(4, -3, 5))
    bpy.context.active_object.data.energy = 1000
    bpy.ops.object.camera_add(location=(6, -6, 4.5), rotation=(1.1, 0, 0.785))
    scene.camera = bpy.context.active_object
    scene.render.resolution_x, scene.render.resolution_y = width, height
    scene.render.resolution_percentage = 100
    scene.render.engine = 'PRT'
    scene.prt.prt_path = prt
    scene.prt.samples = samples
    # What Blender shows and saves as 8-bit is prt's own sRGB encoding only with the Standard
    # view transform (3.4's default is Filmic) and no dither (3.4 adds noise of 1/255 by
    # default when it writes 8-bit files).
    scene.view_settings.view_transform = 'Standard'
    scene.view_settings.look = 'None'
    scene.view_settings.exposure = 0
    scene.view_settings.gamma = 1
    scene.render.dither_intensity = 0
    return scene, cube


def save_render(path, fmt):
    scene = bpy.context.scene
    settings = scene.render.image_settings
    settings.file_format = fmt
    if fmt == 'OPEN_EXR':
        settings.color_depth = '32'
        settings.exr_codec = 'ZIP'
        settings.color_mode = 'RGB'
    else:
        settings.color_depth = '8'
        settings.color_mode = 'RGB'
    bpy.data.images['Render Result'].save_render(filepath=path, scene=scene)


def load_pixels(path):
    image = bpy.data.images.load(path)
    pixels = np.empty(image.size[0] * image.size[1] * image.channels, dtype=np.float32)
    image.pixels.foreach_get(pixels)
    size = tuple(image.size)
    channels = image.channels
    bpy.data.images.remove(image)
    return pixels.reshape(size[1], size[0], channels)[:, :, :3], size


def read_pfm(path):
    """prt's PFM as linear RGB rows, bottom first (Blender's order), read here rather than
    by the add-on's reader, which is under test."""
    with open(path, "rb") as f:
        data = f.read()
    magic, size, scale, pixels = data.split(b"\n", 3)
    width, height = (int(v) for v in size.split())
    if magic != b"PF" or float(scale) >= 0:
        fail("%s: not a little-endian colour PFM" % path)
    return np.frombuffer(pixels, dtype="<f4", count=width * height * 3).reshape(height, width, 3)


def prt_render_of(scene, out_dir, outputs):
    """`prt render` of the glTF the add-on exports, with the flags the engine gives it (less
    the live page), once for each of OUTPUTS. Returns the last command line."""
    from prt_render import commands, engine, export
    glb = os.path.join(out_dir, "scene.glb")
    export.export_gltf(scene, glb, animation=False)
    for output in outputs:
        job = engine.make_job(scene, out_dir, output, None)
        job.serve = ""
        argv = [job.prt, "render", glb] + commands.render_args(job)
        run = subprocess.run(argv, capture_output=True, text=True)
        if run.returncode != 0:
            fail("%s: %s" % (" ".join(argv), run.stderr))
    return argv


def case_install(a):
    installed = install(a.zip)
    addon_utils.disable("prt_render", default_set=True)
    if hasattr(bpy.types.Scene, "prt"):
        fail("scene.prt is still registered after the add-on was disabled")
    addon_utils.enable("prt_render", default_set=True, handle_error=lambda e: fail(repr(e)))
    if not hasattr(bpy.types, "RENDER_PT_prt_sampling"):
        fail("the PRT panel is not registered")
    done("installed into %s, registered, disabled and enabled again" % installed)


def case_elsewhere(a):
    """MPI hosts or a Slurm cluster (the driver brings up the hosts and passes their
    settings): the same pixels as `prt render` on this machine, bit for bit."""
    install(a.zip)
    scene, _ = make_scene(64, 48, 8, a.prt)
    s = scene.prt
    joiner = {}
    if a.case == "mpi":
        s.where, s.hostfile, s.workers, s.mpirun = 'MPI', a.hostfile, 2, a.mpirun
    elif a.case == "joinable":
        # One local worker; another machine (here a second prt) joins with the invitation the
        # render writes in its folder, as the info area tells a user to.
        s.where, s.workers = 'JOINABLE', 1
        scene.prt.samples = 4096  # about 2 s: time for the joiner to arrive

        def join():
            import glob
            deadline = time.monotonic() + 30
            while time.monotonic() < deadline:
                found = glob.glob(os.path.join(tempfile.gettempdir(), "prt-blender-*",
                                               "invitation"))
                if found:
                    joiner["run"] = subprocess.run([a.prt, "join", found[0]],
                                                   capture_output=True, text=True, timeout=60)
                    return
                time.sleep(0.02)
        thread = threading.Thread(target=join, daemon=True)
        thread.start()
    else:
        s.where, s.submit_folder, s.nodes, s.sbatch_script = 'SLURM', a.out, 2, a.sbatch_script
    started = time.monotonic()
    try:
        bpy.ops.render.render()
    except RuntimeError as e:
        fail("the render failed: %s" % e)
    seconds = time.monotonic() - started
    if a.case == "joinable":
        thread.join(60)
        run = joiner.get("run")
        if run is None or run.returncode != 0:
            fail("the joining prt did not end well: %s" % (run and run.stderr))
        print("the joiner said: " + (run.stdout + run.stderr).strip().replace("\n", " | "))
    exr = os.path.join(a.out, "engine.exr")
    save_render(exr, 'OPEN_EXR')
    s.where = 'LOCAL'
    argv = prt_render_of(scene, a.out, [os.path.join(a.out, "prt.pfm")])
    engine_linear, _ = load_pixels(exr)
    if not np.array_equal(engine_linear, read_pfm(os.path.join(a.out, "prt.pfm"))):
        fail("the render result differs from prt's pixels")
    done("%s, 64x48, %d spp in %.2f s: pixels bit-identical to `%s`" % (a.case, s.samples, seconds,
                                                                      " ".join(argv)))


def case_still(a):
    install(a.zip)
    scene, _ = make_scene(64, 48, 8, a.prt)
    # A world PRT does not take (the glTF exporter drops it): a warning, the pixels unchanged.
    scene.world = bpy.data.worlds.new("Grey")
    scene.world.color = (0.2, 0.2, 0.2)
    # An area light, which the exporter drops with a warning of its own.
    bpy.ops.object.light_add(type='AREA', location=(0, 0, 6))
    started = time.monotonic()
    bpy.ops.render.render()
    seconds = time.monotonic() - started
    exr = os.path.join(a.out, "engine.exr")
    png = os.path.join(a.out, "engine.png")
    save_render(exr, 'OPEN_EXR')
    save_render(png, 'PNG')
    argv = prt_render_of(scene, a.out, [os.path.join(a.out, "prt.pfm"),
                                        os.path.join(a.out, "prt.png")])
    engine_linear, size = load_pixels(exr)
    prt_linear = read_pfm(os.path.join(a.out, "prt.pfm"))
    if size != (64, 48):
        fail("the render result is %dx%d, not 64x48" % size)
    if float(prt_linear.max()) <= 0.0:
        fail("prt rendered a black image")
    # The render result holds prt's float pixels; Blender writes them to a float EXR as they
    # are (no view transform for a linear format): bit for bit.
    if not np.array_equal(engine_linear, prt_linear):
        d = np.abs(engine_linear - prt_linear)
        fail("the render result's linear pixels differ from prt's (max %g at %s)"
             % (d.max(), np.unravel_index(d.argmax(), d.shape)))
    # 8-bit: Blender's sRGB view transform (OpenColorIO's, Standard) against prt's own sRGB
    # encoding of the same floats: each rounds the same value, through a different curve
    # evaluation, so a channel may land on the neighbouring code.
    engine_srgb, _ = load_pixels(png)
    prt_srgb, _ = load_pixels(os.path.join(a.out, "prt.png"))
    step = np.abs(np.rint(engine_srgb * 255) - np.rint(prt_srgb * 255))
    if step.max() > 1:
        fail("the render result saved as PNG differs from prt's PNG by %d/255" % step.max())
    done("64x48, 8 spp in %.2f s: linear pixels bit-identical to `%s`; PNG within %d/255 "
         "(%d of %d channels differ)" % (seconds, " ".join(argv), step.max(),
                                         int((step > 0).sum()), step.size))


def case_interactive(a):
    """F12 in Blender's window (under Xvfb): the render runs on a job thread, the export is
    handed to the main thread; the result must be prt's pixels as in the foreground case."""
    install(a.zip)
    scene, _ = make_scene(64, 48, 8, a.prt)
    bpy.context.preferences.view.render_display_type = 'NONE'
    state = {"finished": False, "started": time.monotonic()}
    bpy.app.handlers.render_complete.append(lambda *_: state.update(finished=True))
    bpy.app.handlers.render_cancel.append(lambda *_: fail("the render was cancelled"))

    def step():
        if "invoked" not in state:
            state["invoked"] = bpy.ops.render.render('INVOKE_DEFAULT')
            if 'RUNNING_MODAL' not in state["invoked"]:
                fail("F12 did not start a render job: %s" % state["invoked"])
            return 0.2
        if not state["finished"]:
            if time.monotonic() - state["started"] > 60:
                fail("the render job did not finish within 60 s")
            return 0.2
        exr = os.path.join(a.out, "engine.exr")
        save_render(exr, 'OPEN_EXR')
        prt_render_of(scene, a.out, [os.path.join(a.out, "prt.pfm")])
        engine_linear, _ = load_pixels(exr)
        if not np.array_equal(engine_linear, read_pfm(os.path.join(a.out, "prt.pfm"))):
            fail("the render result of F12 differs from prt's pixels")
        done("F12 on a job thread in %.2f s: pixels bit-identical to prt's"
             % (time.monotonic() - state["started"]))

    bpy.app.timers.register(step, first_interval=0.5)


def case_animation(a):
    install(a.zip)
    scene, cube = make_scene(64, 48, 4, a.prt)
    cube.location = (0, 0, 0)
    cube.keyframe_insert("location", frame=1)
    cube.location = (0, 1.5, 0)
    cube.keyframe_insert("location", frame=2)
    scene.frame_start, scene.frame_end = 1, 2
    scene.render.image_settings.file_format = 'OPEN_EXR'
    scene.render.image_settings.color_depth = '32'
    scene.render.image_settings.color_mode = 'RGB'
    scene.render.filepath = os.path.join(a.out, "job_")
    bpy.ops.render.render(animation=True)
    job = [os.path.join(a.out, "job_%04d.exr" % f) for f in (1, 2)]
    for path in job:
        if not os.path.isfile(path):
            fail("the animation did not write %s" % path)
    # Each frame as a still of its own (the scene exported at that frame): the one-job
    # sequence, which evaluates the exported animation at frame / fps, must give the same.
    scene.prt.animation = 'FRAMES'
    scene.render.filepath = os.path.join(a.out, "own_")
    bpy.ops.render.render(animation=True)
    first, _ = load_pixels(job[0])
    second, _ = load_pixels(job[1])
    if np.array_equal(first, second):
        fail("the two frames are the same image: the animation was not rendered")
    worst = 0.0
    for f, path in zip((1, 2), job):
        own, _ = load_pixels(os.path.join(a.out, "own_%04d.exr" % f))
        mine, _ = load_pixels(path)
        worst = max(worst, float(np.abs(own - mine).max()))
    # The same frame through two exports: the sequence places the cube by the animation's
    # sampled translation, the still by its matrix; equal to float rounding at most.
    if worst > 1e-3:
        fail("a frame of the one-job sequence differs from the frame rendered alone by %g" % worst)
    done("two frames as one prt job, written by Blender; each equal to the frame rendered "
         "alone (max difference %g)" % worst)


def case_cancel(a):
    install(a.zip)
    scene, _ = make_scene(160, 120, 4096, a.prt)
    started = time.monotonic()
    bpy.ops.render.render()
    seconds = time.monotonic() - started
    # Uninterrupted, 160x120 at 4,096 samples takes minutes on two cores.
    if seconds > 30:
        fail("the cancelled render took %.1f s" % seconds)
    # An animation's one job, stopped at its first frame (and, since the forced break does not
    # stop Blender's loop as Esc does, again at the second, which starts a job of its own).
    scene.frame_start, scene.frame_end = 1, 2
    scene.render.filepath = os.path.join(a.out, "frame_")
    started = time.monotonic()
    bpy.ops.render.render(animation=True)
    animation_seconds = time.monotonic() - started
    if animation_seconds > 30:
        fail("the cancelled animation took %.1f s" % animation_seconds)
    done("a still stopped after %.2f s, an animation's job after %.2f s"
         % (seconds, animation_seconds))


def case_error(a, expected):
    install(a.zip)
    make_scene(64, 48, 4, a.prt)
    try:
        bpy.ops.render.render()
    except RuntimeError as e:  # Blender raises the engine's error report as the operator's
        message = str(e)
    else:
        message = ""
    print("OPERATOR: " + message)
    if expected not in message:
        fail("expected an error saying %r, got %r" % (expected, message))
    done("a clear error: %s" % message.strip().splitlines()[0])


def main():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    p = argparse.ArgumentParser()
    p.add_argument("--case", required=True)
    p.add_argument("--zip", required=True)
    p.add_argument("--prt", required=True)
    p.add_argument("--out", required=True)
    p.add_argument("--expect", default="")
    p.add_argument("--hostfile", default="")
    p.add_argument("--mpirun", default="")
    p.add_argument("--sbatch-script", default="")
    a = p.parse_args(argv)
    os.makedirs(a.out, exist_ok=True)
    cases = {"install": case_install, "still": case_still, "animation": case_animation,
             "cancel": case_cancel, "interactive": case_interactive, "mpi": case_elsewhere,
             "slurm": case_elsewhere, "joinable": case_elsewhere}
    try:
        if a.case in ("missing-prt", "failed-prt"):
            case_error(a, a.expect)
        cases[a.case](a)
    except SystemExit:
        raise
    except BaseException as e:  # Blender would exit 0 after a Python exception
        import traceback
        traceback.print_exc()
        fail("%s: %s" % (type(e).__name__, e))


main()
