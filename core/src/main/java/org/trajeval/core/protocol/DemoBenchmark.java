package org.trajeval.core.protocol;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.SplittableRandom;
import org.trajeval.core.io.TrajectoryWriter;
import org.trajeval.core.traj.PlanarTrajectory;

/**
 * Writes a seeded synthetic planar benchmark like the lesson's {@code make_demo_data}: smooth
 * reference paths (x = v t + A sin(w t + phi), y = B cos(w2 t + phi2), yaw along the path), and
 * estimates with drift, noise, a slight time warp t + 0.01 sin(0.05 t) and an unknown rigid
 * offset of the estimate's frame (so alignment matters). Three methods of different quality
 * (alpha best, gamma worst) on every sequence and seed; the drift is scaled by a per-sequence
 * difficulty shared by all methods (the gamma_s of Proposition 1).
 *
 * <p>Deliberate defects, so that the report shows them: session {@code s02} has {@code seq03} in
 * val and {@code seq11} in test (leakage, flagged), and gamma loses tracking on seq06 with seed 3
 * (its estimate stops at 40 % of the sequence: a low-coverage failure).
 */
public final class DemoBenchmark {
    /** File name of the manifest the demo writes. */
    public static final String MANIFEST = "suite.yaml";
    /** File name of the split table the demo writes. */
    public static final String SPLITS = "splits.csv";

    private static final int POSES = 600;
    private static final double DT_S = 0.1;
    private static final long[] SEEDS = {1, 2, 3, 4, 5};
    /** id, session, split. */
    private static final String[][] SEQUENCES = {
        {"seq01", "s01", "train"}, {"seq02", "s01", "train"}, {"seq03", "s02", "val"},
        {"seq04", "s03", "test"}, {"seq05", "s03", "test"}, {"seq06", "s04", "test"},
        {"seq07", "s05", "test"}, {"seq08", "s06", "test"}, {"seq09", "s07", "test"},
        {"seq10", "s08", "test"}, {"seq11", "s02", "test"},
    };
    /** name, drift (m/s), position noise (m), yaw noise (rad). */
    private static final Object[][] METHODS = {
        {"alpha", 0.006, 0.02, Math.toRadians(0.5)},
        {"beta", 0.012, 0.05, Math.toRadians(1.0)},
        {"gamma", 0.03, 0.08, Math.toRadians(1.0)},
    };

    private DemoBenchmark() {
    }

    /**
     * Writes references, estimates, the split table and the manifest into {@code dir}.
     *
     * @param dir target folder (created)
     * @param seed the demo's seed: the same seed writes the same bytes
     * @return the manifest file
     */
    public static Path write(Path dir, long seed) {
        try {
            Files.createDirectories(dir);
            SplittableRandom master = new SplittableRandom(seed);
            List<double[][]> references = new ArrayList<>();
            double[] difficulty = new double[SEQUENCES.length];
            for (int s = 0; s < SEQUENCES.length; s++) {
                SplittableRandom rng = master.split();
                difficulty[s] = 0.5 + 1.5 * rng.nextDouble();
                double[][] ref = reference(rng);
                references.add(ref);
                Path file = dir.resolve("data").resolve(SEQUENCES[s][0]).resolve("reference.csv");
                Files.createDirectories(file.getParent());
                TrajectoryWriter.write(PlanarTrajectory.of(ref[0], ref[1], ref[2], ref[3]), file);
            }
            for (Object[] method : METHODS) {
                for (int s = 0; s < SEQUENCES.length; s++) {
                    if (!"test".equals(SEQUENCES[s][2])) {
                        continue;
                    }
                    for (long runSeed : SEEDS) {
                        SplittableRandom rng = new SplittableRandom(mix(seed, (String) method[0], s, runSeed));
                        double[][] est = estimate(references.get(s), rng, (double) method[1] * difficulty[s],
                                (double) method[2], (double) method[3]);
                        if (method[0].equals("gamma") && SEQUENCES[s][0].equals("seq06") && runSeed == 3) {
                            est = truncate(est, (int) (0.4 * POSES));
                        }
                        Path file = dir.resolve("runs").resolve((String) method[0]).resolve(SEQUENCES[s][0])
                                .resolve("seed" + runSeed + ".csv");
                        Files.createDirectories(file.getParent());
                        TrajectoryWriter.write(PlanarTrajectory.of(est[0], est[1], est[2], est[3]), file);
                    }
                }
            }
            Files.writeString(dir.resolve(SPLITS), splits());
            Path manifest = dir.resolve(MANIFEST);
            Files.writeString(manifest, manifest());
            return manifest;
        } catch (IOException e) {
            throw new UncheckedIOException("could not write the demo benchmark into " + dir, e);
        }
    }

    static long mix(long seed, String method, int sequence, long runSeed) {
        long h = seed * 0x9E3779B97F4A7C15L;
        h ^= method.hashCode() * 0xC2B2AE3D27D4EB4FL;
        h ^= (sequence + 1) * 0x165667B19E3779F9L;
        h ^= runSeed * 0x27D4EB2F165667C5L;
        return h;
    }

    /** A smooth path of {@link #POSES} poses. */
    private static double[][] reference(SplittableRandom rng) {
        return reference(rng, POSES);
    }

