#!/usr/bin/env python3
"""The Blender add-on, tested in Blender headless (label blender):

    addon_test.py --root REPO --prt PRT --case CASE --out DIR [--blender blender]

Builds the add-on's zip with scripts/package-blender-addon.sh, then runs
tests/blender/addon_cases.py inside `blender -b --factory-startup` with a fresh
BLENDER_USER_SCRIPTS (the zip is installed there, not in the user's Blender) and a TMPDIR of
its own, so that it can check afterwards that the engine left no temporary folder behind and
no process that names it (prt runs on the scene exported there). Exits 77 (CTest's
SKIP_RETURN_CODE), saying why, when Blender or its Python's NumPy is missing: Blender is a tool
for these tests, never a dependency of prt.
"""
import argparse
import os
import shutil
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))


def processes_naming(text):
    """The processes whose command line contains TEXT (pid, command line)."""
    found = []
    for pid in os.listdir("/proc"):
        if not pid.isdigit() or int(pid) == os.getpid():
            continue
        try:
            with open("/proc/%s/cmdline" % pid, "rb") as f:
                line = f.read().replace(b"\0", b" ").decode("utf-8", "replace")
        except OSError:
            continue
        if text in line and "addon_test.py" not in line:
            found.append((int(pid), line.strip()))
    return found


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--root", required=True)
    p.add_argument("--prt", required=True)
    p.add_argument("--case", required=True)
    p.add_argument("--out", required=True)
    p.add_argument("--blender", default="blender")
    a = p.parse_args()
    a.root = os.path.abspath(a.root)
    blender = shutil.which(a.blender)
    if blender is None:
        print("SKIP: Blender is not installed (apt-get install blender python3-numpy)")
        return 77
    # Blender's Python finds its modules (NumPy) by the python3 first on PATH: Debian's, beside
    # Blender, not one of a Python version manager's that runs this script.
    base_env = dict(os.environ, PATH=os.path.dirname(blender) + os.pathsep +
                    os.environ.get("PATH", ""))
    check = subprocess.run([blender, "-b", "--factory-startup", "--python-expr",
                            "import numpy; print('NUMPY_OK')"], capture_output=True, text=True,
                           timeout=120, env=base_env)
    if "NUMPY_OK" not in check.stdout:
        print("SKIP: Blender's Python has no NumPy (apt-get install python3-numpy)")
        return 77

    shutil.rmtree(a.out, ignore_errors=True)
    user_scripts = os.path.join(a.out, "user-scripts")
    tmp = os.path.join(a.out, "tmp")
    results = os.path.join(a.out, "results")
    for d in (user_scripts, tmp, results):
        os.makedirs(d)
    zip_path = os.path.join(a.out, "prt_render.zip")
    subprocess.run(["sh", os.path.join(a.root, "scripts", "package-blender-addon.sh"), zip_path],
                   check=True)

    prt, expect = os.path.abspath(a.prt), ""
    env = dict(base_env, BLENDER_USER_SCRIPTS=user_scripts, TMPDIR=tmp)
    env.pop("PRT_BLENDER_TEST_BREAK_AFTER_POLLS", None)
    if a.case == "missing-prt":
        prt = os.path.join(a.out, "no-such-folder", "prt")
        expect = "does not exist or cannot be run"
    elif a.case == "failed-prt":
        prt = os.path.join(a.out, "failing-prt")
        with open(prt, "w") as f:
            f.write("#!/bin/sh\necho 'warning: model file \"scene.glb\": a warning on purpose' >&2\n"
                    "echo 'scene.glb:1:1: error: this prt fails on purpose' >&2\nexit 2\n")
        os.chmod(prt, 0o755)
        expect = "this prt fails on purpose"
    elif a.case == "cancel":
        env["PRT_BLENDER_TEST_BREAK_AFTER_POLLS"] = "4"
    extra = []
    if a.case == "mpi":
        if shutil.which("mpirun") is None:
            print("SKIP: no mpirun (Open MPI)")
            return 77
        hostfile = os.path.join(a.out, "hostfile")
        with open(hostfile, "w") as f:
            f.write("localhost slots=3\n")  # rank 0, the master, and two workers here
        extra = ["--hostfile", hostfile, "--mpirun",
                 os.path.join(a.root, "scripts", "prt-mpirun")]
        env.update(OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
                   OMPI_MCA_btl="self,tcp", OMPI_MCA_btl_tcp_if_include="lo",
                   OMPI_MCA_oob_tcp_if_include="lo")
    cluster = None
    if a.case == "slurm":
        if os.getuid() != 0:
            print("SKIP: a Slurm cluster of network namespaces needs root")
            return 77
        for tool in ("ip", "unshare", "nsenter", "slurmctld", "slurmd", "munged", "sbatch",
                     "mpirun"):
            if shutil.which(tool) is None:
                print("SKIP: no %s (scripts/install-deps.sh installs Slurm)" % tool)
                return 77
        cluster = os.path.join(a.out, "cluster")
        script = os.path.join(a.root, "scripts", "slurm-cluster.sh")
        up = subprocess.run(["bash", script, "up", "3", cluster], capture_output=True, text=True)
        if up.returncode != 0:
            print(up.stdout + up.stderr)
            print("FAIL: the Slurm cluster did not come up")
            return 1
        env.update(SLURM_CONF=os.path.join(cluster, "slurm.conf"),
                   OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
                   OMPI_MCA_btl="tcp,self", OMPI_MCA_btl_tcp_if_include="10.232.0.0/24",
                   OMPI_MCA_oob_tcp_if_include="10.232.0.0/24",
                   PRT_MPIRUN=os.path.join(a.root, "scripts", "prt-mpirun"))
        extra = ["--sbatch-script", os.path.join(a.root, "examples", "slurm", "render.sbatch")]
    try:
        return run_case(a, blender, env, zip_path, prt, expect, extra, tmp, results)
    finally:
        if cluster is not None:
            subprocess.run(["bash", os.path.join(a.root, "scripts", "slurm-cluster.sh"), "down",
                            cluster], capture_output=True)


