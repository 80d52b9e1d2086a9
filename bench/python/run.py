"""Runs trajeval, the vectorised numpy lesson and evo alternately on the same seeded files (planar
CSV pairs; 3D TUM pairs for trajeval's evo and lesson conventions and evo side by side), checks
their numbers agree where their conventions agree, optionally adds the pipeline rows
(pipeline_rows.py), and writes one table with issue 15's targets judged under it
(issue15_targets.py). The commands are bench_commands.py's.

Timing: /usr/bin/time -v around each process (wall clock, user + sys CPU, peak RSS), R runs per
tool and size (evo rows: the first --evo-runs), all tools of a size in one rotation (RUN_ORDER; the
starting tool moves by one each run), median reported. Throughput
is estimate poses / median wall time; memory per pose is (peak RSS - RSS of the same tool on a
1000-pose pair) / poses.  Called by bench/run-benchmarks.sh, which prepares the venv and build.

Other processes: trajeval keeps both cores busy (about 2.3 s of CPU in 1.25 s at 10^6) while the
numpy lesson uses about one (1.5 s in 1.0 s), so any other process on the machine slows trajeval's
wall time more than numpy's. Before every run of every tool the script waits (up to --quiet-wait
seconds) until the machine has been idle for half a second, and it records the CPU time other
processes used during each run (/proc/stat's busy time minus the tool's own user + sys), so a
table says how disturbed its minutes were. The same rule for every tool: it favours neither.
"""
import argparse
import datetime
import json
import os
import platform
import re
import statistics
import subprocess
import sys
import time

import issue15_targets
import pipeline_rows
from bench_commands import EVO_3D, LESSON_3D, PLANAR_LESSON, evo_ape_rpe, trajeval_eval

HERE = os.path.dirname(os.path.abspath(__file__))
# the rows of one size, in the order the table lists them
PLANAR_TOOLS = ["trajeval (1 core)", "trajeval (2 cores)", "numpy lesson", "evo (ape + rpe)"]
SPATIAL_TOOLS = ["trajeval 3D evo se3 (1 core)", "trajeval 3D evo se3 (2 cores)", "trajeval 3D lesson se3 (1 core)",
                 "trajeval 3D lesson se3 (2 cores)", "evo 3D (ape + rpe)"]
# the order they run in (the first tool rotates each run): each 3D case next to the planar case with the
# same threads, so that the ratios of item 1 divide runs seconds apart, not minutes
RUN_ORDER = ["trajeval (1 core)", "trajeval 3D evo se3 (1 core)", "trajeval 3D lesson se3 (1 core)",
             "trajeval (2 cores)", "trajeval 3D evo se3 (2 cores)", "trajeval 3D lesson se3 (2 cores)",
             "numpy lesson", "evo (ape + rpe)", "evo 3D (ape + rpe)"]
EVO_TOOLS = {"evo (ape + rpe)", "evo 3D (ape + rpe)"}


def sh(cmd, **kw):
    return subprocess.run(cmd, check=True, **kw)


def busy_seconds():
    """CPU seconds all processors have spent busy since boot (/proc/stat: user + nice + system +
    irq + softirq + steal, in USER_HZ ticks)."""
    with open("/proc/stat") as f:
        v = [int(x) for x in f.readline().split()[1:]]
    return (v[0] + v[1] + v[2] + v[5] + v[6] + v[7]) / os.sysconf("SC_CLK_TCK")


def wait_quiet(limit_s, window_s=0.5, idle_cores=0.1):
    """Waits until other processes used under idle_cores x window_s of CPU during one window, or
    until limit_s has passed; returns the seconds waited."""
    start = time.monotonic()
    while time.monotonic() - start < limit_s:
        b0 = busy_seconds()
        time.sleep(window_s)
        if busy_seconds() - b0 < idle_cores * window_s:
            break
    return time.monotonic() - start


def load1():
    with open("/proc/loadavg") as f:
        return float(f.read().split()[0])


