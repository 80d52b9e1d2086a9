package org.trajeval.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.trajeval.core.InputException;
import org.trajeval.core.io.LoadedTrajectory;
import org.trajeval.core.io.ReadOptions;
import org.trajeval.core.traj.SpatialTrajectory;

/**
 * Reading a pair on two threads where the estimate is the bigger file (read on the calling thread, so
 * the pool's thread helps with its blocks once the reference is read): the same values, hashes and
 * refusals as one thread, and the reference's refusal still comes first.
 */
class EvalThreadsTest {
    /** Poses of the big estimate: about 8 MB of TUM, several of the reader's 2 MiB blocks. */
    private static final int BIG = 120_000;

    @TempDir
    Path dir;

    @Test
    void aBigEstimateBesideASmallReferenceReadsAsOneThreadDoes() throws IOException {
        Path ref = tum("ref.tum", 1_000, -1);
        Path est = tum("est.tum", BIG, -1);
        LoadedTrajectory[] one = read(1, ref, est);
        LoadedTrajectory[] two = read(2, ref, est);
        for (int k = 0; k < 2; k++) {
            assertEquals(one[k].sha256(), two[k].sha256());
            assertSameValues((SpatialTrajectory) one[k].trajectory(), (SpatialTrajectory) two[k].trajectory());
        }
        assertEquals(BIG, two[1].trajectory().size());
    }

    @Test
    void theReferencesRefusalComesFirstWhenBothFilesAreBad() throws IOException {
        Path ref = tum("ref.tum", 1_000, 10);
        Path est = tum("est.tum", BIG, 5);
        InputException one = assertThrows(InputException.class, () -> read(1, ref, est));
        InputException two = assertThrows(InputException.class, () -> read(2, ref, est));
        assertEquals(one.getMessage(), two.getMessage());
        assertEquals(ref.toString(), sourceOf(two));
    }

    @Test
    void theEstimatesRefusalWhenOnlyTheEstimateIsBad() throws IOException {
        Path ref = tum("ref.tum", 1_000, -1);
        Path est = tum("est.tum", BIG, BIG - 3);
        InputException one = assertThrows(InputException.class, () -> read(1, ref, est));
        InputException two = assertThrows(InputException.class, () -> read(2, ref, est));
        assertEquals(one.getMessage(), two.getMessage());
        assertEquals(est.toString(), sourceOf(two));
    }

    private static LoadedTrajectory[] read(int threads, Path ref, Path est) {
        try (EvalThreads t = new EvalThreads(threads)) {
            return t.both(ReadOptions.defaults(), ref, ReadOptions.defaults(), est);
        }
    }

    private static String sourceOf(InputException e) {
        String m = e.getMessage();
        return m.substring(0, m.indexOf(':'));
    }

    private static void assertSameValues(SpatialTrajectory a, SpatialTrajectory b) {
        assertEquals(a.size(), b.size());
        for (int i = 0; i < a.size(); i++) {
            double[] u = {a.t(i), a.x(i), a.y(i), a.z(i), a.qw(i), a.qx(i), a.qy(i), a.qz(i)};
            double[] v = {b.t(i), b.x(i), b.y(i), b.z(i), b.qw(i), b.qx(i), b.qy(i), b.qz(i)};
            for (int c = 0; c < u.length; c++) {
                assertEquals(Double.doubleToRawLongBits(u[c]), Double.doubleToRawLongBits(v[c]), "pose " + i);
            }
        }
    }

    /** A TUM file of {@code n} poses on a slow helix, 100 Hz; line {@code bad} (1-based) has 5 fields. */
    private Path tum(String name, int n, int bad) throws IOException {
        StringBuilder s = new StringBuilder(n * 80);
        for (int i = 0; i < n; i++) {
            double t = i * 0.01;
            double h = 0.5 * t;
            s.append(String.format(Locale.ROOT, "%.4f %.6f %.6f %.6f", t, Math.cos(h), Math.sin(h), 0.01 * t));
            if (i + 1 != bad) {
                s.append(String.format(Locale.ROOT, " 0 0 %.9f %.9f", Math.sin(h / 2), Math.cos(h / 2)));
            }
            s.append('\n');
        }
        return Files.writeString(dir.resolve(name), s, StandardCharsets.UTF_8);
    }
}
