package org.trajeval.store;

import java.time.Instant;
import java.util.Map;

/** Hand-made run records for the store tests. */
final class Records {
    private Records() {
    }

    /** A successful run with ATE translation RMSE {@code ate} (m) recorded at {@code atMs}. */
    static RunRecord run(int id, String robot, String route, String version, long seed, double ate, long atMs,
            Map<String, String> tags) {
        return new RunRecord(ReportRecords.sha256("test", Integer.toString(id)), "pipeline", "r" + id, 1, null, null,
                robot, "site-a", route, "orb", version, seed, Instant.ofEpochMilli(atMs), true, null,
                Map.of("ate_trans_rmse_m", ate, "rpe_trans_rmse_m", ate / 2), "test", tags);
    }
}