def timed(cmd, out_path, log_path, env=None):
    """Runs cmd under /usr/bin/time -v; returns (wall s, peak RSS bytes, user + sys CPU s of cmd,
    CPU s other processes used meanwhile)."""
    tfile = log_path + ".time"
    b0 = busy_seconds()
    with open(out_path, "w") as out, open(log_path, "w") as err:
        r = subprocess.run(["/usr/bin/time", "-v", "-o", tfile] + cmd, stdout=out, stderr=err, env=env)
    busy = busy_seconds() - b0
    if r.returncode != 0:
        raise SystemExit(f"failed ({r.returncode}): {' '.join(cmd)}; see {log_path}")
    text = open(tfile).read()
    wall = re.search(r"Elapsed \(wall clock\) time \(h:mm:ss or m:ss\): (\S+)", text).group(1)
    parts = [float(p) for p in wall.split(":")]
    secs = parts[-1] + 60 * parts[-2] + (3600 * parts[-3] if len(parts) > 2 else 0)
    rss = int(re.search(r"Maximum resident set size \(kbytes\): (\d+)", text).group(1)) * 1024
    cpu = sum(float(re.search(rf"{k} time \(seconds\): (\S+)", text).group(1)) for k in ("User", "System"))
    return secs, rss, cpu, max(0.0, busy - cpu)


def fmt_n(n):
    e = len(str(n)) - 1
    return f"10^{e}" if n == 10 ** e else str(n)


def tool_commands(trajeval, py, evo_bin, d, n, with_evo):
    """Every tool's commands on the pairs of n poses in directory d (a tool's processes run one after
    the other; its wall and CPU are their sums, its peak RSS the largest)."""
    ref, est = f"{d}/planar_{n}_ref.csv", f"{d}/planar_{n}_est.csv"
    sref, sest = f"{d}/spatial_{n}_ref.tum", f"{d}/spatial_{n}_est.tum"
    tools = {
        "trajeval (1 core)": [trajeval_eval(trajeval, ref, est, PLANAR_LESSON, 1)],
        "trajeval (2 cores)": [trajeval_eval(trajeval, ref, est, PLANAR_LESSON, 2)],
        "numpy lesson": [[py, os.path.join(HERE, "lesson_numpy.py"), ref, est]],
        "trajeval 3D evo se3 (1 core)": [trajeval_eval(trajeval, sref, sest, EVO_3D + ["--align", "se3"], 1)],
        "trajeval 3D evo se3 (2 cores)": [trajeval_eval(trajeval, sref, sest, EVO_3D + ["--align", "se3"], 2)],
        "trajeval 3D lesson se3 (1 core)": [trajeval_eval(trajeval, sref, sest, LESSON_3D + ["--align", "se3"], 1)],
        "trajeval 3D lesson se3 (2 cores)": [trajeval_eval(trajeval, sref, sest, LESSON_3D + ["--align", "se3"], 2)],
    }
    if with_evo:
        # planar: 100 frames = 1 s at 100 Hz (evo has no seconds unit); 3D: 1 frame, as --convention evo
        tools["evo (ape + rpe)"] = evo_ape_rpe(evo_bin, f"{d}/planar_{n}_ref.tum", f"{d}/planar_{n}_est.tum", 100)
        tools["evo 3D (ape + rpe)"] = evo_ape_rpe(evo_bin, sref, sest, 1)
    return tools


