"""The commands the benchmark scripts time, written once: run.py's table and speed3d.py's rows
build their command lines from these (the options of a case are never spelled twice).

Threads: one thread is pinned to CPU 0 with `taskset -c 0`, so that the JVM's own threads
(compiler, collector) share that core too; two threads run unpinned.
"""
import os

# the lesson's planar case: interpolated association, SE(2) alignment, RPE over 1 s
PLANAR_LESSON = ["--convention", "lesson", "--association", "interpolate", "--align", "se2",
                 "--rpe-delta", "1", "--rpe-unit", "s", "--json"]
# 3D, evo's convention: nearest association within 0.01 s, RPE over 1 frame (ALIGN: se3 or sim3)
EVO_3D = ["--convention", "evo", "--json"]
# 3D, the lesson's convention: interpolated association, RPE over 1 s, all pairs
LESSON_3D = ["--convention", "lesson", "--json"]


def trajeval_eval(trajeval, ref, est, options, threads):
    """`trajeval eval REF EST OPTIONS --threads N`, pinned to CPU 0 when N is 1."""
    pin = ["taskset", "-c", "0"] if threads == 1 else []
    return pin + [trajeval, "eval", ref, est] + options + ["--threads", str(threads)]


def evo_ape_rpe(evo_bin, ref, est, delta_frames):
    """evo_ape tum REF EST -a and evo_rpe tum REF EST -a --delta D --delta_unit f: SE(3) Umeyama
    alignment, nearest association within 0.01 s (evo's default), RPE over D frames; the two
    processes a tool row of evo adds up (wall and CPU summed, peak RSS the larger)."""
    return [[os.path.join(evo_bin, "evo_ape"), "tum", ref, est, "-a", "--no_warnings"],
            [os.path.join(evo_bin, "evo_rpe"), "tum", ref, est, "-a", "--delta", str(delta_frames),
             "--delta_unit", "f", "--no_warnings"]]
