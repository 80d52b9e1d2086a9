package org.trajeval.core.io.bag;

import java.util.Arrays;

/**
 * Growing primitive columns of poses read from a bag: time (s), position (m), quaternion (w, x, y, z).
 * Doubling growth up to the message limit.
 */
final class PoseColumns {
    double[] t = new double[1024];
    double[] x = new double[1024];
    double[] y = new double[1024];
    double[] z = new double[1024];
    double[] qw = new double[1024];
    double[] qx = new double[1024];
    double[] qy = new double[1024];
    double[] qz = new double[1024];
    int n;

    void add(double time, double px, double py, double pz, double w, double ix, double iy, double iz) {
        if (n == t.length) {
            int c = (int) Math.min((long) n * 2, Integer.MAX_VALUE - 16);
            t = Arrays.copyOf(t, c);
            x = Arrays.copyOf(x, c);
            y = Arrays.copyOf(y, c);
            z = Arrays.copyOf(z, c);
            qw = Arrays.copyOf(qw, c);
            qx = Arrays.copyOf(qx, c);
            qy = Arrays.copyOf(qy, c);
            qz = Arrays.copyOf(qz, c);
        }
        t[n] = time;
        x[n] = px;
        y[n] = py;
        z[n] = pz;
        qw[n] = w;
        qx[n] = ix;
        qy[n] = iy;
        qz[n] = iz;
        n++;
    }

    void clear() {
        n = 0;
    }

    /**
     * Trims every column to the pose count, or picks the poses {@code order} lists (in that order,
     * possibly fewer) when not null.
     */
    double[][] columns(int[] order) {
        double[][] all = {t, x, y, z, qw, qx, qy, qz};
        double[][] out = new double[8][];
        for (int c = 0; c < 8; c++) {
            if (order == null) {
                out[c] = Arrays.copyOf(all[c], n);
            } else {
                double[] d = new double[order.length];
                for (int i = 0; i < order.length; i++) {
                    d[i] = all[c][order[i]];
                }
                out[c] = d;
            }
        }
        return out;
    }
}
