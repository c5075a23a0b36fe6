#!/usr/bin/env python3
"""The add-on's command lines and its reading of prt's output, without Blender:

    commands_test.py --root REPO --prt PRT

Each place to render builds the argv it should (this machine, MPI hosts, Slurm, machines
that join); every flag it passes exists in the built prt (checked against `prt render
--help`), and the strategy list is the one prt accepts. A process started and stopped by the
add-on's stop path leaves nothing behind.
"""
import argparse
import os
import re
import subprocess
import sys
import time
import unittest

ARGS = None


def load_modules(root):
    sys.path.insert(0, os.path.join(root, "integrations", "blender"))
    from prt_render import commands, process  # noqa: F401  (no bpy needed)
    return commands, process


class CommandLines(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.commands, cls.process = load_modules(ARGS.root)
        cls.help = subprocess.run([ARGS.prt, "render", "--help"], capture_output=True,
                                  text=True, check=True).stdout

    def job(self, **kw):
        base = dict(prt="/opt/prt/bin/prt", scene="/tmp/r/scene.glb", output="/tmp/r/image.pfm",
                    width=64, height=48, samples=8, camera="Camera")
        base.update(kw)
        return self.commands.Job(**base)

    def flags_exist(self, argv):
        for a in argv:
            if a.startswith("--"):
                self.assertRegex(self.help, r"(^|[\s,])%s[\s=]" % re.escape(a.split("=")[0]),
                                 "prt render has no %s" % a)

    def test_strategies_are_prts(self):
        listed = re.findall(r"^\s{30,}([a-z][a-z-]*) \((?:static|dynamic|adaptive)\)",
                            self.help, re.M)
        self.assertEqual(sorted(listed), sorted(self.commands.STRATEGIES))
        self.assertIn("default %s" % self.commands.DEFAULT_STRATEGY, self.help)

    def test_this_machine_serial(self):
        argv = self.commands.command(self.job(threads=3))
        self.assertEqual(argv, ["/opt/prt/bin/prt", "render", "/tmp/r/scene.glb", "-o",
                                "/tmp/r/image.pfm", "--width", "64", "--height", "48",
                                "--integrator", "path", "--spp", "8", "--threads", "3",
                                "--camera", "Camera", "--serve", "127.0.0.1:0",
                                "--no-checkpoint"])
        self.flags_exist(argv)

    def test_this_machine_workers(self):
        argv = self.commands.command(self.job(workers=4, strategy="hybrid", verify_percent=5,
                                              integrator="hall"))
        self.assertIn("--workers 4 --strategy hybrid --verify 5", " ".join(argv))
        self.assertIn("--integrator hall", " ".join(argv))
        self.flags_exist(argv)

    def test_animation(self):
        job = self.job(output="/tmp/r/frame_####.pfm", frames=(3, 11, 2), fps=30)
        argv = self.commands.command(job)
        self.assertIn("--frames 3-11:2 --fps 30", " ".join(argv))
        self.flags_exist(argv)
        self.assertEqual(self.commands.frame_path(job.output, 7), "/tmp/r/frame_0007.pfm")
        self.assertEqual(self.commands.frame_path(job.output, 12345), "/tmp/r/frame_12345.pfm")

    def test_mpi(self):
        argv = self.commands.command(self.job(where="MPI", hostfile="/etc/hosts.mpi", workers=3,
                                              mpirun="/opt/prt/bin/prt-mpirun"))
        self.assertEqual(argv[:9], ["/opt/prt/bin/prt-mpirun", "--hostfile", "/etc/hosts.mpi",
                                    "-np", "4", "--map-by", "node", "--bind-to", "none"])
        self.assertEqual(argv[9:12], ["/opt/prt/bin/prt", "render", "/tmp/r/scene.glb"])
        self.assertNotIn("--workers", argv)  # the ranks are the workers
        self.assertIn("--strategy adaptive --verify 1", " ".join(argv))
        self.flags_exist(argv[9:])

    def test_slurm(self):
        job = self.job(where="SLURM", sbatch="/usr/bin/sbatch", nodes=8, partition="debug",
                       sbatch_script="/opt/prt/share/prt/slurm/render.sbatch",
                       output="/shared/prt-blender-x/image.pfm",
                       scene="/shared/prt-blender-x/scene.glb")
        argv = self.commands.command(job)
        self.assertEqual(argv[:7], ["/usr/bin/sbatch", "--parsable", "--nodes=8",
                                    "--partition=debug", "--chdir=/shared/prt-blender-x",
                                    "/opt/prt/share/prt/slurm/render.sbatch",
                                    "/shared/prt-blender-x/scene.glb"])
        self.assertEqual(argv[7], "/shared/prt-blender-x/image.pfm")
        # render.sbatch sets -o, the checkpoint and the report; no loopback page on a node.
        for absent in ("-o", "--no-checkpoint", "--serve", "--workers"):
            self.assertNotIn(absent, argv[8:])
        self.flags_exist(argv[8:])
        self.assertEqual(self.commands.environment(job, {"PATH": "/bin"})["PRT"],
                         "/opt/prt/bin/prt")

    def test_joinable(self):
        job = self.job(where="JOINABLE", workers=2, accept_file="/home/u/invite")
        argv = self.commands.command(job)
        self.assertIn("--workers 2 --strategy adaptive --verify 1 --accept-workers "
                      "/home/u/invite", " ".join(argv))
        self.flags_exist(argv)
        self.assertIn("prt join /home/u/invite", self.commands.join_command(job))

    def test_refusals(self):
        J = self.commands.JobError
        for bad in (dict(strategy="fastest"), dict(integrator="bdpt"), dict(samples=0),
                    dict(where="MPI"), dict(where="MPI", hostfile="h", workers=0),
                    dict(where="SLURM"), dict(where="JOINABLE", accept_file="f"),
                    dict(frames=(5, 4, 1)), dict(verify_percent=101), dict(where="CLOUD")):
            with self.assertRaises(J, msg=str(bad)):
                self.commands.command(self.job(**bad))

    def test_reading_prts_output(self):
        c = self.commands
        self.assertEqual(c.live_url("prt: live page at http://127.0.0.1:4242/"),
                         "http://127.0.0.1:4242/")
        self.assertEqual(c.live_url("prt: live page at http://0.0.0.0:80/?token=ab12"),
                         "http://127.0.0.1:80/?token=ab12")
        self.assertEqual(c.status_url("http://127.0.0.1:80/?token=ab12", "status.json"),
                         "http://127.0.0.1:80/status.json?token=ab12")
        self.assertEqual(c.progress_line("prt: 45.2% of 76,800 px, 12 s, ETA 15 s; 2 workers: "
                                         "2 working"), (0.452, "15 s", 2))
        self.assertTrue(c.is_warning('warning: model file "x.glb": skinning is not rendered'))
        self.assertTrue(c.is_warning("12:00:00 | WARNING: Baking animation"))
        self.assertFalse(c.is_warning("12:00:00 | ERROR: Draco mesh compression is not "
                                      "available because library could not be found"))
        self.assertEqual(c.status_text({"done_fraction": 0.5, "eta_s": 75, "workers": [
            {"state": "working"}, {"state": "idle"}]}), "PRT 50.0%, ETA 1 min 15 s, "
            "2 workers (1 working)")

    def test_live_page_and_stop(self):
        """A real prt, long enough to be stopped: the live page answers, the stop path ends
        it and every process it started."""
        scene = os.path.join(ARGS.root, "scenes", "complex.scene")
        job = self.job(prt=ARGS.prt, scene=scene, output=os.path.join(ARGS.out, "stop.png"),
                       width=160, height=120, samples=4096, camera="", workers=2)
        os.makedirs(ARGS.out, exist_ok=True)
        run = self.process.PrtProcess(self.commands.command(job), cwd=ARGS.out)
        self.addCleanup(run.stop, 1)
        deadline = time.monotonic() + 30
        status = None
        while time.monotonic() < deadline and status is None:
            if run.live:
                status = self.process.LivePage(run.live).status()
            time.sleep(0.1)
        self.assertIsNotNone(status, "no live page: " + run.tail())
        self.assertIn(status["phase"], ("starting", "rendering"))
        self.assertTrue(run.running())
        started = time.monotonic()
        code = run.stop()
        self.assertEqual(code, 128 + 15, run.tail())  # prt's exit on SIGTERM
        self.assertLess(time.monotonic() - started, self.process.STOP_GRACE_SECONDS)
        with self.assertRaises(ProcessLookupError):
            os.killpg(run.proc.pid, 0)  # nothing of its process group is left
        self.assertFalse(os.path.exists(job.output))


def main():
    global ARGS
    p = argparse.ArgumentParser()
    p.add_argument("--root", required=True)
    p.add_argument("--prt", required=True)
    p.add_argument("--out", default="commands_test_out")
    ARGS, rest = p.parse_known_args()
    ARGS.prt = os.path.abspath(ARGS.prt)
    ARGS.root = os.path.abspath(ARGS.root)
    ARGS.out = os.path.abspath(ARGS.out)
    unittest.main(argv=[sys.argv[0]] + rest, verbosity=2)


if __name__ == "__main__":
    main()
