#!/usr/bin/env python3
"""One master's load: what a message costs it in real runs, and where it saturates.

1. Real runs (--real): prt render of the complex scene at 640x480 with batches of 16 and of
   1,024 pixels (fixed: --batch-seconds 0), under the thread driver and under MPI, --runs
   times each. Every report gives the master's CPU time outside its waits and its messages
   (master.busy_s, messages in and out, heartbeats included); a least-squares fit of
   busy = a * messages + b * pixels over the runs separates the cost of a message (a) from
   the cost of a pixel's colours copied into the image (b). Medians of the runs per setting.
2. The simulator (--sim): W workers (1,024 to 65,536, half 4x slower) on a 3840x2160 image
   with 3 s of work each, batches as small as 8 pixels (standing for pixels cheap enough that
   batches are short), with the small-scale settings (--batch-seconds 0.03, --worker-timeout
   5) and with the defaults by worker count; prints the master's modelled busy share, its
   messages and heartbeats, and the run's elapsed time against the ideal.

Usage: bench/master_load.py [--prt build/prt] [--runs 3] [--real] [--sim]
"""
import argparse
import json
import os
import statistics
import subprocess
import tempfile

SCENE = os.path.join(os.path.dirname(__file__), "..", "scenes", "complex.scene")


def render(prt, driver, batch, report):
    cmd = [prt, "render", SCENE, "--width", "640", "--height", "480", "--batch", str(batch),
           "--batch-seconds", "0", "--verify", "0", "--report", report, "-o",
           os.path.join(os.path.dirname(report), "out.png")]
    env = dict(os.environ)
    if driver == "mpi":
        env.update(OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
        cmd = ["mpirun", "--oversubscribe", "-np", "5"] + cmd
    else:
        cmd += ["--workers", "4"]
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                   env=env, timeout=300)
    with open(report) as f:
        r = json.load(f)
    m = r["master"]
    return m["busy_s"], m["messages_received"] + m["messages_sent"], r["width"] * r["height"]


def fit(points):
    """busy = a * messages + b * pixels by least squares (two unknowns)."""
    sxx = sum(m * m for _, m, _ in points)
    sxy = sum(m * p for _, m, p in points)
    syy = sum(p * p for _, _, p in points)
    sxz = sum(m * z for z, m, _ in points)
    syz = sum(p * z for z, _, p in points)
    det = sxx * syy - sxy * sxy
    return (sxz * syy - sxy * syz) / det, (sxx * syz - sxy * sxz) / det


def real(prt, runs):
    with tempfile.TemporaryDirectory() as d:
        report = os.path.join(d, "r.json")
        for driver in ("threads", "mpi"):
            points = []
            for batch in (16, 1024):
                got = [render(prt, driver, batch, report) for _ in range(runs)]
                busy = statistics.median(g[0] for g in got)
                msgs = statistics.median(g[1] for g in got)
                points.append((busy, msgs, got[0][2]))
                print(f"{driver:7} batch {batch:5}: master busy {1e3 * busy:.1f} ms (median of "
                      f"{runs}), {msgs:.0f} messages in and out")
            a, b = fit(points)
            print(f"{driver:7} fit: {1e6 * a:.2f} us per message, {1e9 * b:.0f} ns per pixel")


def sim(prt):
    print("| workers | settings | batch s | lease s | master busy | messages in | heartbeats "
          "in / out | elapsed s | ideal s |")
    print("|---|---|---|---|---|---|---|---|---|")
    with tempfile.TemporaryDirectory() as d:
        report = os.path.join(d, "s.json")
        for w in (1024, 4096, 16384, 65536):
            for label, flags in (("small-scale", ["--batch-seconds", "0.03", "--worker-timeout",
                                                  "5"]),
                                 ("by worker count", ["--batch-seconds",
                                                      str(max(0.03, w * 25e-6))])):
                subprocess.run([prt, "simulate", "--workers", str(w), "--width", "3840",
                                "--height", "2160", "--slow-share", "0.5", "--serial-seconds",
                                str(3 * w), "--batch", "8", "--quiet", "--report", report] +
                               flags, check=True, stdout=subprocess.DEVNULL)
                with open(report) as f:
                    r = json.load(f)
                m = r["master"]
                print(f"| {w:,} | {label} | {flags[1]} | {5 * r['heartbeat_s']:.3g} | "
                      f"{100 * r['master_busy_share']:.1f} % | {m['messages_received']:,} | "
                      f"{m['heartbeats_received']:,} / {m['heartbeats_sent']:,} | "
                      f"{r['elapsed_s']:.2f} | {r['ideal_s']:.2f} |")


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--prt", default="build/prt")
    p.add_argument("--runs", type=int, default=3)
    p.add_argument("--real", action="store_true")
    p.add_argument("--sim", action="store_true")
    a = p.parse_args()
    if not a.real and not a.sim:
        a.real = a.sim = True
    if a.real:
        real(a.prt, a.runs)
    if a.sim:
        sim(a.prt)


if __name__ == "__main__":
    main()
