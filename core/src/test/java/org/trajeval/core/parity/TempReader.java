package org.trajeval.core.parity;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.trajeval.core.io.LoadedTrajectory;
import org.trajeval.core.io.TrajectoryFormat;
import org.trajeval.core.traj.SpatialTrajectory;

/** TEMPORARY: until the io branch lands. */
final class TempReader {
    static LoadedTrajectory read(Path p, TrajectoryFormat f) {
        try {
            List<double[]> rows = new ArrayList<>();
            for (String line : Files.readAllLines(p)) {
                line = line.trim();
                if (line.isEmpty() || line.startsWith("#")) continue;
                String[] parts = line.split(f == TrajectoryFormat.EUROC ? "," : "\\s+");
                double[] v = new double[parts.length];
                for (int i = 0; i < parts.length; i++) v[i] = Double.parseDouble(parts[i].trim());
                rows.add(v);
            }
            int n = rows.size();
            double[] t = new double[n], x = new double[n], y = new double[n], z = new double[n];
            if (f == TrajectoryFormat.KITTI) {
                double[] r = new double[9 * n];
                for (int i = 0; i < n; i++) {
                    double[] v = rows.get(i);
                    t[i] = i;
                    x[i] = v[3]; y[i] = v[7]; z[i] = v[11];
                    int[] idx = {0, 1, 2, 4, 5, 6, 8, 9, 10};
                    for (int k = 0; k < 9; k++) r[9 * i + k] = v[idx[k]];
                }
                return new LoadedTrajectory(p.toString(), f, "temp", SpatialTrajectory.ofMatrices(t, x, y, z, r), "", true);
            }
            double[] qw = new double[n], qx = new double[n], qy = new double[n], qz = new double[n];
            for (int i = 0; i < n; i++) {
                double[] v = rows.get(i);
                if (f == TrajectoryFormat.EUROC) {
                    t[i] = v[0] / 1e9; x[i] = v[1]; y[i] = v[2]; z[i] = v[3];
                    qw[i] = v[4]; qx[i] = v[5]; qy[i] = v[6]; qz[i] = v[7];
                } else {
                    t[i] = v[0]; x[i] = v[1]; y[i] = v[2]; z[i] = v[3];
                    qx[i] = v[4]; qy[i] = v[5]; qz[i] = v[6]; qw[i] = v[7];
                }
            }
            return new LoadedTrajectory(p.toString(), f, "temp", SpatialTrajectory.of(t, x, y, z, qw, qx, qy, qz), "", false);
        } catch (java.io.IOException e) {
            throw new java.io.UncheckedIOException(e);
        }
    }
}
