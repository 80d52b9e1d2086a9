"""The pipeline rows of the benchmark table (issue 15, items 2 and 5). Called by
bench/pipeline-throughput.sh and bench/pipeline-backlog.sh; standard library only.

throughput: BUNDLES seeded 3D folder bundles (GenerateBundles.java, 10^4-pose TUM pairs, the
  service's default lesson preset) are generated once into DATA; each run hard-links them into a
  fresh root (the template is never consumed) and times `trajeval-pipeline watch --root R --drain`
  (every guarantee on: fsync'd reports and ledger, atomic moves), then `trajeval eval --batch` on
  the same pairs (one report per pair + summary.csv) with the same settings, and checks that both
  gave the same ATE for every run.
backlog: the drain of a backlog of SMALL and of LARGE bundles (100-pose pairs), peak RSS of each.

Every timed command runs under `flock LOCK nice -n 10 /usr/bin/time -v` (the machine is shared: one
benchmark at a time); the 1-minute load average is read before and after each run. --runs R runs
every case R times, alternating the launchers when --before is given, and prints the minimum.
"""
import argparse
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
GENERATOR = os.path.join(ROOT, "bench", "pipeline", "GenerateBundles.java")
# eval --batch with the pipeline's settings: its default lesson preset, two threads
BATCH_OPTIONS = ["--convention", "lesson", "--threads", "2"]


def load():
    return float(open("/proc/loadavg").read().split()[0])


def generate(data, bundles, poses):
    """The seeded bundles, written once (a folder with a complete marker is reused)."""
    d = os.path.join(data, f"bundles-{bundles}x{poses}")
    if os.path.exists(d + ".complete"):
        return d
    shutil.rmtree(d, ignore_errors=True)
    print(f"generating {bundles} bundles of {poses} poses into {d}", file=sys.stderr, flush=True)
    subprocess.run(["java", GENERATOR, d, str(bundles), str(poses)], check=True)
    open(d + ".complete", "w").close()
    return d


def timed(cmd, lock, cwd=None):
    """Runs cmd under the shared lock, nice 10 and /usr/bin/time -v: wall s, CPU s, peak RSS MiB, load, output.
    lock None: the caller holds the lock already (run.py under run-benchmarks.sh; a second flock would wait forever)."""
    fd, tfile = tempfile.mkstemp(prefix="pipeline-bench-", suffix=".time")
    os.close(fd)
    try:
        la0 = load()
        r = subprocess.run((["flock", lock] if lock else []) + ["nice", "-n", "10", "/usr/bin/time", "-v", "-o", tfile] + cmd,
                           stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, cwd=cwd)
        la1 = load()
        text = open(tfile).read()
    finally:
        os.unlink(tfile)

    def field(name):
        return re.search(re.escape(name) + r":\s*(\S+)", text).group(1)

    w = field("Elapsed (wall clock) time (h:mm:ss or m:ss)").split(":")
    wall = float(w[-1]) + 60 * float(w[-2]) + (3600 * float(w[-3]) if len(w) > 2 else 0)
    cpu = float(field("User time (seconds)")) + float(field("System time (seconds)"))
    rss = int(field("Maximum resident set size (kbytes)")) / 1024
    return {"code": r.returncode, "wall": wall, "cpu": cpu, "rss": rss, "load": (la0, la1), "out": r.stdout}


def fresh_root(template, scratch):
    root = tempfile.mkdtemp(prefix="root-", dir=scratch)
    subprocess.run(["cp", "-al", template, os.path.join(root, "incoming")], check=True)
    return root


def drain(launcher, template, scratch, lock, workers, expect):
    root = fresh_root(template, scratch)
    try:
        cmd = [launcher, "watch", "--root", root, "--drain"] + (["--workers", str(workers)] if workers else [])
        r = timed(cmd, lock)
        last = [x for x in r["out"].splitlines() if x.startswith("reported=")]
        if r["code"] != 0 or not last or not last[-1].startswith(f"reported={expect} "):
            raise SystemExit(f"drain failed (exit {r['code']}): {' '.join(cmd)}\n{r['out'][-3000:]}")
        ate = {}
        for f in sorted(os.listdir(os.path.join(root, "reports")))[:20]:
            if f.endswith(".json"):
                rep = json.load(open(os.path.join(root, "reports", f)))
                ate[f] = rep["evaluation"]["ate"]["trans_m"]["rmse"]
        r["ate"] = ate
        return r
    finally:
        shutil.rmtree(root, ignore_errors=True)


def batch(launcher, pairs, scratch, lock):
    out = tempfile.mkdtemp(prefix="batch-", dir=scratch)
    try:
        cmd = [launcher, "eval", "--batch", pairs, "--reports", out] + BATCH_OPTIONS
        r = timed(cmd, lock)
        if r["code"] != 0:
            raise SystemExit(f"eval --batch failed (exit {r['code']}): {' '.join(cmd)}\n{r['out'][-3000:]}")
        r["ate"] = {}
        for f in sorted(os.listdir(out))[:21]:
            if f.endswith(".json"):
                r["ate"][f] = json.load(open(os.path.join(out, f)))["ate"]["trans_m"]["rmse"]
        return r
    finally:
        shutil.rmtree(out, ignore_errors=True)


