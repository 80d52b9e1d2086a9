"""The 3D rows of the benchmark: trajeval on 3D TUM pairs (nearest and interpolated association,
se3/sim3, ATE + RPE) beside the planar CSV pair of the same size, and eval --batch on many
10^4-pose 3D pairs against one process per pair.

Every command runs under `nice -n 10` and /usr/bin/time (wall, user + sys CPU, peak RSS), R times;
the minimum is reported (the machine is shared: the minimum is the least disturbed run), with the
1-minute load average read before each run. B/pose above the baseline = (peak RSS - peak RSS of the
same command on the 1000-pose pair) / poses.  --before DIR adds the same rows for another launcher
(A/B on the same files, the two builds alternated run by run: after, before, before, after, ...).  Called by bench/speed-3d.sh.
"""
import argparse
import os
import re
import subprocess
import sys
import time

from bench_commands import EVO_3D, LESSON_3D, PLANAR_LESSON, evo_ape_rpe, trajeval_eval

HERE = os.path.dirname(os.path.abspath(__file__))


def load():
    return float(open("/proc/loadavg").read().split()[0])


def timed(cmd, out=subprocess.DEVNULL):
    tfile = "/tmp/speed3d-%d.time" % os.getpid()
    la = load()
    r = subprocess.run(["nice", "-n", "10", "/usr/bin/time", "-v", "-o", tfile] + cmd, stdout=out,
                       stderr=subprocess.PIPE, text=True)
    text = open(tfile).read()
    if r.returncode not in (0,):
        raise SystemExit(f"failed ({r.returncode}): {' '.join(cmd)}\n{r.stderr[-2000:]}")
    wall = re.search(r"Elapsed \(wall clock\) time \(h:mm:ss or m:ss\): (\S+)", text).group(1)
    parts = [float(p) for p in wall.split(":")]
    secs = parts[-1] + 60 * parts[-2] + (3600 * parts[-3] if len(parts) > 2 else 0)
    cpu = float(re.search(r"User time \(seconds\): (\S+)", text).group(1)) + \
        float(re.search(r"System time \(seconds\): (\S+)", text).group(1))
    rss = int(re.search(r"Maximum resident set size \(kbytes\): (\d+)", text).group(1)) * 1024
    return secs, cpu, rss, la


def cases(t, d, n):
    p = [f"{d}/planar_{n}_ref.csv", f"{d}/planar_{n}_est.csv"]
    s = [f"{d}/spatial_{n}_ref.tum", f"{d}/spatial_{n}_est.tum"]
    return [
        ("planar CSV, lesson, se2, 1 thread", trajeval_eval(t, *p, PLANAR_LESSON, 1)),
        ("planar CSV, lesson, se2, 2 threads", trajeval_eval(t, *p, PLANAR_LESSON, 2)),
        ("3D TUM, evo (nearest, RPE 1 frame), se3", trajeval_eval(t, *s, EVO_3D + ["--align", "se3"], 2)),
        ("3D TUM, evo (nearest, RPE 1 frame), sim3", trajeval_eval(t, *s, EVO_3D + ["--align", "sim3"], 2)),
        ("3D TUM, lesson (interpolate, RPE 1 s), se3, 1 thread", trajeval_eval(t, *s, LESSON_3D + ["--align", "se3"], 1)),
        ("3D TUM, lesson (interpolate, RPE 1 s), se3, 2 threads", trajeval_eval(t, *s, LESSON_3D + ["--align", "se3"], 2)),
    ]


def gen(py, d, n, kind):
    name = {"planar": f"planar_{n}_est.csv", "spatial": f"spatial_{n}_est.tum"}[kind]
    if not os.path.exists(os.path.join(d, name)):
        subprocess.run(["nice", "-n", "10", py, os.path.join(HERE, "generate.py"), d, str(n), "--kind", kind,
                        "--seed", "20240605"], check=True)


