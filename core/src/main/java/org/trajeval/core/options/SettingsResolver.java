package org.trajeval.core.options;

import java.util.Locale;
import org.trajeval.core.InputException;
import org.trajeval.core.align.AlignmentModel;
import org.trajeval.core.assoc.AssociationMethod;
import org.trajeval.core.assoc.MaxGap;
import org.trajeval.core.assoc.OverlapPolicy;
import org.trajeval.core.eval.Convention;
import org.trajeval.core.eval.TimeOffset;
import org.trajeval.core.eval.EvaluationOptions;
import org.trajeval.core.eval.PlanarProjection;
import org.trajeval.core.io.CsvLayout;
import org.trajeval.core.io.DuplicateTimestamps;
import org.trajeval.core.io.ReadOptions;
import org.trajeval.core.io.TimeUnit;
import org.trajeval.core.io.TimestampOrder;
import org.trajeval.core.io.TrajectoryFormat;
import org.trajeval.core.io.bag.BagIntegrity;
import org.trajeval.core.io.bag.BagReadOptions;
import org.trajeval.core.io.bag.StampSource;
import org.trajeval.core.metric.DriftOptions;
import org.trajeval.core.metric.PairSelection;
import org.trajeval.core.metric.PairsFrom;
import org.trajeval.core.metric.RpeUnit;

/**
 * Turns checked settings into read options (per file) and evaluation options (per data kind),
 * the same way for every front end: the convention's preset for the data (lesson: se2 for
 * planar data, se3 for SE(3) data; {@code planar} counts as planar data), then each given
 * setting. Defaults that depend on the convention: duplicates (evo: keep), RPE horizon (a new
 * rpe_unit without rpe_delta means 1 of that unit), drift (kitti: on).
 */
public final class SettingsResolver {
    private SettingsResolver() {
    }

    /** @return the convention of the settings (when not given: evo when a bag topic is given, as evo_ape bag; else lesson) */
    public static Convention convention(SettingValues s) {
        if (s.has(Setting.CONVENTION)) {
            return Convention.valueOf(upper(Setting.CONVENTION, s));
        }
        return s.has(Setting.REF_TOPIC) || s.has(Setting.EST_TOPIC) ? Convention.EVO : Convention.LESSON;
    }

    /**
     * @param s the settings
     * @param role which file
     * @param base options to start from (size limits of the front end)
     * @param paths how path settings become files
     * @return the read options of that file
     * @throws InputException from {@code paths}
     */
    public static ReadOptions readOptions(SettingValues s, FileRole role, ReadOptions base, PathResolver paths) {
        Setting ownFormat = role == FileRole.REFERENCE ? Setting.REF_FORMAT : Setting.EST_FORMAT;
        String format = (String) (s.has(ownFormat) ? s.get(ownFormat) : s.get(Setting.FORMAT));
        ReadOptions o = base.withFormat(format == null || format.equals("auto") ? null
                : TrajectoryFormat.valueOf(format.toUpperCase(Locale.ROOT).replace('-', '_')));
        CsvLayout d = base.csv();
        String[] columns = (String[]) s.get(Setting.COLUMNS);
        String delimiter = (String) s.get(Setting.DELIMITER);
        TimeUnit unit = s.has(Setting.TIME_UNIT) ? TimeUnit.valueOf(upper(Setting.TIME_UNIT, s)) : d.timeUnit();
        o = o.withCsv(columns == null && delimiter == null && unit == d.timeUnit() ? d
                : new CsvLayout(columns != null ? columns[0] : d.timeColumn(), columns != null ? columns[1] : d.xColumn(),
                        columns != null ? columns[2] : d.yColumn(), columns != null ? columns[3] : d.yawColumn(),
                        delimiter != null ? delimiter.charAt(0) : d.delimiter(), unit));
        if (Boolean.TRUE.equals(s.get(Setting.SORT))) {
            o = o.withOrder(TimestampOrder.SORT);
        }
        DuplicateTimestamps dup = s.has(Setting.DUPLICATES)
                ? DuplicateTimestamps.valueOf(upper(Setting.DUPLICATES, s))
                : convention(s) == Convention.EVO ? DuplicateTimestamps.KEEP : DuplicateTimestamps.REFUSE;
        o = o.withDuplicates(dup);
        Setting topic = role == FileRole.REFERENCE ? Setting.REF_TOPIC : Setting.EST_TOPIC;
        if (s.has(topic) || s.has(Setting.STAMPS) || s.has(Setting.POSE_FIELD) || s.has(Setting.BAG_CRC)) {
            BagReadOptions b = base.bag() != null ? base.bag() : BagReadOptions.DEFAULT;
            o = o.withBag(new BagReadOptions(s.has(topic) ? (String) s.get(topic) : b.topic(),
                    s.has(Setting.STAMPS) ? ("log".equals(s.get(Setting.STAMPS)) ? StampSource.LOG_TIME
                            : StampSource.HEADER) : b.stamps(),
                    s.has(Setting.POSE_FIELD) ? (String) s.get(Setting.POSE_FIELD) : b.poseField(), b.limits(),
                    s.has(Setting.BAG_CRC) ? BagIntegrity.valueOf(upper(Setting.BAG_CRC, s)) : b.integrity()));
        }
        Setting times = role == FileRole.REFERENCE ? Setting.REF_TIMES : Setting.EST_TIMES;
        if (s.has(times)) {
            o = o.withKittiTimes(paths.resolve((String) s.get(times), s.where(times)));
        }
        return o;
    }

