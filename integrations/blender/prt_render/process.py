"""A running prt, as the engine sees it: started in a process group of its own, its output
read by two threads, its live page polled on loopback, and stopped with SIGTERM (then SIGKILL
after a grace period) so that no process is left behind. Plain Python, no bpy.
"""
import collections
import json
import os
import signal
import subprocess
import threading
import time
import urllib.error
import urllib.request

from . import commands

# How long prt gets to stop on SIGTERM (it writes no checkpoint here: --no-checkpoint) before
# its process group is killed.
STOP_GRACE_SECONDS = 10.0


class PrtProcess:
    """A launched command (prt, prt-mpirun, or sbatch's job through SlurmJob). Threading: the
    reader threads only append to the line buffers; everything else is called by the engine's
    render thread."""

    def __init__(self, argv, env=None, cwd=None):
        self.argv = list(argv)
        self.lines = collections.deque(maxlen=200)  # the last lines, for an error message
        self.warnings = []                          # lines to show as Blender warnings
        self.live = None                            # the live page's address, once printed
        self.progress = None                        # the last progress line, parsed
        self._lock = threading.Lock()
        self._reported = 0
        self.proc = subprocess.Popen(self.argv, env=env, cwd=cwd, stdin=subprocess.DEVNULL,
                                     stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                                     start_new_session=True)
        self._readers = [threading.Thread(target=self._read, args=(s,), daemon=True)
                         for s in (self.proc.stdout, self.proc.stderr)]
        for r in self._readers:
            r.start()

    def _read(self, stream):
        for raw in iter(stream.readline, b""):
            line = raw.decode("utf-8", "replace").rstrip("\r\n")
            with self._lock:
                self.lines.append(line)
                if self.live is None:
                    self.live = commands.live_url(line)
                progress = commands.progress_line(line)
                if progress is not None:
                    self.progress = progress
                if commands.is_warning(line):
                    self.warnings.append(line)
        stream.close()

    def new_warnings(self):
        """Warnings printed since the last call."""
        with self._lock:
            new = self.warnings[self._reported:]
            self._reported = len(self.warnings)
        return new

    def running(self):
        return self.proc.poll() is None

    def returncode(self):
        return self.proc.poll()

    def wait(self, timeout=None):
        code = self.proc.wait(timeout)
        for r in self._readers:
            r.join(5)
        return code

    def tail(self, count=8):
        with self._lock:
            lines = [l for l in self.lines if l.strip()]
        return "\n".join(lines[-count:])

    def stop(self, grace=STOP_GRACE_SECONDS):
        """SIGTERM to the whole process group (prt, or mpirun and its ranks), a wait of at most
        GRACE seconds, then SIGKILL to what is left. Returns the exit code."""
        if self.proc.poll() is None:
            _signal_group(self.proc.pid, signal.SIGTERM)
            try:
                self.proc.wait(grace)
            except subprocess.TimeoutExpired:
                pass
        # Whatever the leader did, nothing it started may outlive it.
        _signal_group(self.proc.pid, signal.SIGKILL)
        return self.wait()


def _signal_group(pgid, sig):
    try:
        os.killpg(pgid, sig)
    except (ProcessLookupError, PermissionError):
        pass


class LivePage:
    """Polls prt's live page: /status.json, and /image.png when the status changed."""

    def __init__(self, url, timeout=2.0):
        self.url = url
        self.timeout = timeout
        self.version = None

    def status(self):
        """The snapshot as a dict, or None when the server does not answer (yet, or any more)."""
        try:
            with urllib.request.urlopen(commands.status_url(self.url, "status.json"),
                                        timeout=self.timeout) as r:
                return json.loads(r.read().decode("utf-8"))
        except (OSError, ValueError, urllib.error.URLError):
            return None

    def image(self, path):
        """Writes the image so far to PATH; False when it could not be had."""
        try:
            with urllib.request.urlopen(commands.status_url(self.url, "image.png"),
                                        timeout=self.timeout) as r:
                data = r.read()
        except (OSError, urllib.error.URLError):
            return False
        if not data.startswith(b"\x89PNG"):
            return False
        tmp = path + ".part"
        with open(tmp, "wb") as f:
            f.write(data)
        os.replace(tmp, path)
        return True


class SlurmJob:
    """A render submitted with sbatch: its id, its state from squeue, its progress from the
    log render.sbatch writes in the submit folder (prt-JOBID.out), stopped with scancel."""

    def __init__(self, argv, env, folder, squeue="squeue", scancel="scancel"):
        self.folder = folder
        self.squeue = squeue
        self.scancel = scancel
        done = subprocess.run(argv, env=env, cwd=folder, stdin=subprocess.DEVNULL,
                              capture_output=True, text=True, timeout=120)
        if done.returncode != 0:
            raise RuntimeError("sbatch failed: %s" % (done.stderr.strip() or done.stdout.strip()))
        self.job_id = done.stdout.strip().split(";")[0]
        if not self.job_id.isdigit():
            raise RuntimeError("sbatch gave no job id: %r" % done.stdout)
        self.log = os.path.join(folder, "prt-%s.out" % self.job_id)
        self._read = 0
        self.lines = collections.deque(maxlen=200)
        self.warnings = []
        self.progress = None
        self.live = None
        self._reported = 0

    def state(self):
        """Slurm's state of the job (PENDING, RUNNING, ...), or None once it has left the
        queue."""
        done = subprocess.run([self.squeue, "-h", "-j", self.job_id, "-o", "%T"],
                              capture_output=True, text=True, timeout=60)
        state = done.stdout.strip()
        return state or None

    def poll_log(self):
        try:
            with open(self.log, "rb") as f:
                f.seek(self._read)
                data = f.read()
        except OSError:
            return
        complete = data.rfind(b"\n") + 1
        self._read += complete
        for raw in data[:complete].splitlines():
            line = raw.decode("utf-8", "replace").replace("\r", "")
            self.lines.append(line)
            progress = commands.progress_line(line)
            if progress is not None:
                self.progress = progress
            if commands.is_warning(line):
                self.warnings.append(line)

    def new_warnings(self):
        new = self.warnings[self._reported:]
        self._reported = len(self.warnings)
        return new

    def tail(self, count=8):
        lines = [l for l in self.lines if l.strip()]
        return "\n".join(lines[-count:])

    def stop(self):
        subprocess.run([self.scancel, self.job_id], capture_output=True, timeout=60)
        deadline = time.monotonic() + STOP_GRACE_SECONDS
        while self.state() is not None and time.monotonic() < deadline:
            time.sleep(0.5)
