"""Seeded trajectory pairs for the benchmark (planar CSV, planar TUM export, 3D TUM).

Reference: 100 Hz, t_k = 1000 + 0.01 k s; a smooth path
    x = 0.5 s + 2 sin(0.15 s) + 40 sin(s / 300),  y = 1.5 cos(0.10 s) + 30 cos(s / 500)  (m),
yaw = heading (rad); s = t - 1000.  Estimate: stamps shifted by 3 ms plus a slow 1 ms warp (so
association must interpolate; the last estimate poses fall past the reference and are cropped),
the true pose at those stamps moved by a fixed rigid motion, plus drift and seeded noise.
3D pairs add z = 0.2 sin(s / 50), pitch and roll wobble, and a 3D rigid motion of the estimate.

Usage: generate.py OUT_DIR N [--seed S] [--kind planar|planar-tum|spatial]
Files: planar_N_ref.csv / planar_N_est.csv (t,x,y,yaw), planar_N_ref.tum / planar_N_est.tum
(z = 0, yaw quaternion), spatial_N_ref.tum / spatial_N_est.tum.
"""
import argparse
import os

import numpy as np

CHUNK = 1_000_000


def path(s):
    x = 0.5 * s + 2.0 * np.sin(0.15 * s) + 40.0 * np.sin(s / 300.0)
    y = 1.5 * np.cos(0.10 * s) + 30.0 * np.cos(s / 500.0)
    dx = 0.5 + 0.3 * np.cos(0.15 * s) + (40.0 / 300.0) * np.cos(s / 300.0)
    dy = -0.15 * np.sin(0.10 * s) - (30.0 / 500.0) * np.sin(s / 500.0)
    return x, y, np.arctan2(dy, dx)


def stamps(n, kind):
    s_ref = np.arange(n) * 0.01
    s_est = s_ref + 0.003 + 0.001 * np.sin(s_ref / 7.0)
    return s_ref, s_est


def write_rows(fname, header, cols, fmt, delimiter):
    tmp = fname + ".part"
    with open(tmp, "w") as f:
        if header:
            f.write(header + "\n")
        n = len(cols[0])
        for a in range(0, n, CHUNK):
            block = np.column_stack([c[a:a + CHUNK] for c in cols])
            np.savetxt(f, block, fmt=fmt, delimiter=delimiter)
    os.replace(tmp, fname)


def planar(n, seed):
    rng = np.random.default_rng(seed)
    s_ref, s_est = stamps(n, "planar")
    xr, yr, yawr = path(s_ref)
    xe0, ye0, yawe0 = path(s_est)
    theta, tx, ty = 0.3, 5.0, -2.0
    c, s = np.cos(theta), np.sin(theta)
    # drift grows slowly with time; noise is white
    xd = xe0 + 1e-4 * s_est + 0.02 * rng.standard_normal(n)
    yd = ye0 - 5e-5 * s_est + 0.02 * rng.standard_normal(n)
    yawd = yawe0 + 0.01 * np.sin(0.2 * s_est) + 0.005 * rng.standard_normal(n)
    xe = c * xd - s * yd + tx
    ye = s * xd + c * yd + ty
    yawe = np.arctan2(np.sin(yawd + theta), np.cos(yawd + theta))
    return (1000.0 + s_ref, xr, yr, yawr), (1000.0 + s_est, xe, ye, yawe)


def quat_from_ypr(yaw, pitch, roll):
    cy, sy = np.cos(yaw / 2), np.sin(yaw / 2)
    cp, sp = np.cos(pitch / 2), np.sin(pitch / 2)
    cr, sr = np.cos(roll / 2), np.sin(roll / 2)
    return (cr * cp * cy + sr * sp * sy, sr * cp * cy - cr * sp * sy,
            cr * sp * cy + sr * cp * sy, cr * cp * sy - sr * sp * cy)


def spatial(n, seed):
    rng = np.random.default_rng(seed + 1)
    s_ref, s_est = stamps(n, "spatial")
    out = []
    for s_, noisy in ((s_ref, False), (s_est, True)):
        x, y, yaw = path(s_)
        z = 0.2 * np.sin(s_ / 50.0)
        pitch = 0.05 * np.sin(s_ / 13.0)
        roll = 0.04 * np.cos(s_ / 17.0)
        if noisy:
            x = x + 1e-4 * s_ + 0.02 * rng.standard_normal(n)
            y = y - 5e-5 * s_ + 0.02 * rng.standard_normal(n)
            z = z + 0.01 * rng.standard_normal(n)
            yaw = yaw + 0.005 * rng.standard_normal(n)
        q = quat_from_ypr(yaw, pitch, roll)
        if noisy:
            # rigid motion of the whole estimate: rotation about a tilted axis, then a translation
            ang = 0.4
            ax = np.array([0.6, 0.0, 0.8])
            w0, v = np.cos(ang / 2), np.sin(ang / 2) * ax
            r = np.array([
                [1 - 2 * (v[1]**2 + v[2]**2), 2 * (v[0]*v[1] - v[2]*w0), 2 * (v[0]*v[2] + v[1]*w0)],
                [2 * (v[0]*v[1] + v[2]*w0), 1 - 2 * (v[0]**2 + v[2]**2), 2 * (v[1]*v[2] - v[0]*w0)],
                [2 * (v[0]*v[2] - v[1]*w0), 2 * (v[1]*v[2] + v[0]*w0), 1 - 2 * (v[0]**2 + v[1]**2)]])
            p = r @ np.vstack([x, y, z]) + np.array([[1.0], [-2.0], [0.5]])
            x, y, z = p
            bw, bx, by, bz = q
            q = (w0 * bw - v[0] * bx - v[1] * by - v[2] * bz,
                 w0 * bx + v[0] * bw + v[1] * bz - v[2] * by,
                 w0 * by - v[0] * bz + v[1] * bw + v[2] * bx,
                 w0 * bz + v[0] * by - v[1] * bx + v[2] * bw)
        out.append((1000.0 + s_, x, y, z, q[1], q[2], q[3], q[0]))
    return out[0], out[1]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("out")
    ap.add_argument("n", type=int)
    ap.add_argument("--seed", type=int, default=20240605)
    ap.add_argument("--kind", choices=["planar", "planar-tum", "spatial"], default="planar")
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    n = a.n
    if a.kind in ("planar", "planar-tum"):
        ref, est = planar(n, a.seed)
        for name, tr in (("ref", ref), ("est", est)):
            if a.kind == "planar":
                write_rows(os.path.join(a.out, f"planar_{n}_{name}.csv"), "t,x,y,yaw", tr,
                           ["%.2f" if name == "ref" else "%.6f", "%.6f", "%.6f", "%.9f"], ",")
            else:
                t, x, y, yaw = tr
                z = np.zeros(n)
                zero = np.zeros(n)
                cols = (t, x, y, z, zero, zero, np.sin(yaw / 2), np.cos(yaw / 2))
                write_rows(os.path.join(a.out, f"planar_{n}_{name}.tum"), None, cols,
                           ["%.6f", "%.6f", "%.6f", "%.1f", "%.1f", "%.1f", "%.12f", "%.12f"], " ")
    else:
        ref, est = spatial(n, a.seed)
        for name, tr in (("ref", ref), ("est", est)):
            write_rows(os.path.join(a.out, f"spatial_{n}_{name}.tum"), None, tr,
                       ["%.6f"] * 4 + ["%.12f"] * 4, " ")


if __name__ == "__main__":
    main()
