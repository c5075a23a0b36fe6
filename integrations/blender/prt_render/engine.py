"""The PRT render engine: F12 exports the scene with Blender's glTF exporter into a temporary
folder, runs `prt render` on it, and fills the render result from prt's live page
(/status.json, /image.png on loopback) as the image fills in; the finished image is prt's
32-bit float image (.pfm, as its .exr), so the render result holds prt's own linear pixels, bit for bit.

An animation (Ctrl-F12) is one balanced prt job by default: at the first frame Blender asks
for, the frame range is exported with its animation and rendered with --frames; each later
call of render() waits for its frame's file and hands it back. Blender writes the frames
where its output settings say.
"""
import os
import shutil
import tempfile
import time

import bpy

from . import commands
from . import export
from . import pfm
from . import process

POLL_SECONDS = 0.25
# The image so far is fetched at most this often: prt encodes a PNG for each request, on
# cores that render otherwise (a 1920x1080 PNG costs tens of milliseconds).
IMAGE_SECONDS = 1.0
# For the tests: the engine's break check becomes true after this many polls, as Esc would.
TEST_BREAK_ENV = "PRT_BLENDER_TEST_BREAK_AFTER_POLLS"


class RenderFailed(Exception):
    """A failure told to the user in Blender's info area; never a traceback."""


class Stopped(Exception):
    """Esc before prt started: nothing to tell."""


def _resolve_executable(path, what):
    path = bpy.path.abspath(path.strip()) if path.strip() else ""
    if not path:
        raise RenderFailed("no %s executable is set (Render properties > PRT)" % what)
    if os.sep in path:
        if os.path.isfile(path) and os.access(path, os.X_OK):
            return os.path.abspath(path)  # prt runs in the render's folder
        raise RenderFailed("the %s executable '%s' does not exist or cannot be run: set its path "
                           "in Render properties > PRT" % (what, path))
    found = shutil.which(path)
    if found is None:
        raise RenderFailed("the %s executable '%s' is not on PATH: install PRT, or set the path "
                           "of prt in Render properties > PRT" % (what, path))
    return found