    /**
     * @param s the settings
     * @param kind the data: planar or SE(3) (after reading both files)
     * @return the evaluation options
     * @throws InputException on settings that exclude each other
     */
    public static EvaluationOptions evaluationOptions(SettingValues s, DataKind kind) {
        boolean planar = Boolean.TRUE.equals(s.get(Setting.PLANAR));
        if (planar && s.has(Setting.PROJECT_TO_PLANE)) {
            throw bad(s, Setting.PROJECT_TO_PLANE, "'" + s.where(Setting.PROJECT_TO_PLANE) + "' (projection after "
                    + "alignment) and '" + s.where(Setting.PLANAR) + "' (before alignment) exclude each other; "
                    + "choose one", (String) s.get(Setting.PROJECT_TO_PLANE));
        }
        EvaluationOptions o = EvaluationOptions.preset(convention(s), planar || kind == DataKind.PLANAR);
        if (s.has(Setting.ASSOCIATION)) {
            o = o.withAssociation(AssociationMethod.valueOf(upper(Setting.ASSOCIATION, s)));
        }
        if (s.has(Setting.MAX_DIFF_S)) {
            o = o.withMaxDiffS((Double) s.get(Setting.MAX_DIFF_S));
        }
        if (s.get(Setting.T_OFFSET_S) instanceof Double offset) {
            o = o.withTOffsetS(offset);
        } else if (s.has(Setting.T_OFFSET_S)) {
            o = o.withTimeOffset(TimeOffset.AUTO);
        }
        if (s.get(Setting.MAX_GAP_S) instanceof Double gap) {
            o = o.withMaxGap(MaxGap.ofSeconds(gap));
        }
        if (s.has(Setting.OVERLAP)) {
            o = o.withOverlap(OverlapPolicy.valueOf(upper(Setting.OVERLAP, s)));
        }
        if (s.has(Setting.ALIGNMENT)) {
            o = o.withAlignment(AlignmentModel.valueOf(upper(Setting.ALIGNMENT, s)));
        }
        if (s.has(Setting.N_TO_ALIGN)) {
            o = o.withNToAlign((Integer) s.get(Setting.N_TO_ALIGN));
        }
        if (planar) {
            o = o.withProjection(PlanarProjection.XY_BEFORE_ALIGNMENT);
        } else if (s.has(Setting.PROJECT_TO_PLANE)) {
            o = o.withProjection("xy".equals(s.get(Setting.PROJECT_TO_PLANE)) ? PlanarProjection.XY_AFTER_ALIGNMENT
                    : PlanarProjection.XZ_AFTER_ALIGNMENT);
        }
        o = rpe(s, o);
        if (Boolean.TRUE.equals(s.get(Setting.EXTRA_METRICS))) {
            o = o.withExtraMetrics(true);
        }
        if (s.has(Setting.RPE_PAIRS)) {
            o = o.withPairSelection("all-pairs".equals(s.get(Setting.RPE_PAIRS)) ? PairSelection.ALL_PAIRS
                    : PairSelection.CONSECUTIVE);
        }
        if (s.has(Setting.PAIRS_FROM)) {
            o = o.withPairsFrom(PairsFrom.valueOf(upper(Setting.PAIRS_FROM, s)));
        }
        return drift(s, o);
    }

