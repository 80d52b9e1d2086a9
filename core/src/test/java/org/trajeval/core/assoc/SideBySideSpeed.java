package org.trajeval.core.assoc;

import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.nio.file.Path;
import java.util.Locale;
import org.trajeval.core.io.ReadOptions;
import org.trajeval.core.io.TrajectoryReader;
import org.trajeval.core.traj.SpatialTrajectory;

/**
 * Not a test: the SE(3) interpolated reference's rotations one pose at a time
 * ({@link InterpolatedReference#rotationOnce}, poses k and k + 1) against two side by side
 * ({@link InterpolatedReference#rotationsOnce}), alternated run by run in one warm JVM so that both
 * see the same machine; thread CPU time, ns per pose, the minimum of each, and both checksums
 * (equal: the same bits).
 *
 * <pre>
 * java -cp "core/build/classes/java/test:cli/build/install/trajeval/lib/*" \
 *     org.trajeval.core.assoc.SideBySideSpeed REF.tum EST.tum 20
 * </pre>
 */
public final class SideBySideSpeed {
    private SideBySideSpeed() {
    }

    public static void main(String[] args) {
        SpatialTrajectory ref = TrajectoryReader.read(Path.of(args[0]), ReadOptions.defaults()).trajectory()
                .toSpatial();
        SpatialTrajectory est = TrajectoryReader.read(Path.of(args[1]), ReadOptions.defaults()).trajectory()
                .toSpatial();
        int runs = Integer.parseInt(args[2]);
        int k0 = 0;
        while (k0 < est.size() && est.t(k0) < ref.t(0)) {
            k0++;
        }
        int k1 = est.size();
        while (k1 > k0 && est.t(k1 - 1) > ref.t(ref.size() - 1)) {
            k1--;
        }
        int first = k0;
        int m = k1 - k0;
        InterpolatedReference r = InterpolatedReference.spatial(ref, m);
        r.fill(k -> est.t(first + k), 0, m);
        ThreadMXBean cpu = ManagementFactory.getThreadMXBean();
        double[] best = {Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY};
        double[] checksum = new double[2];
        double[] out = new double[18];
        for (int run = 0; run < 2 * runs; run++) {
            int way = run % 2;
            long c0 = cpu.getCurrentThreadCpuTime();
            InterpolatedReference.Cursor cursor = new InterpolatedReference.Cursor();
            double sum = 0.0;
            for (int k = 0; k + 1 < m; k += 2) {
                if (way == 0) {
                    r.rotationOnce(k, out, 0, cursor);
                    r.rotationOnce(k + 1, out, 9, cursor);
                } else {
                    r.rotationsOnce(k, out, 0, 9, cursor);
                }
                sum += out[0] + out[4] + out[13] + out[17];
            }
            double ns = (cpu.getCurrentThreadCpuTime() - c0) / (double) m;
            best[way] = Math.min(best[way], ns);
            checksum[way] = sum;
        }
        System.out.printf(Locale.ROOT, "one at a time %.1f ns/pose, side by side %.1f ns/pose (minima of %d, %d poses);"
                + " checksums %s %s%n", best[0], best[1], runs, m, checksum[0], checksum[1]);
    }
}
