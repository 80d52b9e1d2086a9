"""Checks that two tools' numbers agree where their conventions agree.

  compare.py lesson TRAJEVAL.json NUMPY.json     trajeval --convention lesson vs lesson_numpy.py
  compare.py evo TRAJEVAL.json APE.zip RPE.zip   trajeval --convention evo --align se3 vs
                                                 evo_ape -a / evo_rpe -a --delta 1 --delta_unit f
Tolerance: 1e-9 relative, or an absolute floor for values near zero: 1e-12 rad for angles; for
distances (lesson check) the difference of the two tools' fitted alignments carried to the
farthest point, |dt| + |dtheta| X + 4 eps X (X the largest coordinate, eps = 2.2e-16), at least
1e-12 m. Why: the alignment's translation is a mean of n coordinates; numpy sums pairwise, a
plain loop left to right, so the two translations differ by ~sqrt(n) eps X (5e-11 m at 10^6
poses of 5000 m), which moves every aligned position alike. That is invisible in rmse or mean
(1e-9 relative) but decides the last digits of a minimum ATE of 5e-5 m. The floor and the
alignment difference are printed.
"""
import json
import math
import sys
import zipfile

REL_TOL = 1e-9
ABS_TOL = 1e-12
KEYS = ("rmse", "mean", "median", "std", "min", "max")


def close(a, b, abs_tol):
    return abs(a - b) <= max(abs_tol, REL_TOL * max(abs(a), abs(b)))


def check(label, mine, theirs, keys, failures, abs_tol=ABS_TOL):
    worst = 0.0
    worst_abs = [0.0]
    for k in keys:
        a, b = float(mine[k]), float(theirs[k])
        if not close(a, b, abs_tol):
            failures.append(f"{label}.{k}: trajeval {a!r} vs {b!r}")
        if REL_TOL * max(abs(a), abs(b)) >= abs_tol:  # where the relative criterion governs
            worst = max(worst, abs(a - b) / max(abs(a), abs(b)))
        else:
            worst_abs[0] = max(worst_abs[0], abs(a - b))
    print(f"{label:28s} agree: worst relative difference {worst:.2e} (where the relative criterion "
          f"governs; absolute floor {abs_tol:.1e})")


def lesson(trajeval_path, numpy_path):
    t = json.load(open(trajeval_path))
    p = json.load(open(numpy_path))
    failures = []
    x = p["max_abs_coordinate_m"]
    rot = t["alignment"]["rotation"]
    d_theta = abs(math.atan2(rot[1][0], rot[0][0]) - p["alignment"]["theta_rad"])
    d_t = math.hypot(t["alignment"]["translation_m"][0] - p["alignment"]["translation_m"][0],
                     t["alignment"]["translation_m"][1] - p["alignment"]["translation_m"][1])
    distance_floor = max(ABS_TOL, d_t + d_theta * x + 4 * 2.220446049250313e-16 * x)
    print(f"alignments differ by {d_t:.1e} m, {d_theta:.1e} rad; coordinates up to {x:.0f} m")
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
