"""The lesson's planar evaluation (section 10 of the lesson), vectorised with numpy.

Same mathematics as the lesson's Python, with the corrections of shared/seed/NOTES.md:
  * the reference is interpolated at the estimate's stamps (x, y linear; yaw through cos/sin,
    then atan2), after cropping the estimate to the reference's time span (the lesson refuses
    any stamp outside it and crashes on its own demo data);
  * the SE(2) alignment (closed-form 2D Umeyama/Kabsch without scale) is applied to whole
    poses: positions p -> R p + t AND yaw -> yaw + theta;
  * ATE: |p_est - p_ref| (m) and |wrap(yaw_est - yaw_ref)| (rad) per pose;
  * RPE over delta = 1 s: for every i, j = first index with t_j >= t_i + delta (j < n);
    trans error |d_est - d_ref| of the body-frame relative translations (m), rot error
    |wrap(dyaw_est - dyaw_ref)| (rad).
No Python loop over poses: every step is a numpy array operation.

Usage: lesson_numpy.py REF.csv EST.csv [--delta 1.0]   (prints one JSON object)
"""
import argparse
import json

import numpy as np
import pandas as pd


def load(path):
    df = pd.read_csv(path, engine="c", dtype=np.float64)
    t = df["t"].to_numpy()
    cols = [t, df["x"].to_numpy(), df["y"].to_numpy(), df["yaw"].to_numpy()]
    if np.any(np.diff(t) < 0):  # the lesson sorts by t
        order = np.argsort(t, kind="stable")
        cols = [c[order] for c in cols]
    return cols


def wrap(a):
    return (a + np.pi) % (2.0 * np.pi) - np.pi


def stats(e):
    n = e.size
    sse = float(np.dot(e, e))
    return {"rmse": float(np.sqrt(sse / n)), "mean": float(np.mean(e)), "median": float(np.median(e)),
            "std": float(np.std(e)), "min": float(np.min(e)), "max": float(np.max(e)), "sse": sse, "n": n}


def evaluate(ref_path, est_path, delta):
    tr, xr, yr, yawr = load(ref_path)
    te, xe, ye, yawe = load(est_path)
    inside = (te >= tr[0]) & (te <= tr[-1])
    dropped = int(te.size - np.count_nonzero(inside))
    te, xe, ye, yawe = te[inside], xe[inside], ye[inside], yawe[inside]

    # reference at the estimate's stamps
    xg = np.interp(te, tr, xr)
    yg = np.interp(te, tr, yr)
    yawg = np.arctan2(np.interp(te, tr, np.sin(yawr)), np.interp(te, tr, np.cos(yawr)))

    # SE(2) alignment fitted on positions, applied to whole poses
    ex, ey = xe - xe.mean(), ye - ye.mean()
    gx, gy = xg - xg.mean(), yg - yg.mean()
    theta = np.arctan2(np.dot(ex, gy) - np.dot(ey, gx), np.dot(ex, gx) + np.dot(ey, gy))
    c, s = np.cos(theta), np.sin(theta)
    tx = xg.mean() - (c * xe.mean() - s * ye.mean())
    ty = yg.mean() - (s * xe.mean() + c * ye.mean())
    xa = c * xe - s * ye + tx
    ya = s * xe + c * ye + ty
    yawa = yawe + theta

    ate_trans = np.hypot(xa - xg, ya - yg)
    ate_rot = np.abs(wrap(yawa - yawg))

    # RPE: every start pose i, j = first sample with t_j >= t_i + delta
    n = te.size
    j = np.searchsorted(te, te + delta, side="left")
    i = np.nonzero(j < n)[0]
    j = j[i]

    def rel(x, y, yaw):
        dxw, dyw = x[j] - x[i], y[j] - y[i]
        ci, si = np.cos(yaw[i]), np.sin(yaw[i])
        return ci * dxw + si * dyw, -si * dxw + ci * dyw, wrap(yaw[j] - yaw[i])

    dxe, dye, dthe = rel(xa, ya, yawa)
    dxg, dyg, dthg = rel(xg, yg, yawg)
    rpe_trans = np.hypot(dxe - dxg, dye - dyg)
    rpe_rot = np.abs(wrap(dthe - dthg))
    return {
        "association": {"matched": int(n), "dropped": dropped},
        "max_abs_coordinate_m": float(max(np.max(np.abs(xr)), np.max(np.abs(yr)), np.max(np.abs(xe)), np.max(np.abs(ye)))),
        "alignment": {"theta_rad": float(theta), "translation_m": [float(tx), float(ty)]},
        "ate": {"trans_m": stats(ate_trans), "rot_rad": stats(ate_rot)},
        "rpe": {"trans_m": stats(rpe_trans), "rot_rad": stats(rpe_rot), "pairs": int(i.size)},
    }


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("ref")
    ap.add_argument("est")
    ap.add_argument("--delta", type=float, default=1.0)
    a = ap.parse_args()
    print(json.dumps(evaluate(a.ref, a.est, a.delta), indent=1))


if __name__ == "__main__":
    main()
