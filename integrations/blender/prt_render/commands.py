"""The command lines the PRT render engine runs, and the reading of what prt prints.

Plain Python, no bpy: the engine builds a Job from the scene's settings and this module turns
it into argv, so that every place to render (this machine, MPI hosts, a Slurm cluster, a
render that machines join) is tested without Blender (tests/blender/commands_test.py).
"""
import dataclasses
import os
import re
import shlex

# What `prt render --strategy` accepts (its --help lists them; commands_test.py checks that
# this list and the built prt agree). adaptive is prt's default.
STRATEGIES = ("adaptive", "scatter", "scatter-weighted", "hybrid", "hybrid-weighted",
              "reservoir", "reservoir-scatter", "blocks", "frames", "self", "guided",
              "factoring", "awf-b", "awf-c", "af", "stealing")
DEFAULT_STRATEGY = "adaptive"
INTEGRATORS = ("path", "hall")

# Where to render.
LOCAL = "LOCAL"        # prt on this machine: serially on its threads, or with local workers
MPI = "MPI"            # scripts/prt-mpirun (or mpirun) over a hostfile; rank 0 on this machine
SLURM = "SLURM"        # sbatch examples/slurm/render.sbatch from a folder the nodes share
JOINABLE = "JOINABLE"  # this machine's workers, and any machine that runs `prt join FILE`
PLACES = (LOCAL, MPI, SLURM, JOINABLE)


class JobError(ValueError):
    """A setting that cannot make a command line; the message says which and why."""


@dataclasses.dataclass
class Job:
    """One `prt render` run, whole: built once from the panel's settings."""
    prt: str                       # the prt executable
    scene: str                     # the exported glTF file
    output: str                    # the image (.exr), or a pattern with #### for --frames
    width: int
    height: int
    integrator: str = "path"
    samples: int = 16              # --spp
    camera: str = ""               # --camera (the glTF camera's name); empty: the file's first
    threads: int = 0               # --threads; 0: every core
    where: str = LOCAL
    workers: int = 0               # local workers (0: a serial render), MPI worker ranks
    strategy: str = DEFAULT_STRATEGY
    verify_percent: float = 1.0    # --verify of a parallel render
    serve: str = "127.0.0.1:0"     # --serve [HOST:]PORT; the engine polls it
    frames: tuple = None           # (first, last, step) for --frames, or None for a still
    fps: int = 24                  # --fps: the exporter writes frame N at N / fps seconds
    hostfile: str = ""             # MPI
    mpirun: str = "prt-mpirun"     # MPI: prt-mpirun, else mpirun
    sbatch: str = "sbatch"         # Slurm
    sbatch_script: str = ""        # Slurm: examples/slurm/render.sbatch (or its installed copy)
    nodes: int = 2                 # Slurm
    partition: str = ""            # Slurm; empty: the cluster's default
    accept_file: str = ""          # JOINABLE: --accept-workers FILE
    extra_environment: dict = dataclasses.field(default_factory=dict)

    def parallel(self):
        return self.where != LOCAL or self.workers > 0


def validate(job):
    """Raises JobError for settings prt would refuse, before anything is exported."""
    if job.where not in PLACES:
        raise JobError("unknown place to render %r (one of %s)" % (job.where, ", ".join(PLACES)))
    if job.integrator not in INTEGRATORS:
        raise JobError("unknown integrator %r (one of %s)" % (job.integrator,
                                                              ", ".join(INTEGRATORS)))
    if job.strategy not in STRATEGIES:
        raise JobError("unknown strategy %r (one of %s)" % (job.strategy, ", ".join(STRATEGIES)))
    if not 1 <= job.width <= 32768 or not 1 <= job.height <= 32768:
        raise JobError("the image must be 1 to 32768 pixels each way, not %dx%d"
                       % (job.width, job.height))
    if not 1 <= job.samples <= 4096:
        raise JobError("samples must be 1 to 4096, not %d" % job.samples)
    if not 0 <= job.threads <= 1024:
        raise JobError("threads must be 0 (every core) to 1024, not %d" % job.threads)
    if not 0 <= job.verify_percent <= 100:
        raise JobError("--verify must be a percentage, 0 to 100, not %g" % job.verify_percent)
    if job.where == MPI:
        if not job.hostfile:
            raise JobError("rendering on MPI hosts needs a hostfile")
        if job.workers < 1:
            raise JobError("rendering on MPI hosts needs at least one worker rank")
    if job.where == SLURM:
        if not job.sbatch_script:
            raise JobError("rendering on Slurm needs render.sbatch (examples/slurm/)")
        if job.nodes < 1:
            raise JobError("a Slurm job needs at least one node")
    if job.where == JOINABLE:
        if not job.accept_file:
            raise JobError("a render that machines join needs the file to invite them with")
        if job.workers < 1:
            raise JobError("a render that machines join needs at least one local worker")
    if job.frames is not None:
        first, last, step = job.frames
        if last < first or step < 1:
            raise JobError("frames %d to %d by %d: no frame to render" % (first, last, step))


