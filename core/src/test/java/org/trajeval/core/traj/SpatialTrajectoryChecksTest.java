package org.trajeval.core.traj;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.util.function.Consumer;
import org.junit.jupiter.api.Test;

/**
 * The checks of {@link SpatialTrajectory#ofFirst}: which refusal a column of quaternion poses
 * gets. The expected messages follow from the order of the checks, by hand: timestamps first
 * (finite, then not decreasing, pose by pose), then each column's finiteness (x, y, z, qw, qx,
 * qy, qz), then the quaternion norms.
 */
class SpatialTrajectoryChecksTest {
    private static final int N = 12;

    /** Columns t, x, y, z, qw, qx, qy, qz of N valid poses, then {@code fault} applied. */
    private static String refusal(Consumer<double[][]> fault) {
        double[][] c = new double[8][N + 3]; // spare capacity past n, as readers hand over
        for (int i = 0; i < N; i++) {
            c[0][i] = 0.1 * i;
            c[1][i] = i;
            c[2][i] = -i;
            c[3][i] = 2.5;
            c[4][i] = 1.0;
        }
        c[4][N] = Double.NaN; // past n: never looked at
        fault.accept(c);
        return assertThrows(IllegalArgumentException.class,
                () -> SpatialTrajectory.ofFirst(N, c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7])).getMessage();
    }

    @Test
    void validColumnsAreKeptAsGivenIncludingEqualTimestampsAndSparePastN() {
        double[][] c = new double[8][N + 3];
        for (int i = 0; i < N; i++) {
            c[0][i] = i / 2; // 0, 0, 1, 1, ...: equal neighbours are allowed
            c[7][i] = -1e-150; // tiny, its norm above 0 (1e-300 would square to 0)
        }
        c[1][N] = Double.POSITIVE_INFINITY;
        SpatialTrajectory t = SpatialTrajectory.ofFirst(N, c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7]);
        assertEquals(N, t.size());
        assertEquals(5.0, t.t(N - 1));
        assertEquals(-1e-150, t.qz(N - 1));
    }

    @Test
    void aTimestampThatIsNotFiniteIsNamed() {
        assertEquals("timestamp 4 is not finite: NaN", refusal(c -> c[0][4] = Double.NaN));
        assertEquals("timestamp 0 is not finite: -Infinity", refusal(c -> c[0][0] = Double.NEGATIVE_INFINITY));
    }

    @Test
    void aDecreasingTimestampIsNamedWithTheOneBefore() {
        assertEquals("timestamps must not decrease: t[6] = 0.1 s after t[5] = 0.5 s", refusal(c -> c[0][6] = 0.1));
    }

    @Test
    void aValueThatIsNotFiniteIsNamedByItsIndex() {
        assertEquals("pose[3] is not finite: Infinity", refusal(c -> c[3][3] = Double.POSITIVE_INFINITY));
        assertEquals("pose[11] is not finite: NaN", refusal(c -> c[7][11] = Double.NaN));
    }

    @Test
    void aZeroQuaternionIsNamed() {
        assertEquals("quaternion 9 is zero", refusal(c -> c[4][9] = 0.0));
    }

    @Test
    void ofSeveralFaultsTheFirstCheckInOrderIsReported() {
        // a zero quaternion at 2, a NaN qz at 8, a decreasing stamp at 10: the stamp is checked first
        assertEquals("timestamps must not decrease: t[10] = 0.0 s after t[9] = 0.9 s", refusal(c -> {
            c[4][2] = 0.0;
            c[7][8] = Double.NaN;
            c[0][10] = 0.0;
        }));
        // a zero quaternion at 2 and a NaN qz at 8: finiteness comes before the norms
        assertEquals("pose[8] is not finite: NaN", refusal(c -> {
            c[4][2] = 0.0;
            c[7][8] = Double.NaN;
        }));
        // an infinite x at 7 and an infinite y at 1: x is checked before y
        assertEquals("pose[7] is not finite: Infinity", refusal(c -> {
            c[1][7] = Double.POSITIVE_INFINITY;
            c[2][1] = Double.NEGATIVE_INFINITY;
        }));
    }
}
