package org.trajeval.core.protocol;

import java.util.Locale;
import org.trajeval.core.report.EvaluationReport;

/**
 * A lower-is-better scalar taken from one run's {@link EvaluationReport}; the names (with their
 * units) are the keys used in manifests and reports.
 */
public enum RunMetric {
    /** ATE translation RMSE (m). */
    ATE_TRANS_RMSE_M,
    /** ATE translation mean (m). */
    ATE_TRANS_MEAN_M,
    /** ATE rotation RMSE (rad). */
    ATE_ROT_RMSE_RAD,
    /** RPE translation RMSE (m). */
    RPE_TRANS_RMSE_M,
    /** RPE rotation RMSE (rad). */
    RPE_ROT_RMSE_RAD,
    /** KITTI-style drift, mean translational error per segment length (%); needs drift settings. */
    DRIFT_TRANS_PCT;

    /** @return the key: ate_trans_rmse_m, ... */
    public String key() {
        return name().toLowerCase(Locale.ROOT);
    }

    /** @return the metric with that key, or {@code null} */
    public static RunMetric fromKey(String key) {
        for (RunMetric m : values()) {
            if (m.key().equals(key)) {
                return m;
            }
        }
        return null;
    }

    /** @return the unit: m, rad or % */
    public String unit() {
        String k = key();
        return k.substring(k.lastIndexOf('_') + 1).replace("pct", "%");
    }

    /** @return the metric's value in {@code r}, or NaN when the report does not hold it */
    public double of(EvaluationReport r) {
        return switch (this) {
            case ATE_TRANS_RMSE_M -> r.ate() == null ? Double.NaN : value(r.ate().transM().rmse());
            case ATE_TRANS_MEAN_M -> r.ate() == null ? Double.NaN : value(r.ate().transM().mean());
            case ATE_ROT_RMSE_RAD -> r.ate() == null ? Double.NaN : value(r.ate().rotRad().rmse());
            case RPE_TRANS_RMSE_M -> r.rpe() == null ? Double.NaN : value(r.rpe().transM().rmse());
            case RPE_ROT_RMSE_RAD -> r.rpe() == null ? Double.NaN : value(r.rpe().rotRad().rmse());
            case DRIFT_TRANS_PCT -> r.drift() == null ? Double.NaN : r.drift().transPct();
        };
    }

    private static double value(Double d) {
        return d == null ? Double.NaN : d;
    }
}