    /** A smooth path of {@code poses} poses 0.1 s apart, per-sequence shape, yaw from the central-difference velocity. */
    static double[][] reference(SplittableRandom rng, int poses) {
        double v = 0.4 + 0.2 * rng.nextDouble();
        double a = 1.5 + rng.nextDouble();
        double w = 0.1 + 0.1 * rng.nextDouble();
        double b = 1.0 + rng.nextDouble();
        double w2 = 0.08 + 0.06 * rng.nextDouble();
        double phi = rng.nextDouble() * Math.PI;
        double[] t = new double[poses];
        double[] x = new double[poses];
        double[] y = new double[poses];
        double[] yaw = new double[poses];
        for (int i = 0; i < poses; i++) {
            t[i] = i * DT_S;
            x[i] = v * t[i] + a * Math.sin(w * t[i] + phi);
            y[i] = b * Math.cos(w2 * t[i] + phi);
        }
        for (int i = 0; i < poses; i++) {
            int i0 = Math.max(0, i - 1);
            int i1 = Math.min(poses - 1, i + 1);
            yaw[i] = Math.atan2(y[i1] - y[i0], x[i1] - x[i0]);
        }
        return new double[][] {t, x, y, yaw};
    }

    /** Drift + noise + time warp, then an unknown rigid motion of the estimate's frame. */
    static double[][] estimate(double[][] ref, SplittableRandom rng, double driftMps, double noiseM,
            double yawNoiseRad) {
        double theta = (rng.nextDouble() - 0.5) * Math.toRadians(40);
        double ox = (rng.nextDouble() - 0.5) * 4.0;
        double oy = (rng.nextDouble() - 0.5) * 4.0;
        double dirX = rng.nextDouble() - 0.5;
        double c = Math.cos(theta);
        double s = Math.sin(theta);
        int n = ref[0].length;
        double[] t = new double[n];
        double[] x = new double[n];
        double[] y = new double[n];
        double[] yaw = new double[n];
        for (int i = 0; i < n; i++) {
            double ti = ref[0][i];
            t[i] = ti + 0.01 * Math.sin(0.05 * ti);
            double ex = ref[1][i] + driftMps * (0.7 + dirX) * ti + noiseM * rng.nextGaussian();
            double ey = ref[2][i] - driftMps * 0.7 * ti + noiseM * rng.nextGaussian();
            double eyaw = ref[3][i] + Math.toRadians(2.0) * Math.sin(0.2 * ti) + yawNoiseRad * rng.nextGaussian();
            x[i] = c * ex - s * ey + ox;
            y[i] = s * ex + c * ey + oy;
            yaw[i] = eyaw + theta;
        }
        return new double[][] {t, x, y, yaw};
    }

    private static double[][] truncate(double[][] est, int n) {
        double[][] out = new double[4][];
        for (int k = 0; k < 4; k++) {
            out[k] = java.util.Arrays.copyOf(est[k], n);
        }
        return out;
    }

    private static String splits() {
        StringBuilder sb = new StringBuilder("sequence_id,session_id,split\n");
        for (String[] s : SEQUENCES) {
            sb.append(s[0]).append(',').append(s[1]).append(',').append(s[2]).append('\n');
        }
        return sb.toString();
    }

    private static String manifest() {
        StringBuilder sb = new StringBuilder();
        sb.append("# trajeval demo benchmark (synthetic, seeded): three methods, eight test sequences, five seeds.\n");
        sb.append("# Deliberate defects: session s02 is in val (seq03) and test (seq11); gamma/seq06/seed 3 fails.\n");
        sb.append("format: ").append(SuiteManifest.FORMAT).append('\n');
        sb.append("version: ").append(SuiteManifest.FORMAT_VERSION).append('\n');
        sb.append("name: trajeval-demo\n");
        sb.append("seeds: [");
        for (int i = 0; i < SEEDS.length; i++) {
            sb.append(i > 0 ? ", " : "").append(SEEDS[i]);
        }
        sb.append("]\n");
        sb.append("evaluated_splits: [test]\n");
        sb.append("sequences:\n");
        for (String[] s : SEQUENCES) {
            sb.append(String.format(Locale.ROOT, "  - {id: %s, session: %s, reference: data/%s/reference.csv, "
                    + "split: %s, tags: [synthetic, planar]}%n", s[0], s[1], s[0], s[2]));
        }
        sb.append("methods:\n");
        for (Object[] m : METHODS) {
            sb.append("  - {name: ").append(m[0]).append(", estimates: \"runs/{method}/{sequence}/seed{seed}.csv\"}\n");
        }
        sb.append("metrics:\n");
        sb.append("  convention: lesson\n");
        sb.append("  association: interpolate\n");
        sb.append("  overlap: crop\n");
        sb.append("  alignment: se2\n");
        sb.append("  rpe: {delta: 1.0, unit: s, pairs: consecutive}\n");
        sb.append("failure:\n");
        sb.append("  min_coverage: 0.9\n");
        sb.append("  max_ate_trans_rmse_m: 2.0\n");
        sb.append("  divergence_trans_m: 10.0\n");
        sb.append("score:\n");
        sb.append("  - {metric: ate_trans_rmse_m, cap: 2.0, weight: 0.5}\n");
        sb.append("  - {metric: rpe_trans_rmse_m, cap: 0.8, weight: 0.5}\n");
        sb.append("budget: {device: cpu, cores: 2, real_time_factor: 1.0, memory_cap_mib: 2048}\n");
        return sb.toString().replace("\r\n", "\n");
    }
}