def row(case, tag, n, runs):
    best = min(runs, key=lambda r: r["wall"])
    cpu = min(r["cpu"] for r in runs)
    loads = ", ".join(f"{r['load'][0]:.1f}-{r['load'][1]:.1f}" for r in runs)
    rss = sorted(r["rss"] for r in runs)
    rss_text = f"{rss[0]:.0f}" + (f" ({', '.join(f'{x:.0f}' for x in rss[1:])})" if len(rss) > 1 else "")
    print(f"| {case} | {tag} | {n} | {best['wall']:.2f} | {n / best['wall']:.1f} | {cpu:.2f} | {cpu * 1000 / n:.1f} | "
          f"{rss_text} | {loads} |", flush=True)


def throughput(a):
    template = generate(a.data, a.bundles, a.poses)
    pairs = template + ".pairs.csv"
    launchers = [("after", a.pipeline, a.trajeval)] + ([("before", a.before_pipeline, a.before_trajeval)]
                                                        if a.before_pipeline else [])
    print(f"{os.cpu_count()} CPUs; {a.bundles} bundles of {a.poses}-pose 3D TUM pairs, lesson preset; "
          f"minimum of {a.runs} runs; load average (1 min) before-after each run")
    print("| case | build | runs | min wall (s) | runs/s | min CPU (s) | CPU ms/run | peak RSS (MiB): min (others) | load |")
    print("| --- | --- | ---: | ---: | ---: | ---: | ---: | ---: | --- |")
    results = {}
    for k in range(a.runs):
        order = launchers if k % 2 == 0 else list(reversed(launchers))
        for tag, pl, tr in order:
            results.setdefault(("drain", tag), []).append(drain(pl, template, a.scratch, a.lock, a.workers, a.bundles))
            if not a.no_batch and tr:
                results.setdefault(("batch", tag), []).append(batch(tr, pairs, a.scratch, a.lock))
    for (case, tag), runs in sorted(results.items()):
        name = (f"trajeval-pipeline watch --drain, {a.workers or 'default'} workers" if case == "drain"
                else "trajeval eval --batch --threads 2")
        row(name, tag, a.bundles, runs)
    # the same numbers from both front ends (and both builds): report files differ only in name
    drains = results[("drain", "after")][0]["ate"]
    if ("batch", "after") in results:
        same_ate(drains, results[("batch", "after")][0]["ate"])
        print(f"checked: pipeline and eval --batch give the same ATE RMSE, bit for bit, on {len(drains)} runs")


def same_ate(drains, batches):
    """Stops unless every report of the drain has the same ATE RMSE as eval --batch's of that name."""
    for f, v in drains.items():
        if batches.get(f) != v:
            raise SystemExit(f"ATE of {f} differs: pipeline {v}, eval --batch {batches.get(f)}")


def backlog(a):
    print(f"{os.cpu_count()} CPUs; backlog drained by trajeval-pipeline watch --drain, {a.poses}-pose 3D pairs; "
          f"minimum of {a.runs} runs; load average (1 min) before-after each run")
    print("| case | build | runs | min wall (s) | runs/s | min CPU (s) | CPU ms/run | peak RSS (MiB): min (others) | load |")
    print("| --- | --- | ---: | ---: | ---: | ---: | ---: | ---: | --- |")
    launchers = [("after", a.pipeline)] + ([("before", a.before_pipeline)] if a.before_pipeline else [])
    peaks = {}
    for n in (a.small, a.large):
        template = generate(a.data, n, a.poses)
        runs = {}
        for k in range(a.runs):
            for tag, pl in (launchers if k % 2 == 0 else list(reversed(launchers))):
                runs.setdefault(tag, []).append(drain(pl, template, a.scratch, a.lock, a.workers, n))
        for tag, rs in runs.items():
            row(f"backlog of {n} bundles", tag, n, rs)
            peaks[(tag, n)] = min(r["rss"] for r in rs)
    for tag, _ in launchers:
        print(f"{tag}: peak RSS at {a.large} / at {a.small} bundles = {peaks[(tag, a.large)] / peaks[(tag, a.small)]:.2f}x "
              f"(target <= 1.2x)")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("mode", choices=("throughput", "backlog"))
    ap.add_argument("--pipeline", required=True)
    ap.add_argument("--trajeval")
    ap.add_argument("--before-pipeline")
    ap.add_argument("--before-trajeval")
    ap.add_argument("--bundles", type=int, default=1000)
    ap.add_argument("--poses", type=int, default=10000)
    ap.add_argument("--small", type=int, default=1000)
    ap.add_argument("--large", type=int, default=100000)
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--workers", type=int, default=0)
    ap.add_argument("--no-batch", action="store_true")
    ap.add_argument("--data", required=True)
    ap.add_argument("--lock", default="/tmp/trajeval-bench.lock")
    a = ap.parse_args()
    os.makedirs(a.data, exist_ok=True)
    a.scratch = tempfile.mkdtemp(prefix="runs-", dir=a.data)
    try:
        throughput(a) if a.mode == "throughput" else backlog(a)
    finally:
        shutil.rmtree(a.scratch, ignore_errors=True)


if __name__ == "__main__":
    main()
