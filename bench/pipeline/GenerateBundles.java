import java.io.BufferedWriter;
import java.io.IOException;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Random;

/**
 * Seeded 3D run bundles for the pipeline benchmarks (bench/pipeline-throughput.sh,
 * bench/pipeline-backlog.sh); run with the JDK's source launcher, no build needed:
 *
 * <pre>java bench/pipeline/GenerateBundles.java OUT BUNDLES POSES [SEED]</pre>
 *
 * Writes {@code OUT/run-NNNNNN/} (run.yaml, gt.tum, est.tum) and the marker
 * {@code OUT/run-NNNNNN.done} for each bundle, and {@code OUT.pairs.csv} (name,ref,est: the same
 * pairs for {@code trajeval eval --batch}). Bundle k uses seed SEED + k, so every bundle holds
 * different numbers. Reference: 100 Hz, t = 1000 + 0.01 i s, a smooth 3D path
 * (x = 0.5 s + 2 sin(0.15 s), y = 1.5 cos(0.10 s), z = 0.2 sin(s / 50), yaw = heading, pitch and
 * roll wobbling by 0.05 rad); estimate: stamps 3 ms later, the true pose there turned by 0.3 rad
 * about z and moved by (5, -2, 0.5) m, plus seeded noise of 0.02 m and 0.005 rad. TUM lines
 * {@code t x y z qx qy qz qw}. The bundle has no metrics: the service's default (lesson) preset.
 */
public final class GenerateBundles {
    public static void main(String[] args) throws IOException {
        if (args.length < 3) {
            System.err.println("usage: java GenerateBundles.java OUT BUNDLES POSES [SEED]");
            System.exit(2);
        }
        Path out = Path.of(args[0]);
        int bundles = Integer.parseInt(args[1]);
        int poses = Integer.parseInt(args[2]);
        long seed = args.length > 3 ? Long.parseLong(args[3]) : 20261123L;
        Files.createDirectories(out);
        Path pairs = out.resolveSibling(out.getFileName() + ".pairs.csv");
        try (BufferedWriter table = Files.newBufferedWriter(pairs, StandardCharsets.UTF_8)) {
            table.write("name,ref,est\n");
            for (int k = 0; k < bundles; k++) {
                String name = String.format("run-%06d", k);
                Path b = out.resolve(name);
                Files.createDirectories(b);
                Random rnd = new Random(seed + k);
                write(b.resolve("gt.tum"), poses, false, rnd);
                write(b.resolve("est.tum"), poses, true, rnd);
                Files.writeString(b.resolve("run.yaml"), "run_id: " + name + "\nrobot_id: bot-" + (k % 7)
                        + "\nsequence: loop\nmethod: bench\nseed: " + (seed + k) + "\nreference: gt.tum\nestimate: est.tum\n");
                Files.writeString(out.resolve(name + ".done"), "");
                table.write(name + "," + b.resolve("gt.tum").toAbsolutePath() + "," + b.resolve("est.tum").toAbsolutePath()
                        + "\n");
            }
        }
    }

    private static void write(Path file, int poses, boolean estimate, Random rnd) throws IOException {
        double theta = 0.3;
        double c = Math.cos(theta);
        double sn = Math.sin(theta);
        StringBuilder line = new StringBuilder(128);
        try (Writer w = Files.newBufferedWriter(file, StandardCharsets.US_ASCII)) {
            for (int i = 0; i < poses; i++) {
                double s = i * 0.01 + (estimate ? 0.003 : 0.0);
                double x = 0.5 * s + 2.0 * Math.sin(0.15 * s);
                double y = 1.5 * Math.cos(0.10 * s);
                double z = 0.2 * Math.sin(s / 50.0);
                double yaw = Math.atan2(-0.15 * Math.sin(0.10 * s), 0.5 + 0.3 * Math.cos(0.15 * s));
                double pitch = 0.05 * Math.sin(s / 3.0);
                double roll = 0.05 * Math.cos(s / 4.0);
                if (estimate) {
                    double xn = x + 0.02 * rnd.nextGaussian();
                    double yn = y + 0.02 * rnd.nextGaussian();
                    x = c * xn - sn * yn + 5.0;
                    y = sn * xn + c * yn - 2.0;
                    z = z + 0.5 + 0.02 * rnd.nextGaussian();
                    yaw = yaw + theta + 0.005 * rnd.nextGaussian();
                    pitch += 0.005 * rnd.nextGaussian();
                    roll += 0.005 * rnd.nextGaussian();
                }
                // q = Rz(yaw) Ry(pitch) Rx(roll) as a unit quaternion (x, y, z, w)
                double cy = Math.cos(yaw / 2), sy = Math.sin(yaw / 2);
                double cp = Math.cos(pitch / 2), sp = Math.sin(pitch / 2);
                double cr = Math.cos(roll / 2), sr = Math.sin(roll / 2);
                double qw = cr * cp * cy + sr * sp * sy;
                double qx = sr * cp * cy - cr * sp * sy;
                double qy = cr * sp * cy + sr * cp * sy;
                double qz = cr * cp * sy - sr * sp * cy;
                line.setLength(0);
                fixed(line, 1000.0 + s, 6).append(' ');
                fixed(line, x, 6).append(' ');
                fixed(line, y, 6).append(' ');
                fixed(line, z, 6).append(' ');
                fixed(line, qx, 9).append(' ');
                fixed(line, qy, 9).append(' ');
                fixed(line, qz, 9).append(' ');
                fixed(line, qw, 9).append('\n');
                w.append(line);
            }
        }
    }

    /** Appends v with {@code digits} decimals (rounded half away from zero), without String.format's cost. */
    private static StringBuilder fixed(StringBuilder sb, double v, int digits) {
        long scale = 1;
        for (int d = 0; d < digits; d++) {
            scale *= 10;
        }
        long r = Math.round(Math.abs(v) * scale);
        if (v < 0 && r != 0) {
            sb.append('-');
        }
        sb.append(r / scale).append('.');
        String frac = Long.toString(r % scale);
        for (int d = frac.length(); d < digits; d++) {
            sb.append('0');
        }
        return sb.append(frac);
    }
}
