package org.trajeval.pipeline;

import java.io.IOException;
import java.io.OutputStream;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import java.util.Random;
import java.util.zip.ZipEntry;
import java.util.zip.ZipOutputStream;

/** Writes run bundles for tests: planar CSV trajectories, folders, zips, bare pairs and markers. */
public final class Fixtures {
    private Fixtures() {
    }

    /**
     * Writes a {@code t,x,y,yaw} CSV of a circle-ish drive at 10 Hz, with seeded noise of
     * {@code noiseM} (m) added to x and y.
     */
    public static void writeTrajectory(Path file, int poses, double noiseM, long seed) {
        Random rnd = new Random(seed);
        StringBuilder sb = new StringBuilder("t,x,y,yaw\n");
        for (int i = 0; i < poses; i++) {
            double t = i * 0.1;
            double a = t * 0.2;
            double x = 10 * Math.cos(a) + noiseM * rnd.nextGaussian();
            double y = 10 * Math.sin(a) + noiseM * rnd.nextGaussian();
            double yaw = Math.atan2(Math.sin(a + Math.PI / 2), Math.cos(a + Math.PI / 2));
            sb.append(String.format(Locale.ROOT, "%.3f,%.6f,%.6f,%.6f%n", t, x, y, yaw));
        }
        write(file, sb.toString());
    }

    /** @return the run.yaml text of a run */
    public static String manifest(String runId, String robot, String ref, String est) {
        return "run_id: " + runId + "\nrobot_id: " + robot + "\nsequence: loop\nmethod: test\nseed: 1\nreference: " + ref
                + "\nestimate: " + est + "\n";
    }

    /** Writes a folder bundle {@code dir/NAME/} with run.yaml, gt.csv and est.csv (no marker). */
    public static Path folderBundle(Path dir, String name, String runId, int poses, long seed) {
        Path b = dir.resolve(name);
        writeTrajectory(b.resolve("gt.csv"), poses, 0.0, seed);
        writeTrajectory(b.resolve("est.csv"), poses, 0.05, seed + 1000);
        write(b.resolve("run.yaml"), manifest(runId, "bot-" + (seed % 5), "gt.csv", "est.csv"));
        return b;
    }

    /** Writes a zip bundle {@code dir/NAME.zip} (no marker). */
    public static Path zipBundle(Path dir, String name, String runId, int poses, long seed) {
        Path tmp = dir.resolveSibling(dir.getFileName() + "-ziptmp-" + name);
        Path b = folderBundle(tmp, name, runId, poses, seed);
        Path zip = dir.resolve(name + ".zip");
        try (ZipOutputStream z = new ZipOutputStream(Files.newOutputStream(zip))) {
            for (String f : new String[] {"run.yaml", "gt.csv", "est.csv"}) {
                z.putNextEntry(new ZipEntry(f));
                z.write(Files.readAllBytes(b.resolve(f)));
                z.closeEntry();
            }
            deleteTree(tmp);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        return zip;
    }

    /** Writes a bare pair {@code NAME.gt.csv + NAME.est.csv} (no marker). */
    public static void pair(Path dir, String name, int poses, long seed) {
        writeTrajectory(dir.resolve(name + ".gt.csv"), poses, 0.0, seed);
        writeTrajectory(dir.resolve(name + ".est.csv"), poses, 0.05, seed + 1000);
    }

    /** Writes the marker {@code NAME.done}. */
    public static void marker(Path dir, String name) {
        write(dir.resolve(name + ".done"), "");
    }

    /** Writes a zip with the given entries (name, bytes). */
    public static void zip(Path zip, Object... nameThenBytes) {
        try (OutputStream o = Files.newOutputStream(zip); ZipOutputStream z = new ZipOutputStream(o)) {
            for (int i = 0; i < nameThenBytes.length; i += 2) {
                z.putNextEntry(new ZipEntry((String) nameThenBytes[i]));
                z.write((byte[]) nameThenBytes[i + 1]);
                z.closeEntry();
            }
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /** Writes text, creating the folders. */
    public static void write(Path file, String text) {
        try {
            Files.createDirectories(file.toAbsolutePath().getParent());
            Files.writeString(file, text, StandardCharsets.UTF_8);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /** Deletes a tree (tests' temporary folders). */
    public static void deleteTree(Path root) throws IOException {
        if (!Files.exists(root)) {
            return;
        }
        try (var s = Files.walk(root)) {
            for (Path p : (Iterable<Path>) s.sorted(java.util.Comparator.reverseOrder())::iterator) {
                Files.deleteIfExists(p);
            }
        }
    }
}