def render_args(job, with_output=True):
    """The arguments after `prt render SCENE`, the same under every launcher; -o and
    --no-checkpoint unless WITH_OUTPUT is false (render.sbatch sets the output and keeps a
    checkpoint of its own)."""
    args = ["-o", job.output] if with_output else []
    args += ["--width", str(job.width),
            "--height", str(job.height), "--integrator", job.integrator,
            "--spp", str(job.samples), "--threads", str(job.threads)]
    if job.camera:
        args += ["--camera", job.camera]
    if job.frames is not None:
        first, last, step = job.frames
        args += ["--frames", "%d-%d:%d" % (first, last, step), "--fps", str(job.fps)]
    if job.where == LOCAL and job.workers > 0 or job.where == JOINABLE:
        args += ["--workers", str(job.workers)]
    if job.parallel():
        args += ["--strategy", job.strategy, "--verify", "%g" % job.verify_percent]
    if job.where == JOINABLE:
        args += ["--accept-workers", job.accept_file]
    if job.serve and job.where != SLURM:
        args += ["--serve", job.serve]
    if with_output:
        # The render's temporary folder goes with it: a checkpoint there would go too.
        args += ["--no-checkpoint"]
    return args


def command(job):
    """argv of the process to start for JOB (validated first)."""
    validate(job)
    if job.where in (LOCAL, JOINABLE):
        return [job.prt, "render", job.scene] + render_args(job)
    if job.where == MPI:
        # Rank 0, the master, takes the hostfile's first slot: this machine must come first,
        # since the master writes the image and serves the live page on its loopback.
        return [job.mpirun, "--hostfile", job.hostfile, "-np", str(job.workers + 1),
                "--map-by", "node", "--bind-to", "none",
                job.prt, "render", job.scene] + render_args(job)
    # SLURM: render.sbatch adds -o, --checkpoint and --report itself (the checkpoint beside
    # the output in the submit folder, so that a requeued job resumes).
    sb = [job.sbatch, "--parsable", "--nodes=%d" % job.nodes]
    if job.partition:
        sb.append("--partition=%s" % job.partition)
    sb += ["--chdir=%s" % (os.path.dirname(job.output) or "."), job.sbatch_script, job.scene,
           job.output] + render_args(job, with_output=False)
    return sb


def environment(job, base):
    """The environment of the launched process: render.sbatch reads PRT and PRT_MPIRUN."""
    env = dict(base)
    if job.where == SLURM:
        env["PRT"] = job.prt
    env.update(job.extra_environment)
    return env


def join_command(job):
    """What to run on a machine that should join a JOINABLE render, for the info line."""
    return "prt join %s  (or: sbatch --nodes=N examples/slurm/join.sbatch %s)" % (
        shlex.quote(job.accept_file), shlex.quote(job.accept_file))


def frame_path(pattern, frame):
    """The file prt writes frame FRAME of a --frames pattern to: the #s its zero-padded number."""
    m = re.search(r"#+", pattern)
    if not m:
        raise JobError("the pattern %r has no #" % pattern)
    digits = len(m.group(0))
    number = ("-%0*d" % (digits, -frame)) if frame < 0 else "%0*d" % (digits, frame)
    return pattern[:m.start()] + number + pattern[m.end():]


# --- what prt prints -------------------------------------------------------------------

_LIVE = re.compile(r"prt: live page at (http://\S+)")
_PROGRESS = re.compile(r"prt: ([0-9.]+)% of [0-9,]+ px, ([0-9.]+ \w+)(?:, ETA ([^;]+))?"
                       r"(?:; (\d+) workers?)?")


def live_url(line):
    """The address to poll from a 'prt: live page at URL' line, or None. A server that listens
    on every interface (0.0.0.0, [::]) is polled on loopback; the token stays in the query."""
    m = _LIVE.search(line)
    if not m:
        return None
    url = m.group(1)
    url = url.replace("//0.0.0.0:", "//127.0.0.1:").replace("//[::]:", "//[::1]:")
    return url


def status_url(live, path):
    """LIVE (the page's address, maybe with ?token=) with PATH instead of the page."""
    base, _, query = live.partition("?")
    base = base.rstrip("/") + "/" + path
    return base + ("?" + query if query else "")


def progress_line(line):
    """A progress line ('prt: 45.2% of 76,800 px, 12 s, ETA 15 s; 2 workers: ...') as
    (fraction, eta or None, workers or None), else None."""
    m = _PROGRESS.search(line)
    if not m:
        return None
    workers = int(m.group(4)) if m.group(4) else None
    return float(m.group(1)) / 100.0, (m.group(3) or "").strip() or None, workers


def is_warning(line):
    """A warning prt (or the glTF exporter) printed, to be shown in Blender's info area."""
    lower = line.lower()
    if "draco mesh compression is not available" in lower:
        return False  # Debian's Blender lacks Draco, which the export never uses
    return "warning" in lower and ("warning:" in lower or "| warning" in lower)


def status_text(status):
    """Blender's status line from a /status.json snapshot: percent, ETA and workers."""
    fraction = status.get("done_fraction")
    if fraction is None and status.get("pixels_total"):
        fraction = status.get("pixels_done", 0) / status["pixels_total"]
    parts = ["PRT %.1f%%" % (100.0 * (fraction or 0.0))]
    eta = status.get("eta_s")
    if isinstance(eta, (int, float)) and eta >= 0:
        parts.append("ETA %s" % format_seconds(eta))
    workers = status.get("workers") or []
    if workers:
        working = sum(1 for w in workers if w.get("state") == "working")
        parts.append("%d worker%s (%d working)" % (len(workers), "s" if len(workers) > 1 else "",
                                                   working))
    return ", ".join(parts)


def format_seconds(seconds):
    seconds = int(round(seconds))
    if seconds < 60:
        return "%d s" % seconds
    if seconds < 3600:
        return "%d min %02d s" % divmod(seconds, 60)
    return "%d h %02d min" % (seconds // 3600, seconds % 3600 // 60)