def _image_size(scene):
    r = scene.render
    return (max(1, r.resolution_x * r.resolution_percentage // 100),
            max(1, r.resolution_y * r.resolution_percentage // 100))


def _sbatch_script(settings, prt):
    if settings.sbatch_script.strip():
        return _resolve_file(settings.sbatch_script, "the Slurm job script")
    prefix = os.path.dirname(os.path.dirname(prt))
    for candidate in (os.path.join(prefix, "share", "prt", "slurm", "render.sbatch"),):
        if os.path.isfile(candidate):
            return candidate
    raise RenderFailed("no Slurm job script: set render.sbatch (examples/slurm/) in Render "
                       "properties > PRT > Where to render")


def _resolve_file(path, what):
    path = os.path.abspath(bpy.path.abspath(path))
    if not os.path.isfile(path):
        raise RenderFailed("%s '%s' does not exist" % (what, path))
    return path


def make_job(scene, folder, output, frames):
    """The prt job for SCENE's settings, writing OUTPUT (a pattern when FRAMES is set)."""
    s = scene.prt
    prt = _resolve_executable(s.prt_path, "prt")
    width, height = _image_size(scene)
    job = commands.Job(prt=prt, scene=os.path.join(folder, "scene.glb"), output=output,
                       width=width, height=height, integrator=s.integrator, samples=s.samples,
                       camera=export.camera_name(scene), threads=s.threads, where=s.where,
                       workers=s.workers, strategy=s.strategy, verify_percent=s.verify,
                       serve=s.serve.strip() or "127.0.0.1:0", frames=frames,
                       fps=scene.render.fps)
    if s.where == commands.MPI:
        job.hostfile = _resolve_file(s.hostfile, "the MPI hostfile")
        launcher = s.mpirun.strip() or "prt-mpirun"
        beside = os.path.join(os.path.dirname(prt), launcher)
        job.mpirun = beside if os.sep not in launcher and os.access(beside, os.X_OK) else \
            _resolve_executable(launcher, "MPI launcher")
    elif s.where == commands.SLURM:
        job.sbatch = _resolve_executable("sbatch", "Slurm sbatch")
        job.sbatch_script = _sbatch_script(s, prt)
        job.nodes = s.nodes
        job.partition = s.partition.strip()
    elif s.where == commands.JOINABLE:
        job.accept_file = os.path.abspath(bpy.path.abspath(s.accept_file)) \
            if s.accept_file.strip() else os.path.join(folder, "invitation")
    try:
        commands.validate(job)
    except commands.JobError as e:
        raise RenderFailed(str(e)) from None
    return job


def _make_folder(scene):
    """The render's temporary folder: under the Slurm submit folder (the nodes must see it),
    else the system's temporary folder."""
    s = scene.prt
    parent = None
    if s.where == commands.SLURM:
        parent = bpy.path.abspath(s.submit_folder) if s.submit_folder.strip() else ""
        if not parent or not os.path.isdir(parent):
            raise RenderFailed("rendering on Slurm needs a submit folder that every node sees "
                               "(Render properties > PRT > Where to render)")
    return tempfile.mkdtemp(prefix="prt-blender-", dir=parent)


def _load_final(result, path, width, height):
    """prt's finished image into the render result, as it is: its 32-bit float linear pixels
    (the .pfm prt writes holds every bit of them)."""
    try:
        pixels = pfm.read_rgba(path, width, height)
    except (OSError, ValueError) as e:
        raise RenderFailed("prt's image could not be read: %s" % e) from None
    result.layers[0].passes["Combined"].rect = pixels.reshape(-1, 4)


class Run:
    """One prt job under way: its folder, its process (or Slurm job) and its live page."""

    def __init__(self, job, folder):
        self.job = job
        self.folder = folder
        self.page = None
        self.version = None
        self.live_png = os.path.join(folder, "live.png")
        self.image_at = 0.0
        argv = commands.command(job)
        env = commands.environment(job, os.environ)
        try:
            if job.where == commands.SLURM:
                self.proc = process.SlurmJob(argv, env, folder)
            else:
                self.proc = process.PrtProcess(argv, env=env, cwd=folder)
        except (OSError, RuntimeError) as e:
            shutil.rmtree(folder, ignore_errors=True)
            raise RenderFailed("could not start %s: %s" % (argv[0], e)) from None

    def running(self):
        if isinstance(self.proc, process.SlurmJob):
            self.proc.poll_log()
            return self.proc.state() is not None
        return self.proc.running()

    def poll(self, engine, result):
        """Shows what is new: warnings, the progress and, when it changed, the image so far."""
        for line in self.proc.new_warnings():
            engine.report({'WARNING'}, "prt: " + line.strip())
        if self.page is None and self.proc.live:
            self.page = process.LivePage(self.proc.live)
        status = self.page.status() if self.page is not None else None
        if status is not None:
            fraction = status.get("done_fraction") or 0.0
            engine.update_progress(min(1.0, max(0.0, fraction)))
            engine.update_stats("", commands.status_text(status))
            now = time.monotonic()
            if result is not None and status.get("version") != self.version and \
                    status.get("pixels_done", 0) > 0 and now - self.image_at >= IMAGE_SECONDS \
                    and self.page.image(self.live_png):
                self.version = status.get("version")
                self.image_at = now
                try:
                    result.layers[0].load_from_file(self.live_png)
                    engine.update_result(result)
                except (RuntimeError, ValueError):
                    pass  # an image of another size (another frame's): wait for the next
        elif self.proc.progress is not None:  # Slurm: the log's progress lines
            fraction, eta, workers = self.proc.progress
            engine.update_progress(fraction)
            text = "PRT %.1f%%" % (100 * fraction)
            if eta:
                text += ", ETA " + eta
            if workers:
                text += ", %d workers" % workers
            engine.update_stats("", text)

    def returncode(self):
        if isinstance(self.proc, process.SlurmJob):
            return 0 if os.path.exists(self.job.output) or self.job.frames else 1
        return self.proc.wait()

    def failure(self, code):
        tail = self.proc.tail()
        return "prt failed (exit code %s)%s" % (code, ":\n" + tail if tail else "")

    def close(self):
        """Stops the job if it still runs (SIGTERM, then SIGKILL; scancel) and removes the
        folder."""
        try:
            if isinstance(self.proc, process.SlurmJob):
                if self.proc.state() is not None:
                    self.proc.stop()
            else:
                self.proc.stop()
        finally:
            shutil.rmtree(self.folder, ignore_errors=True)


class _Sequence:
    """The animation job that outlives one call of render(): started at the first frame
    Blender asks for, closed after the last, on cancel, or when another render starts."""
    run = None
    key = None
    frames = None

    @classmethod
    def close(cls, *_args):
        if cls.run is not None:
            run, cls.run, cls.key, cls.frames = cls.run, None, None, None
            run.close()


def _sequence_key(scene):
    s = scene.prt
    return (scene.name, scene.frame_end, scene.frame_step, _image_size(scene), scene.render.fps,
            tuple(getattr(s, p) for p in s.__annotations__))


class PRTRenderEngine(bpy.types.RenderEngine):
    bl_idname = "PRT"
    bl_label = "PRT"
    bl_use_preview = False

    def __init__(self):
        self._polls = 0
        limit = os.environ.get(TEST_BREAK_ENV, "")
        self._break_after = int(limit) if limit.isdigit() else None

    def _break(self):
        self._polls += 1
        if self._break_after is not None and self._polls > self._break_after:
            return True
        return self.test_break()

    def render(self, depsgraph):
        scene = depsgraph.scene
        try:
            if self.is_animation and scene.prt.animation == 'JOB' and scene.frame_start >= 0:
                self._render_sequence_frame(scene)
            else:
                _Sequence.close()
                self._render_still(scene)
        except RenderFailed as e:
            _Sequence.close()
            self.report({'ERROR'}, "PRT: %s" % e)
        except Stopped:
            _Sequence.close()

    # --- a still (or one frame, rendered on its own) -----------------------------------------

    def _export(self, scene, folder, animation):
        for w in export.unexported_warnings(scene):
            self.report({'WARNING'}, "PRT: " + w)
        self.update_stats("", "PRT: exporting the scene (glTF)")
        path = os.path.join(folder, "scene.glb")
        try:
            warnings = export.on_main_thread(
                lambda: export.export_gltf(scene, path, animation), self._break)
        except RuntimeError as e:
            raise RenderFailed(str(e)) from None
        if warnings is None:  # Esc during the export
            raise Stopped()
        for w in warnings:
            self.report({'WARNING'}, "PRT: glTF export: " + w.split("|", 1)[-1].strip())

    def _render_still(self, scene):
        folder = _make_folder(scene)
        run = None
        try:
            self._export(scene, folder, animation=False)
            job = make_job(scene, folder, os.path.join(folder, "image.pfm"), None)
            run = Run(job, folder)
            self._announce(job)
            width, height = _image_size(scene)
            result = self.begin_result(0, 0, width, height)
            try:
                while run.running():
                    if self._break():
                        self.update_stats("", "PRT: stopping")
                        return
                    run.poll(self, result)
                    time.sleep(POLL_SECONDS)
                code = run.returncode()  # (its output read to the end)
                run.poll(self, None)
                if code != 0:
                    raise RenderFailed(run.failure(code))
                _load_final(result, job.output, width, height)
                self.update_progress(1.0)
            finally:
                self.end_result(result)
        finally:
            if run is not None:
                run.close()
            else:
                shutil.rmtree(folder, ignore_errors=True)

    def _announce(self, job):
        if job.where == commands.JOINABLE:
            self.report({'INFO'}, "PRT: machines join this render with: " +
                        commands.join_command(job))

    # --- a frame of an animation rendered as one job ------------------------------------------

    def _render_sequence_frame(self, scene):
        frame = scene.frame_current
        key = _sequence_key(scene)
        frames = _Sequence.frames
        if _Sequence.run is None or _Sequence.key != key or frames is None or \
                not (frames[0] <= frame <= frames[1] and (frame - frames[0]) % frames[2] == 0):
            _Sequence.close()
            self._start_sequence(scene, frame, key)
        run = _Sequence.run
        first, last, step = _Sequence.frames
        path = commands.frame_path(run.job.output, frame)
        width, height = _image_size(scene)
        result = self.begin_result(0, 0, width, height)
        try:
            while not os.path.exists(path):
                if self._break():
                    self.update_stats("", "PRT: stopping")
                    _Sequence.close()
                    return
                if not run.running():
                    code = run.returncode()
                    run.poll(self, None)
                    if not os.path.exists(path):
                        raise RenderFailed(run.failure(code) if code != 0 else
                                           "prt ended without writing frame %d:\n%s"
                                           % (frame, run.proc.tail()))
                    break
                run.poll(self, result)
                time.sleep(POLL_SECONDS)
            _load_final(result, path, width, height)
        finally:
            self.end_result(result)
        os.remove(path)
        if frame + step > last:  # the last frame: the job ends with it
            code = run.returncode()
            _Sequence.close()
            if code != 0:
                raise RenderFailed(run.failure(code))

    def _start_sequence(self, scene, frame, key):
        folder = _make_folder(scene)
        try:
            self._export(scene, folder, animation=True)
            step = scene.frame_step
            last = frame + (scene.frame_end - frame) // step * step
            job = make_job(scene, folder, os.path.join(folder, "frame_####.pfm"),
                           (frame, last, step))
        except BaseException:
            shutil.rmtree(folder, ignore_errors=True)
            raise
        _Sequence.run = Run(job, folder)
        _Sequence.key = key
        _Sequence.frames = (frame, last, step)
        self._announce(job)


def register():
    bpy.utils.register_class(PRTRenderEngine)
    for handlers in (bpy.app.handlers.render_cancel, bpy.app.handlers.render_complete):
        if _Sequence.close not in handlers:
            handlers.append(_Sequence.close)


def unregister():
    _Sequence.close()
    for handlers in (bpy.app.handlers.render_cancel, bpy.app.handlers.render_complete):
        if _Sequence.close in handlers:
            handlers.remove(_Sequence.close)
    bpy.utils.unregister_class(PRTRenderEngine)