def evo_side_by_side(a, n, mine):
    """evo_ape tum REF EST -a plus evo_rpe tum REF EST -a --delta 1 --delta_unit f: the options of
    trajeval's --convention evo --align se3 (nearest association within 0.01 s, SE(3) Umeyama, RPE
    over one frame); wall and CPU of the two added, peak RSS the larger, against the trajeval row."""
    ref, est = f"{a.data}/spatial_{n}_ref.tum", f"{a.data}/spatial_{n}_est.tum"
    ape, rpe = evo_ape_rpe(a.evo, ref, est, 1)
    runs = []
    for _ in range(a.evo_runs):
        x, y = timed(ape), timed(rpe)
        runs.append((x[0] + y[0], x[1] + y[1], max(x[2], y[2]), x[3], y[3]))
    best = min(runs, key=lambda r: r[0])
    print(f"| 10^{len(str(n)) - 1} | evo 1.38 | evo_ape -a + evo_rpe -a --delta 1 --delta_unit f | {best[0]:.2f} | "
          f"{best[1]:.2f} | {best[1] * 1e9 / n:.0f} | {best[2] / 2**20:.0f} | | "
          f"{', '.join(f'{r[3]:.1f}/{r[4]:.1f}' for r in runs)} |", flush=True)
    if mine:
        print(f"| 10^{len(str(n)) - 1} | ratio | evo / trajeval (evo convention, se3) | "
              f"{best[0] / mine['wall_min_s']:.1f}x | {best[1] / mine['cpu_min_s']:.1f}x | | | | |", flush=True)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--trajeval", required=True)
    ap.add_argument("--before", default=None, help="another launcher, measured on the same files")
    ap.add_argument("--python", default=sys.executable, help="a python with numpy, for generate.py")
    ap.add_argument("--sizes", default="1000000")
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--data", default="bench/data")
    ap.add_argument("--batch", type=int, default=0, help="pairs of 10^4 3D poses for the eval --batch rows")
    ap.add_argument("--evo", default=None, help="a bin/ directory with evo_ape and evo_rpe: side by side on the 3D pairs")
    ap.add_argument("--evo-runs", type=int, default=1, help="runs of evo per size (each takes 1-2 min at 10^6)")
    a = ap.parse_args()
    os.makedirs(a.data, exist_ok=True)
    tools = [("after", a.trajeval)] + ([("before", a.before)] if a.before else [])
    rows = []
    for kind in ("planar", "spatial"):
        gen(a.python, a.data, 1000, kind)
    base = {}
    for tag, t in tools:
        for name, cmd in cases(t, a.data, 1000):
            base[(tag, name)] = min(timed(cmd)[2] for _ in range(2))
    for n in [int(float(x)) for x in a.sizes.split(",")]:
        for kind in ("planar", "spatial"):
            gen(a.python, a.data, n, kind)
        evo_row_cpu = None
        names = [name for name, _ in cases(tools[0][1], a.data, n)]
        for idx, name in enumerate(names):
            # builds alternated run by run (after, before, before, after, ...), so that neither build
            # always runs first: in a VM the first of two back-to-back big runs pays more page-fault time
            timings = {tag: [] for tag, _ in tools}
            for k in range(a.runs):
                for tag, t in (tools if k % 2 == 0 else tools[::-1]):
                    timings[tag].append(timed(cases(t, a.data, n)[idx][1]))
            for tag, t in tools:
                runs = timings[tag]
                best = min(runs, key=lambda r: r[1])
                row = {"poses": n, "build": tag, "case": name, "wall_min_s": min(r[0] for r in runs),
                       "cpu_min_s": best[1], "rss_min_mib": min(r[2] for r in runs) / 2**20,
                       "bytes_per_pose": (min(r[2] for r in runs) - base[(tag, name)]) / n,
                       "load": [r[3] for r in runs]}
                rows.append(row)
                if tag == "after" and name.startswith("3D TUM, evo") and name.endswith("se3"):
                    evo_row_cpu = row
                print(f"| 10^{len(str(n)) - 1} | {tag} | {name} | {row['wall_min_s']:.2f} | {row['cpu_min_s']:.2f} | "
                      f"{row['cpu_min_s'] * 1e9 / n:.0f} | {row['rss_min_mib']:.0f} | {row['bytes_per_pose']:.0f} | "
                      f"{', '.join(f'{x:.1f}' for x in row['load'])} |", flush=True)
        if a.evo:
            evo_side_by_side(a, n, evo_row_cpu)
    if a.batch:
        n = 10000
        gen(a.python, a.data, n, "spatial")
        ref, est = f"{a.data}/spatial_{n}_ref.tum", f"{a.data}/spatial_{n}_est.tum"
        table = os.path.join(a.data, f"batch_{a.batch}.csv")
        with open(table, "w") as f:
            f.write("name,ref,est\n")
            for k in range(a.batch):
                f.write(f"p{k:05d},{os.path.abspath(ref)},{os.path.abspath(est)}\n")
        for tag, t in tools:
            if tag != "after":
                continue
            for preset in ("evo", "lesson"):
                out = os.path.join(a.data, f"batch_out_{preset}")
                runs = [timed([t, "eval", "--batch", table, "--reports", out, "--convention", preset,
                               "--align", "se3", "--threads", "2"]) for _ in range(a.runs)]
                best = min(runs, key=lambda r: r[0])
                print(f"| batch {a.batch} x 10^4 3D | {tag} | eval --batch, {preset}, se3, 2 threads | "
                      f"{best[0]:.2f} | {best[1]:.2f} | {a.batch / best[0]:.1f} pairs/s | {best[2] / 2**20:.0f} | "
                      f"| {', '.join(f'{r[3]:.1f}' for r in runs)} |", flush=True)
            k = 20
            t0 = time.time()
            per = [timed([t, "eval", ref, est, "--convention", "evo", "--align", "se3", "--out",
                          os.path.join(a.data, "one.json")]) for _ in range(k)]
            wall = min(p[0] for p in per)
            print(f"| one process per pair ({k} runs) | {tag} | eval REF EST --out, evo, se3 | {wall:.2f} (min) | "
                  f"{min(p[1] for p in per):.2f} | {1 / wall:.1f} pairs/s | {max(p[2] for p in per) / 2**20:.0f} | "
                  f"| {per[0][3]:.1f} |", flush=True)


if __name__ == "__main__":
    main()