class Bench:
    def __init__(self, a):
        self.a = a
        self.py = a.python
        self.data = os.path.abspath(a.data)
        self.work = os.path.abspath(a.results)
        os.makedirs(self.data, exist_ok=True)
        os.makedirs(self.work, exist_ok=True)
        self.evo_bin = os.path.dirname(self.py)

    def gen(self, n, kind):
        names = {"planar": f"planar_{n}_est.csv", "planar-tum": f"planar_{n}_est.tum",
                 "spatial": f"spatial_{n}_est.tum"}
        if not os.path.exists(os.path.join(self.data, names[kind])):
            print(f"  generating {kind} pair of {fmt_n(n)} poses", flush=True)
            sh([self.py, os.path.join(HERE, "generate.py"), self.data, str(n), "--kind", kind,
                "--seed", str(self.a.seed)])

    def tools(self, n):
        return tool_commands(self.a.trajeval, self.py, self.evo_bin, self.data, n, n <= self.a.max_evo)

    def run_tool(self, name, cmds, n, run):
        """Returns a sample {wall_s, rss_bytes, cpu_s, other_cpu_s, load1, waited_s} and the output path."""
        x = {"wall_s": 0.0, "rss_bytes": 0, "cpu_s": 0.0, "other_cpu_s": 0.0}
        slug = re.sub(r"[^a-z0-9]+", "-", name.lower()).strip("-")
        x["waited_s"] = wait_quiet(self.a.quiet_wait) if self.a.quiet_wait > 0 else 0.0
        x["load1"] = load1()
        for k, cmd in enumerate(cmds):
            base = f"{self.work}/{slug}_{n}_{run}_{k}"
            w, r, c, o = timed(cmd, base + ".out", base + ".log")
            x["wall_s"] += w
            x["rss_bytes"] = max(x["rss_bytes"], r)
            x["cpu_s"] += c
            x["other_cpu_s"] += o
        return x, f"{self.work}/{slug}_{n}_{run}_0.out"

    def baseline(self):
        n = 1000
        self.gen(n, "planar")
        self.gen(n, "planar-tum")
        self.gen(n, "spatial")
        base = {}
        for name, cmds in self.tools(n).items():
            rs = [self.run_tool(name, cmds, n, r)[0]["rss_bytes"] for r in range(3)]
            base[name] = statistics.median(rs)
        return base

    def agreement(self, n, outputs):
        res = {}
        t, p = outputs.get("trajeval (1 core)"), outputs.get("numpy lesson")
        r = subprocess.run([self.py, os.path.join(HERE, "compare.py"), "lesson", t, p],
                           capture_output=True, text=True)
        res["lesson"] = {"ok": r.returncode == 0, "detail": r.stdout.strip()}
        if n <= self.a.max_check:
            self.gen(n, "spatial")
            d, w = self.data, self.work
            rt, et = f"{d}/spatial_{n}_ref.tum", f"{d}/spatial_{n}_est.tum"
            tj = f"{w}/check_{n}_trajeval.json"
            with open(tj, "w") as f:
                sh([self.a.trajeval, "eval", rt, et, "--convention", "evo", "--align", "se3", "--format", "tum",
                    "--json"], stdout=f)
            for z in (f"{w}/check_{n}_ape.zip", f"{w}/check_{n}_rpe.zip"):
                if os.path.exists(z):
                    os.remove(z)
            sh([f"{self.evo_bin}/evo_ape", "tum", rt, et, "-a", "--no_warnings", "--save_results",
                f"{w}/check_{n}_ape.zip"], stdout=subprocess.DEVNULL)
            sh([f"{self.evo_bin}/evo_rpe", "tum", rt, et, "-a", "--delta", "1", "--delta_unit", "f",
                "--no_warnings", "--save_results", f"{w}/check_{n}_rpe.zip"], stdout=subprocess.DEVNULL)
            r = subprocess.run([self.py, os.path.join(HERE, "compare.py"), "evo", tj,
                                f"{w}/check_{n}_ape.zip", f"{w}/check_{n}_rpe.zip"], capture_output=True, text=True)
            res["evo"] = {"ok": r.returncode == 0, "detail": r.stdout.strip()}
        return res

    def recheck(self):
        """Re-runs the agreement checks on the outputs of the last timed run (no new timing)."""
        path = os.path.join(self.work, "bench.json")
        result = json.load(open(path))
        checks = {}
        for n in sorted({row["poses"] for row in result["rows"]}):
            last = result["runs"] - 1
            outputs = {"trajeval (1 core)": f"{self.work}/trajeval-1-core_{n}_{last}_0.out",
                       "numpy lesson": f"{self.work}/numpy-lesson_{n}_{last}_0.out"}
            checks[n] = self.agreement(n, outputs)
            for k, v in checks[n].items():
                print(f"  {fmt_n(n):>5} agreement with {k}: {'OK' if v['ok'] else 'MISMATCH'}\n" + v["detail"])
        result["agreement"] = {str(k): v for k, v in checks.items()}
        result["agreement_rechecked"] = datetime.datetime.now().astimezone().isoformat(timespec="seconds")
        self.finish(result, checks)

    def finish(self, result, checks):
        with open(os.path.join(self.work, "bench.json"), "w") as f:
            json.dump(result, f, indent=1)
        table = markdown(result)
        with open(os.path.join(self.work, "bench.md"), "w") as f:
            f.write(table)
        print(table)
        if self.a.readme:
            splice(self.a.readme, table)
        if not all(v["ok"] for c in checks.values() for v in c.values()):
            sys.exit(1)

    def main(self):
        a = self.a
        if a.recheck:
            self.recheck()
            return
        print("baseline: each tool on a 1000-pose pair", flush=True)
        base = self.baseline()
        rows, checks = [], {}
        for n in a.sizes:
            self.gen(n, "planar")
            self.gen(n, "spatial")
            if n <= a.max_evo:
                self.gen(n, "planar-tum")
            tools = self.tools(n)
            names = [k for k in RUN_ORDER if k in tools]
            samples = {k: [] for k in names}
            outputs = {}
            runs = a.runs_at.get(n, a.runs)
            for run in range(runs):
                order = names[run % len(names):] + names[:run % len(names)]
                for name in order:
                    if name in EVO_TOOLS and len(samples[name]) >= a.evo_runs:
                        continue
                    x, out = self.run_tool(name, tools[name], n, run)
                    samples[name].append(x)
                    outputs[name] = out
                    print(f"  {fmt_n(n):>5} run {run + 1}/{runs} {name:32s} {x['wall_s']:8.2f} s "
                          f"{x['rss_bytes'] / 2**20:8.0f} MiB  CPU {x['cpu_s']:6.2f} s  others {x['other_cpu_s']:5.2f} s  "
                          f"load {x['load1']:.2f}" + (f"  (waited {x['waited_s']:.1f} s)" if x["waited_s"] >= 1 else ""),
                          flush=True)
            checks[n] = self.agreement(n, outputs)
            for k, v in checks[n].items():
                print(f"  {fmt_n(n):>5} agreement with {k}: {'OK' if v['ok'] else 'MISMATCH'}\n" + v["detail"])
            t_ref = statistics.median(x["wall_s"] for x in samples["trajeval (1 core)"])
            for name in [k for k in PLANAR_TOOLS + SPATIAL_TOOLS if samples.get(k)]:
                col = {k: [x[k] for x in samples[name]] for k in samples[name][0]}
                wall = statistics.median(col["wall_s"])
                rss = statistics.median(col["rss_bytes"])
                rows.append({"poses": n, "tool": name, "runs": len(col["wall_s"]), "median_wall_s": wall,
                             "walls_s": col["wall_s"], "peak_rss_bytes": rss,
                             "median_cpu_s": statistics.median(col["cpu_s"]), "cpus_s": col["cpu_s"],
                             "median_other_cpu_s": statistics.median(col["other_cpu_s"]),
                             "other_cpus_s": col["other_cpu_s"], "loads1": col["load1"],
                             "poses_per_s": n / wall, "bytes_per_pose_above_baseline": (rss - base[name]) / n,
                             "baseline_rss_bytes": base[name], "time_ratio_vs_trajeval_1core": wall / t_ref})
        result = {"date": datetime.datetime.now().astimezone().isoformat(timespec="seconds"),
                  "machine": machine(), "runs": a.runs, "runs_at": {str(k): v for k, v in a.runs_at.items()},
                  "evo_runs": a.evo_runs, "quiet_wait_s": a.quiet_wait, "max_evo": a.max_evo,
                  "max_check": a.max_check, "seed": a.seed, "rows": rows,
                  "agreement": {str(k): v for k, v in checks.items()},
                  "commands": {k: [" ".join(c).replace(HERE, "bench/python") for c in v] for k, v in
                               tool_commands("trajeval", "python", "", "DATA", "N", True).items()}}
        if a.pipeline or a.backlog:
            result.update(pipeline_rows.measure(
                a, lambda: wait_quiet(a.quiet_wait) if a.quiet_wait > 0 else 0.0))
        self.finish(result, checks)