    private static EvaluationOptions rpe(SettingValues s, EvaluationOptions o) {
        if (!s.has(Setting.RPE_DELTA) && !s.has(Setting.RPE_UNIT)) {
            return o;
        }
        RpeUnit unit = o.rpeUnit();
        if (s.has(Setting.RPE_UNIT)) {
            for (RpeUnit u : RpeUnit.values()) {
                if (u.symbol().equals(s.get(Setting.RPE_UNIT))) {
                    unit = u;
                }
            }
        }
        double delta = s.has(Setting.RPE_DELTA) ? (Double) s.get(Setting.RPE_DELTA)
                : unit == o.rpeUnit() ? o.rpeDelta() : 1.0;
        if (unit == RpeUnit.FRAMES && delta != Math.rint(delta)) {
            throw bad(s, Setting.RPE_DELTA, "'" + s.where(Setting.RPE_DELTA) + "' must be a whole number of frames "
                    + "(rpe_unit frames)", Double.toString(delta));
        }
        return o.withRpe(delta, unit);
    }

    private static EvaluationOptions drift(SettingValues s, EvaluationOptions o) {
        boolean tuned = s.has(Setting.DRIFT_SEGMENT_LENGTHS_M) || s.has(Setting.DRIFT_STEP_FRAMES);
        if (Boolean.FALSE.equals(s.get(Setting.DRIFT))) {
            if (tuned) {
                Setting t = s.has(Setting.DRIFT_STEP_FRAMES) ? Setting.DRIFT_STEP_FRAMES
                        : Setting.DRIFT_SEGMENT_LENGTHS_M;
                throw bad(s, t, "'" + s.where(t) + "' needs drift, which '" + s.where(Setting.DRIFT)
                        + "' turns off", "false");
            }
            return o.withDrift(null);
        }
        if (!tuned && !Boolean.TRUE.equals(s.get(Setting.DRIFT))) {
            return o;
        }
        DriftOptions base = o.drift() != null ? o.drift() : DriftOptions.KITTI;
        double[] lengths = s.has(Setting.DRIFT_SEGMENT_LENGTHS_M) ? (double[]) s.get(Setting.DRIFT_SEGMENT_LENGTHS_M)
                : base.segmentLengthsM();
        int step = s.has(Setting.DRIFT_STEP_FRAMES) ? (Integer) s.get(Setting.DRIFT_STEP_FRAMES) : base.stepFrames();
        return o.withDrift(new DriftOptions(lengths, step));
    }

    /**
     * @return the lengths of the relative errors per sub-trajectory length (m), or null for the
     *     default (10 ... 50 % of the reference path, {@code SubTrajectoryErrors})
     */
    public static double[] subTrajectoryLengthsM(SettingValues s) {
        return s.has(Setting.SUBTRAJ_LENGTHS_M) ? ((double[]) s.get(Setting.SUBTRAJ_LENGTHS_M)).clone() : null;
    }

    private static String upper(Setting setting, SettingValues s) {
        return ((String) s.get(setting)).toUpperCase(Locale.ROOT).replace('-', '_');
    }

    private static InputException bad(SettingValues s, Setting setting, String detail, String found) {
        return new InputException(s.source(), 0, s.where(setting), Setting.problem(s.source()), detail, found);
    }
}
