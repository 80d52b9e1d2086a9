"""The pipeline rows of run.py's table (issue 15, items 2 and 5), measured by pipeline_bench.py's
own drain and batch (which check every run's output) and written as a second table.

--pipeline B: the drain of B seeded 10^4-pose 3D folder bundles (`trajeval-pipeline watch --drain`)
and `trajeval eval --batch` on the same pairs, alternated run by run (drain, batch, batch, drain,
...), --pipeline-runs times; runs/s = B / wall time. --backlog: one drain of a backlog of 10^3 and
one of 10^5 100-pose bundles; their peak RSS ratio. The lock is not taken again: run-benchmarks.sh
runs under it as a whole (a second flock of the same file would wait forever).
"""
import os
import shutil
import statistics
import tempfile

import pipeline_bench

BUNDLE_POSES, BACKLOG_POSES = 10000, 100
BACKLOGS = (("small", 1000), ("large", 100000))


def measure(a, wait):
    """The pipeline entries of bench.json; wait() is called before every timed run (run.py's wait
    for an idle machine, the same rule as for the other tools) and returns the seconds waited."""
    os.makedirs(a.pipeline_data, exist_ok=True)
    scratch = tempfile.mkdtemp(prefix="runs-", dir=a.pipeline_data)

    def timed(run):
        waited = wait()
        x = run()
        x.pop("out", None)
        x["waited_s"] = waited
        return x

    out = {}
    try:
        if a.pipeline:
            template = pipeline_bench.generate(a.pipeline_data, a.pipeline, BUNDLE_POSES)
            cases = {"drain": lambda: pipeline_bench.drain(a.trajeval_pipeline, template, scratch, None,
                                                           a.pipeline_workers, a.pipeline),
                     "batch": lambda: pipeline_bench.batch(a.trajeval, template + ".pairs.csv", scratch, None)}
            samples = {k: [] for k in cases}
            for run in range(a.pipeline_runs):
                for name in (list(cases) if run % 2 == 0 else list(cases)[::-1]):
                    x = timed(cases[name])
                    samples[name].append(x)
                    print(f"  pipeline run {run + 1}/{a.pipeline_runs} {name:6s} {x['wall']:7.2f} s "
                          f"{a.pipeline / x['wall']:6.1f} runs/s  CPU {x['cpu']:6.2f} s  {x['rss']:6.0f} MiB  "
                          f"load {x['load'][0]:.2f}-{x['load'][1]:.2f}", flush=True)
            pipeline_bench.same_ate(samples["drain"][0]["ate"], samples["batch"][0]["ate"])
            out["pipeline"] = [row(k, a.pipeline, v) for k, v in samples.items()]
            out["pipeline_ate_checked"] = len(samples["drain"][0]["ate"])
        if a.backlog:
            backlog = {}
            for key, n in BACKLOGS:
                template = pipeline_bench.generate(a.pipeline_data, n, BACKLOG_POSES)
                x = timed(lambda: pipeline_bench.drain(a.trajeval_pipeline, template, scratch, None,
                                                       a.pipeline_workers, n))
                print(f"  backlog of {n} bundles {x['wall']:7.2f} s  {x['rss']:6.0f} MiB", flush=True)
                backlog[key] = row("drain", n, [x]) | {"bundles": n}
            backlog["ratio"] = backlog["large"]["median_rss_mib"] / backlog["small"]["median_rss_mib"]
            out["backlog"] = backlog
    finally:
        shutil.rmtree(scratch, ignore_errors=True)
    return out


def row(case, bundles, runs):
    """Median and best of pipeline_bench's runs (wall s, CPU s, peak RSS MiB, load before-after)."""
    walls = [x["wall"] for x in runs]
    return {"case": case, "runs": bundles, "samples": len(runs), "median_wall_s": statistics.median(walls),
            "walls_s": walls, "median_runs_per_s": bundles / statistics.median(walls),
            "best_runs_per_s": bundles / min(walls),
            "median_cpu_ms_per_run": statistics.median(x["cpu"] for x in runs) * 1000 / bundles,
            "median_rss_mib": statistics.median(x["rss"] for x in runs), "loads1": [list(x["load"]) for x in runs]}


def markdown(r, fmt_n):
    """The pipeline rows (--pipeline, --backlog) as a second table, with what they run."""
    rows = r.get("pipeline", []) + [r["backlog"][k] for k in ("small", "large") if "backlog" in r]
    if not rows:
        return []
    lines = ["", "Pipeline rows (`--pipeline`, `--backlog`; run at `nice -n 10` by `bench/python/pipeline_bench.py`, "
             "each sample after the same wait for an idle machine; drain and batch alternated, median of the "
             "samples):", "",
             "| case | runs per sample | samples | median wall (s) | wall min-max (s) | runs/s (median) | "
             "runs/s (best) | CPU ms per run | peak RSS (MiB) | load before-after |",
             "| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | --- |"]
    for p in rows:
        what = ({"drain": "trajeval-pipeline watch --drain", "batch": "trajeval eval --batch"}[p["case"]]
                + (f", backlog of {p['bundles']} {BACKLOG_POSES}-pose bundles" if "bundles" in p else
                   f", {fmt_n(BUNDLE_POSES)}-pose 3D bundles"))
        lines.append(f"| {what} | {p['runs']} | {p['samples']} | {p['median_wall_s']:.2f} | "
                     f"{min(p['walls_s']):.2f}-{max(p['walls_s']):.2f} | {p['median_runs_per_s']:.1f} | "
                     f"{p['best_runs_per_s']:.1f} | {p['median_cpu_ms_per_run']:.1f} | {p['median_rss_mib']:.0f} | "
                     + ", ".join(f"{a:.1f}-{b:.1f}" for a, b in p["loads1"]) + " |")
    lines += ["", "- trajeval-pipeline watch --drain: `trajeval-pipeline watch --root R --drain`, R a fresh root whose "
              "`incoming/` holds hard links to the seeded bundles (`bench/pipeline/GenerateBundles.java`: a folder "
              "with a 3D TUM pair and run.yaml; the service's default lesson preset, fsync'd reports and ledger, "
              "atomic moves); default workers unless `--pipeline-workers`"]
    if "pipeline" in r:
        lines.append("- trajeval eval --batch: `trajeval eval --batch PAIRS.csv --reports OUT "
                     + " ".join(pipeline_bench.BATCH_OPTIONS) + "` on the same pairs (one report per pair + summary.csv)")
    if "pipeline_ate_checked" in r:
        lines.append(f"- checked: the drain and eval --batch gave the same ATE RMSE, bit for bit, on "
                     f"{r['pipeline_ate_checked']} reports")
    if "backlog" in r:
        lines.append(f"- backlog: peak RSS of the drain of {r['backlog']['large']['bundles']} bundles / of "
                     f"{r['backlog']['small']['bundles']}: {r['backlog']['ratio']:.2f}x (one run each)")
    return lines
