package org.trajeval.store;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.time.Clock;
import java.time.Instant;
import java.time.ZoneOffset;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class TrendTest {
    private static final Clock CLOCK = Clock.fixed(Instant.parse("2026-11-23T08:00:00Z"), ZoneOffset.UTC);
    private static final long DAY_MS = 86_400_000L;
    private static final double P_TOL = 1e-12;

    /** 3 robots, 10 days, 20 runs a day, ATE ~ N(0.10 m, 0.01 m); bot-2's last day shifted by {@code shift} m. */
    private static List<RunRecord> fleet(double shift, long seed) {
        Random rnd = new Random(seed);
        List<RunRecord> out = new ArrayList<>();
        int id = 0;
        for (int robot = 1; robot <= 3; robot++) {
            for (int day = 0; day < 10; day++) {
                for (int k = 0; k < 20; k++) {
                    double ate = 0.10 + 0.01 * rnd.nextGaussian() + (robot == 2 && day == 9 ? shift : 0.0);
                    out.add(Records.run(id++, "bot-" + robot, "hall", "2.4", k, ate, day * DAY_MS + k * 1000L,
                            Map.of()));
                }
            }
        }
        return out;
    }

    private static Trend.Result trend(Path dir, List<RunRecord> runs) {
        try (ResultsStore s = ResultsStore.open(StoreLocation.sqlite(dir.resolve("t.db")), CLOCK)) {
            s.record(runs);
            return Trend.of(s, "ate_trans_rmse_m", "robot", TrendBucket.DAY, Selection.all(), 0, 0.95);
        }
    }

    @Test
    void aRobotWhoseLatestDayIsWorseIsFlaggedAndNoOtherIs(@TempDir Path dir) {
        Trend.Result r = trend(dir, fleet(0.02, 1));
        assertEquals(3, r.slices().size());
        for (Trend.Slice s : r.slices()) {
            assertEquals(10, s.points().size());
            assertEquals("1970-01-10", s.latest().bucket());
            assertEquals(180, s.historyN());
            assertEquals(s.slice().equals("bot-2"), s.flagged(), s.slice() + " p " + s.adjustedP());
        }
    }

    @Test
    void aSteadyFleetRaisesNoFlag(@TempDir Path dir) {
        Trend.Result r = trend(dir, fleet(0.0, 2));
        assertTrue(r.slices().stream().noneMatch(Trend.Slice::flagged));
    }

    @Test
    void aBetterLatestDayIsNoFlag(@TempDir Path dir) {
        Trend.Result r = trend(dir, fleet(-0.02, 3));
        assertFalse(r.slices().stream().anyMatch(Trend.Slice::flagged));
    }

    @Test
    void untestedSlicesStayOutOfTheHolmFamily() {
        // Holm 1979 / statsmodels multipletests(method="holm"): p = (0.01, 0.04, 0.03) -> (0.03, 0.06, 0.06);
        // the untested slices (NaN) neither count in m = 3 nor get an adjusted p
        assertArrayEquals(new double[] {Double.NaN, 0.03, 0.06, Double.NaN, 0.06},
                Trend.holmOverTested(new double[] {Double.NaN, 0.01, 0.04, Double.NaN, 0.03}), P_TOL);
    }
}
