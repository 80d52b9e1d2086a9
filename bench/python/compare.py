"""Checks that two tools' numbers agree where their conventions agree.

  compare.py lesson TRAJEVAL.json NUMPY.json     trajeval --convention lesson vs lesson_numpy.py
  compare.py evo TRAJEVAL.json APE.zip RPE.zip   trajeval --convention evo --align se3 vs
                                                 evo_ape -a / evo_rpe -a --delta 1 --delta_unit f
Tolerance: 1e-9 relative, or an absolute floor for values near zero: 1e-12 rad for angles, and
for distances 1e-12 m or 1e-14 x the largest coordinate of the pair, whichever is larger (~45 ulp
of that coordinate). A minimum ATE of 1.5e-4 m is the difference of coordinates of ~500 m; the
two tools fit the alignment with sums in a different order, which moves every aligned position
by a few 1e-13 m, so only the absolute floor is meaningful there.
Prints one line per compared statistic family and the worst relative difference; exit 1 on a
mismatch.
"""
import json
import sys
import zipfile

REL_TOL = 1e-9
ABS_TOL = 1e-12
KEYS = ("rmse", "mean", "median", "std", "min", "max")


def close(a, b, abs_tol):
    return abs(a - b) <= max(abs_tol, REL_TOL * max(abs(a), abs(b)))


def check(label, mine, theirs, keys, failures, abs_tol=ABS_TOL):
    worst = 0.0
    for k in keys:
        a, b = float(mine[k]), float(theirs[k])
        if not close(a, b, abs_tol):
            failures.append(f"{label}.{k}: trajeval {a!r} vs {b!r}")
        if max(abs(a), abs(b)) > 0:
            worst = max(worst, abs(a - b) / max(abs(a), abs(b)))
    print(f"{label:28s} agree: worst relative difference {worst:.2e}")


def lesson(trajeval_path, numpy_path):
    t = json.load(open(trajeval_path))
    p = json.load(open(numpy_path))
    failures = []
    distance_floor = max(ABS_TOL, 1e-14 * p["max_abs_coordinate_m"])
    for m in ("ate", "rpe"):
        for part in ("trans_m", "rot_rad"):
            check(f"{m}.{part}", t[m][part], p[m][part], KEYS, failures,
                  distance_floor if part == "trans_m" else ABS_TOL)
            if t[m][part]["n"] != p[m][part]["n"]:
                failures.append(f"{m}.{part}.n: {t[m][part]['n']} vs {p[m][part]['n']}")
    if t["association"]["matched"] != p["association"]["matched"]:
        failures.append("matched counts differ")
    return failures


def evo_stats(zip_path):
    with zipfile.ZipFile(zip_path) as z:
        return json.loads(z.read("stats.json"))


def evo(trajeval_path, ape_zip, rpe_zip):
    t = json.load(open(trajeval_path))
    failures = []
    check("ate.trans_m vs evo_ape", t["ate"]["trans_m"], evo_stats(ape_zip), KEYS + ("sse",), failures)
    check("rpe.trans_m vs evo_rpe", t["rpe"]["trans_m"], evo_stats(rpe_zip), KEYS + ("sse",), failures)
    return failures


def main():
    kind = sys.argv[1]
    failures = lesson(*sys.argv[2:4]) if kind == "lesson" else evo(*sys.argv[2:5])
    for f in failures:
        print("MISMATCH " + f)
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