def machine():
    cpu = open("/proc/cpuinfo").read()
    model = re.search(r"model name\s*:\s*(.*)", cpu).group(1).strip()
    cores = len(re.findall(r"^processor\s*:", cpu, re.M))
    mem = subprocess.run(["free", "-h"], capture_output=True, text=True).stdout.splitlines()[1].split()[1]
    java = subprocess.run(["java", "-version"], capture_output=True, text=True).stderr.splitlines()[1].strip()
    vers = {}
    for mod in ("numpy", "pandas", "evo"):
        try:
            vers[mod] = __import__(mod).__version__
        except Exception:  # a missing module is reported, not fatal
            vers[mod] = "?"
    return {"cpu": model, "logical_cpus": cores, "memory": mem, "os": platform.platform(), "java": java,
            "python": platform.python_version(), **vers}


def markdown(r):
    m = r["machine"]
    lines = [f"Measured {r['date']} on {m['cpu']}, {m['logical_cpus']} logical CPUs, {m['memory']} RAM, "
             f"{m['os']}; {m['java']}; Python {m['python']}, numpy {m['numpy']}, pandas {m['pandas']}, "
             f"evo {m['evo']}. Median of {runs_text(r)} per tool and size"
             + (f" (evo: its first {r['evo_runs']}, `--evo-runs`)" if "evo_runs" in r else "")
             + ", all tools of a size in one rotation (each 3D case next to the planar case with the same "
             "threads, so that their ratio divides runs seconds apart; the first tool moves by one each run)"
             + (f", each run started once the machine had been idle for 0.5 s (waiting at most "
                f"{r['quiet_wait_s']:g} s; `--quiet-wait`)" if r.get("quiet_wait_s") else "")
             + f"; evo run up to {fmt_n(r['max_evo'])} poses (`--max-evo`). CPU is the tool's user + sys; "
             "others' CPU is what other processes used during its runs (median; a busy minute slows the "
             "tool that uses both cores most).",
             "",
             "| poses | tool | median wall (s) | wall min-max (s) | CPU (s) | others' CPU (s) | poses/s | peak RSS (MiB) "
             "| B/pose above baseline | time / trajeval (1 core) |",
             "| ---: | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |"]
    for row in r["rows"]:
        cpu = f"{row['median_cpu_s']:.2f}" if "median_cpu_s" in row else "-"
        other = f"{row['median_other_cpu_s']:.2f}" if "median_other_cpu_s" in row else "-"
        lines.append(f"| {fmt_n(row['poses'])} | {row['tool']} | {row['median_wall_s']:.2f} | "
                     f"{min(row['walls_s']):.2f}-{max(row['walls_s']):.2f} | {cpu} | {other} | "
                     f"{row['poses_per_s']:,.0f} | {row['peak_rss_bytes'] / 2**20:,.0f} | "
                     f"{row['bytes_per_pose_above_baseline']:,.0f} | {row['time_ratio_vs_trajeval_1core']:.1f}x |")
    lines.append("")
    lines.append("Baselines (peak RSS on a 1000-pose pair): " + ", ".join(
        f"{row['tool']} {row['baseline_rss_bytes'] / 2**20:.0f} MiB" for row in r["rows"]
        if row["poses"] == r["rows"][0]["poses"]) + ".")
    lines.append("")
    lines.append("Agreement (" + ("re-checked on the same outputs " + r["agreement_rechecked"]
                                  if "agreement_rechecked" in r else "checked in the same run") + "):")
    for n, c in r["agreement"].items():
        for k, v in c.items():
            what = ("trajeval --convention lesson vs numpy lesson (planar CSV)" if k == "lesson"
                    else "trajeval --convention evo --align se3 vs evo_ape -a / evo_rpe -a --delta 1 --delta_unit f (3D TUM)")
            worst = max((float(x) for x in re.findall(r"difference ([0-9.e+-]+)", v["detail"])), default=0.0)
            lines.append(f"- {fmt_n(int(n))}: {what}: {'agree' if v['ok'] else 'MISMATCH'}, "
                         f"worst relative difference {worst:.1e}")
    if "commands" in r:
        lines += ["", "What each row runs (DATA: the seeded pairs of `bench/python/generate.py`, N: poses; "
                  "a row of two commands adds their wall and CPU times and takes the larger peak RSS):"]
        lines += [f"- {k}: " + " + ".join(f"`{c}`" for c in v) for k, v in r["commands"].items()]
    lines += pipeline_rows.markdown(r, fmt_n)
    lines += [""] + issue15_targets.markdown(r)
    return "\n".join(lines) + "\n"


