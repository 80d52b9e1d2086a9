package org.trajeval.core.report;

import java.util.List;
import java.util.Objects;

/**
 * The errors of one saved evaluation, whoever wrote it (trajeval's {@code --save-series} folder or
 * {@code --out} JSON, or an evo {@code --save_results} archive), as {@code trajeval res} compares
 * them. Rotations are held in rad whatever the source's unit.
 *
 * @param name the name the user gave it (method), or the file name
 * @param source the path as given
 * @param origin "trajeval" or "evo"
 * @param description what the source says it is (evo's title, trajeval's alignment and RPE horizon)
 * @param timeUnit unit of the errors' times: "s", "frame", or null when no times were saved
 * @param errors one entry per error kind present
 * @param segments relative errors per sub-trajectory length (none for evo archives and summaries)
 */
public record ResultSet(String name, String source, String origin, String description, String timeUnit,
        List<Errors> errors, EvaluationSeries.Segments segments) {

    /** @throws NullPointerException on a missing component */
    public ResultSet {
        Objects.requireNonNull(name, "name");
        Objects.requireNonNull(source, "source");
        Objects.requireNonNull(segments, "segments");
        errors = List.copyOf(errors);
    }

    /** A result without sub-trajectory errors. */
    public ResultSet(String name, String source, String origin, String description, String timeUnit,
            List<Errors> errors) {
        this(name, source, origin, description, timeUnit, errors, EvaluationSeries.Segments.NONE);
    }

    /** Error kinds, with their key and label (SI units). */
    public enum Kind {
        ATE_TRANS("ate_trans_m", "ATE translation (m)", false),
        ATE_ROT("ate_rot_rad", "ATE rotation (rad)", true),
        RPE_TRANS("rpe_trans_m", "RPE translation (m)", false),
        RPE_ROT("rpe_rot_rad", "RPE rotation (rad)", true);

        private final String key;
        private final String label;
        private final boolean rotation;

        Kind(String key, String label, boolean rotation) {
            this.key = key;
            this.label = label;
            this.rotation = rotation;
        }

        /** @return report key with unit, e.g. {@code ate_trans_m} */
        public String key() {
            return key;
        }

        /** @return label with unit */
        public String label() {
            return label;
        }

        /** @return true for angles (rad) */
        public boolean rotation() {
            return rotation;
        }
    }

    /**
     * @param kind which error
     * @param stats the statistics as the source stored them (SI units)
     * @param t time of each value from the first pose (s, or frames), or null when not saved
     * @param values the per-pose or per-pair values (SI units), or null when not saved
     */
    public record Errors(Kind kind, EvaluationReport.Stats stats, double[] t, double[] values) {
        /** @throws IllegalArgumentException when t and values differ in length */
        public Errors {
            Objects.requireNonNull(kind, "kind");
            Objects.requireNonNull(stats, "stats");
            if (t != null && values != null && t.length != values.length) {
                throw new IllegalArgumentException(kind.key() + ": " + t.length + " times, " + values.length
                        + " values");
            }
        }
    }

    /** @return the errors of this kind, or null */
    public Errors of(Kind kind) {
        return errors.stream().filter(e -> e.kind() == kind).findFirst().orElse(null);
    }
}
