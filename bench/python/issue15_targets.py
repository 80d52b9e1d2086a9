"""Issue 15's targets, judged on the rows of one run of run.py: every measured figure is computed
from that run's bench.json (no number typed by hand), each line says measured, target, met or
missed and by how much. Gap = |measured - target| / target (a margin when met).

What each item divides:
- item 1, time: median wall of a 3D trajeval row over that of the planar trajeval row with the same
  threads and the same number of poses (so per pose as well); 2 cores, the threads the targets
  are judged on. Memory: the 3D row's peak RSS above its own 1000-pose baseline, per pose.
  Against evo: evo_ape + evo_rpe (same options) over trajeval's evo convention, se3, 2 cores.
- item 2: 1000 bundles / median wall of the drain, and of eval --batch on the same pairs.
- item 3: median wall of trajeval (2 cores) over that of the numpy lesson, planar pair, cold.
- item 4: 10^7 poses / median wall, planar pair, on one core and on two.
- item 5: peak RSS of the larger backlog's drain over the smaller's.
"""

PLANAR = {1: "trajeval (1 core)", 2: "trajeval (2 cores)"}
THREE_D = {"evo se3": "trajeval 3D evo se3 (2 cores)", "lesson se3": "trajeval 3D lesson se3 (2 cores)"}
EVO_3D = "evo 3D (ape + rpe)"
NUMPY = "numpy lesson"
OPS = {"<=": lambda m, t: m <= t, "<": lambda m, t: m < t, ">=": lambda m, t: m >= t}


def verdict(measured, op, target):
    """'met (margin X %)' or '**missed** by X %', X = |measured - target| / target."""
    gap = abs(measured - target) / target * 100
    pct = f"{gap:.1f} %" if gap < 10 else f"{gap:.0f} %"
    return f"met (margin {pct})" if OPS[op](measured, target) else f"**missed** by {pct}"


def _n(n):
    e = len(str(n)) - 1
    return f"10^{e}" if n == 10 ** e else str(n)


def _x(v):
    return f"{v:.2f}x"


def checks(r):
    """(item, what, measured or None, op, target, format): every target line, in issue order."""
    rows = {(row["poses"], row["tool"]): row for row in r["rows"]}

    def wall(n, tool):
        return rows[(n, tool)]["median_wall_s"] if (n, tool) in rows else None

    def ratio(a, b):
        return a / b if a is not None and b is not None else None

    out = []
    for n in (10 ** 6, 10 ** 7):
        for case, tool in THREE_D.items():
            out.append((1, f"{_n(n)} 3D TUM, {case}, 2 cores: time per pose / planar CSV (trajeval 2 cores)",
                        ratio(wall(n, tool), wall(n, PLANAR[2])), "<=", 1.3, _x))
    for n in (10 ** 6, 10 ** 7):
        for case, tool in THREE_D.items():
            b = rows[(n, tool)]["bytes_per_pose_above_baseline"] if (n, tool) in rows else None
            out.append((1, f"{_n(n)} 3D TUM, {case}, 2 cores: peak RSS above the baseline per pose", b, "<=", 200,
                        lambda v: f"{v:.0f} B"))
    out.append((1, "10^6 3D TUM: evo_ape + evo_rpe time / trajeval evo se3 (2 cores)",
                ratio(wall(10 ** 6, EVO_3D), wall(10 ** 6, THREE_D["evo se3"])), ">=", 50, lambda v: f"{v:.1f}x"))
    pipe = {p["case"]: p for p in r.get("pipeline", [])}
    for case, what in (("drain", "trajeval-pipeline watch --drain"), ("batch", "trajeval eval --batch")):
        p = pipe.get(case)
        out.append((2, f"{what}, {p['runs']} x 10^4-pose 3D bundles: runs/s (median)" if p else
                    f"{what}, 10^4-pose 3D bundles: runs/s (median)",
                    p["median_runs_per_s"] if p else None, ">=", 100, lambda v: f"{v:.1f} runs/s"))
    for n, op, target in ((10 ** 4, "<=", 1.5), (10 ** 5, "<", 1.0), (10 ** 6, "<", 1.0)):
        out.append((3, f"{_n(n)} planar CSV: trajeval (2 cores) wall / numpy lesson wall",
                    ratio(wall(n, PLANAR[2]), wall(n, NUMPY)), op, target, _x))
    for threads, target in ((1, 4e6), (2, 6e6)):
        w = wall(10 ** 7, PLANAR[threads])
        out.append((4, f"10^7 planar CSV, {PLANAR[threads]}: poses/s", 1e7 / w if w else None, ">=", target,
                    lambda v: f"{v / 1e6:.2f} M"))
    b = r.get("backlog")
    out.append((5, (f"backlog of {b['large']['bundles']} over {b['small']['bundles']} bundles: peak RSS ratio" if b
                    else "backlog of 10^5 over 10^3 bundles: peak RSS ratio"),
                b["ratio"] if b else None, "<=", 1.2, _x))
    return out


def markdown(r):
    """The generated block under the table: one line per target."""
    lines = ["Issue 15 targets, computed from the rows above (median wall times; "
             "`bench/python/issue15_targets.py` says what each line divides):", ""]
    for item, what, measured, op, target, fmt in checks(r):
        if measured is None:
            lines.append(f"- item {item}, {what}: not measured in this run (target {op} {fmt(target)})")
        else:
            lines.append(f"- item {item}, {what}: {fmt(measured)} (target {op} {fmt(target)}): "
                         f"{verdict(measured, op, target)}")
    return lines
