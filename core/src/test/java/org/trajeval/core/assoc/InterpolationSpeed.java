package org.trajeval.core.assoc;

import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.nio.file.Path;
import java.util.Locale;
import org.trajeval.core.io.ReadOptions;
import org.trajeval.core.io.TrajectoryReader;
import org.trajeval.core.traj.SpatialTrajectory;

/**
 * Not a test: the SE(3) interpolated reference alone, in one warm JVM, timed by this thread's CPU
 * time (so that other processes on a shared machine count less than in wall time). Each run
 * fills the brackets of every estimate stamp inside the reference's span, then asks the poses as
 * the lesson's RPE over 1 s does on 100 Hz data (rotation of i, of i + 100, of i again for the
 * ATE, positions of both); prints ns per pose for each run and the minimum, and a checksum of
 * the values (equal for two builds that give the same bits).
 *
 * <pre>
 * gradle :core:testClasses :cli:installDist
 * java -cp "core/build/classes/java/test:cli/build/install/trajeval/lib/*" \
 *     org.trajeval.core.assoc.InterpolationSpeed REF.tum EST.tum 10
 * </pre>
 */
public final class InterpolationSpeed {
    /** Poses between an RPE pair's start and end (1 s at 100 Hz). */
    private static final int LAG = 100;

    private InterpolationSpeed() {
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
        ThreadMXBean cpu = ManagementFactory.getThreadMXBean();
        double best = Double.POSITIVE_INFINITY;
        double checksum = 0.0;
        double[] ri = new double[9];
        double[] rj = new double[9];
        for (int run = 0; run < runs; run++) {
            long c0 = cpu.getCurrentThreadCpuTime();
            InterpolatedReference r = InterpolatedReference.spatial(ref, m);
            r.fill(k -> est.t(first + k), 0, m);
            InterpolatedReference.Cursor cursor = new InterpolatedReference.Cursor();
            double sum = 0.0;
            for (int i = 0; i + LAG < m; i++) {
                r.rotation(i, ri, 0, cursor);
                r.rotation(i + LAG, rj, 0, cursor);
                r.rotation(i, ri, 0, cursor);
                sum += ri[0] + rj[4] + r.x(i) + r.y(i + LAG) + r.z(i);
            }
            double ns = (cpu.getCurrentThreadCpuTime() - c0) / (double) m;
            best = Math.min(best, ns);
            checksum = sum;
            System.out.printf(Locale.ROOT, "run %d: %.1f ns/pose%n", run + 1, ns);
        }
        System.out.printf(Locale.ROOT, "minimum %.1f ns/pose over %d poses; checksum %s%n", best, m, checksum);
    }
}
