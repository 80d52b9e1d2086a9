package org.trajeval.pipeline;

import java.util.Locale;
import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;

/**
 * Optional metric settings of a run ({@code metrics:} in run.yaml); a {@code null} field keeps
 * the default of the convention.
 *
 * @param convention lesson (default), evo or kitti
 * @param alignment none, se2, sim2, se3, sim3, origin, posyaw
 * @param association interpolate, nearest, nearest_interpolated
 * @param maxDiffS max timestamp difference for nearest association (s), > 0
 * @param rpeDelta RPE horizon in {@code rpeUnit}, > 0
 * @param rpeUnit s, frames or m
 */
public record MetricSettings(String convention, String alignment, String association, Double maxDiffS,
        Double rpeDelta, String rpeUnit) {

    /** The defaults: the lesson convention's preset. */
    public static final MetricSettings DEFAULTS = new MetricSettings(null, null, null, null, null, null);

    /** @throws InputException on a value outside its set or range (field named) */
    public MetricSettings {
        convention = oneOf("metrics.convention", convention, "lesson", "evo", "kitti");
        alignment = oneOf("metrics.alignment", alignment, "none", "se2", "sim2", "se3", "sim3", "origin", "posyaw");
        association = oneOf("metrics.association", association, "interpolate", "nearest", "nearest_interpolated");
        rpeUnit = oneOf("metrics.rpe_unit", rpeUnit, "s", "frames", "m");
        positive("metrics.max_diff_s", maxDiffS, "(s)");
        positive("metrics.rpe_delta", rpeDelta, "(in rpe_unit)");
    }

    private static String oneOf(String field, String value, String... allowed) {
        if (value == null) {
            return null;
        }
        String v = value.trim().toLowerCase(Locale.ROOT);
        for (String a : allowed) {
            if (a.equals(v)) {
                return v;
            }
        }
        throw new InputException(null, 0, field, InputProblem.INVALID_CONFIGURATION,
                field + " must be one of " + String.join(", ", allowed), value);
    }

    private static void positive(String field, Double value, String unit) {
        if (value != null && !(value > 0 && Double.isFinite(value))) {
            throw new InputException(null, 0, field, InputProblem.INVALID_CONFIGURATION,
                    field + " must be a positive number " + unit, String.valueOf(value));
        }
    }

    /** @return a stable text form, part of the run's content hash */
    public String canonical() {
        return "convention=" + convention + ";alignment=" + alignment + ";association=" + association
                + ";max_diff_s=" + maxDiffS + ";rpe_delta=" + rpeDelta + ";rpe_unit=" + rpeUnit;
    }
}