def run_case(a, blender, env, zip_path, prt, expect, extra, tmp, results):
    window = []
    if a.case == "interactive":  # Blender with its window, on a virtual X server
        xvfb = shutil.which("xvfb-run")
        if xvfb is None:
            print("SKIP: no xvfb-run (apt-get install xvfb) to run Blender with a window")
            return 77
        window = [xvfb, "-a", "-s", "-screen 0 1024x768x24"]
    background = [] if window else ["-b"]
    cmd = ["nice", "-n", "10"] + window + [blender] + background + [
           "--factory-startup", "--python-exit-code", "3",
           "--python", os.path.join(HERE, "addon_cases.py"), "--", "--case", a.case,
           "--zip", zip_path, "--prt", prt, "--out", results, "--expect", expect] + extra
    started = time.monotonic()
    run = subprocess.run(cmd, env=env, capture_output=True, text=True, timeout=600)
    seconds = time.monotonic() - started
    output = run.stdout + run.stderr
    print(output)
    print("blender ran %.1f s, exit code %d" % (seconds, run.returncode))
    if "Traceback" in output:
        print("FAIL: a Python traceback in Blender's output")
        return 1
    if run.returncode != 0 or "\nPASS " not in "\n" + run.stdout:
        print("FAIL: the case did not pass")
        return 1
    # What the exporter leaves out, and prt's warnings, reach Blender's info area.
    shown = {"still": ["Warning: PRT: the world colour (0.2, 0.2, 0.2) is not exported",
                       "Warning: PRT: glTF export: WARNING: Unsupported light source AREA"],
             "failed-prt": ['Warning: prt: warning: model file "scene.glb": a warning on '
                            'purpose'],
             # Blender's status line: the machine that joined rendered beside the local one.
             "joinable": ["2 workers (2 working)"]}.get(a.case, [])
    for line in shown:
        if line not in output:
            print("FAIL: Blender's output lacks %r" % line)
            return 1
    # Nothing left behind: no process running on what the engine exported, no temporary folder.
    # (A Slurm render's folder is made in its submit folder, the results.)
    deadline = time.monotonic() + 5
    while processes_naming(tmp) + processes_naming(results) and time.monotonic() < deadline:
        time.sleep(0.1)
    left = processes_naming(tmp) + processes_naming(results)
    if left:
        print("FAIL: processes left behind: %s" % left)
        for pid, _ in left:
            try:
                os.kill(pid, 9)
            except OSError:
                pass
        return 1
    # (Blender's own blender_* folder stays there: the case ends with os._exit.)
    leftovers = [n for d in (tmp, results) for n in os.listdir(d) if n.startswith("prt-blender-")]
    if leftovers:
        print("FAIL: temporary files left behind in %s: %s" % (tmp, leftovers))
        return 1
    print("pass: %s" % a.case)
    return 0


if __name__ == "__main__":
    sys.exit(main())