def runs_text(r):
    by_size = {int(k): v for k, v in r.get("runs_at", {}).items()}
    if not by_size:
        return f"{r['runs']} runs"
    return f"{r['runs']} runs (" + ", ".join(f"{fmt_n(k)}: {v}" for k, v in sorted(by_size.items())) + ")"


def splice(readme, table):
    start, end = "<!-- bench-table:start -->", "<!-- bench-table:end -->"
    text = open(readme).read()
    i, j = text.find(start), text.find(end)
    if i < 0 or j < 0:
        raise SystemExit(f"{readme}: markers {start} / {end} not found")
    with open(readme, "w") as f:
        f.write(text[:i + len(start)] + "\n" + table + text[j:])


def parse_args():
    ap = argparse.ArgumentParser()
    ap.add_argument("--trajeval", required=True)
    ap.add_argument("--python", default=sys.executable)
    ap.add_argument("--sizes", default="10000,100000,1000000,10000000")
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--runs-at", dest="runs_at_list", action="append", default=[], metavar="POSES=RUNS",
                    help="runs for one size instead of --runs, e.g. 1000000=9 (repeatable)")
    ap.add_argument("--quiet-wait", type=float, default=10.0, metavar="SECONDS",
                    help="before each run, wait up to this long for 0.5 s of idle machine (0: never wait)")
    ap.add_argument("--max-evo", type=int, default=1_000_000)
    ap.add_argument("--evo-runs", type=int, default=1, metavar="RUNS",
                    help="runs of each evo row per size (3D evo takes 1-2 min per run at 10^6)")
    ap.add_argument("--pipeline", type=int, default=0, metavar="BUNDLES",
                    help="add the pipeline rows: drain of BUNDLES 10^4-pose 3D bundles and eval --batch (0: off)")
    ap.add_argument("--pipeline-runs", type=int, default=3)
    ap.add_argument("--pipeline-workers", type=int, default=0, help="--workers of the drain (0: its default)")
    ap.add_argument("--backlog", action="store_true",
                    help="add the backlog rows: peak RSS of a drain of 10^5 over 10^3 100-pose bundles (~5 min)")
    ap.add_argument("--trajeval-pipeline", default=None)
    ap.add_argument("--pipeline-data", default=os.path.join(os.environ.get("TMPDIR", "/tmp"),
                                                            "trajeval-pipeline-bench"))
    ap.add_argument("--max-check", type=int, default=100_000)
    ap.add_argument("--seed", type=int, default=20240605)
    ap.add_argument("--data", default="bench/data")
    ap.add_argument("--results", default="bench/results")
    ap.add_argument("--readme", default=None)
    ap.add_argument("--recheck", action="store_true",
                    help="re-run only the agreement checks on the saved outputs of the last run")
    a = ap.parse_args()
    if a.evo_runs < 0 or a.runs < 1:
        ap.error("--runs wants at least 1, --evo-runs at least 0")
    if (a.pipeline or a.backlog) and not a.trajeval_pipeline:
        ap.error("--pipeline and --backlog need --trajeval-pipeline")
    a.sizes = [int(float(s)) for s in a.sizes.split(",")]
    a.runs_at = {}
    for item in a.runs_at_list:
        size, _, runs = item.partition("=")
        if not runs.isdigit() or int(runs) < 1:
            ap.error(f"--runs-at wants POSES=RUNS, found {item!r}")
        a.runs_at[int(float(size))] = int(runs)
    return a


if __name__ == "__main__":
    Bench(parse_args()).main()
