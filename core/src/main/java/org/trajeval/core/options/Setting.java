package org.trajeval.core.options;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.regex.Pattern;
import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;

/**
 * The one table of evaluation settings shared by every front end: {@code trajeval eval} flags,
 * a suite manifest's {@code metrics}, a bundle's {@code run.yaml} and a Kafka run event. Each
 * setting has a key (files and events, snake_case with its unit: {@code max_diff_s}), a flag
 * (the command line: {@code --max-diff}), a value type, a unit, the values it allows, the
 * formats it applies to and its help text. {@link SettingsResolver} turns the values into
 * read and evaluation options; a new setting is a constant here and a line there.
 */
public enum Setting {
    FORMAT("format", "--format", SettingKind.CHOICE, SettingScope.READ_BOTH,
            "auto|csv|tum|kitti|euroc|nclt|robotcar-ins|robotcar-vo|icl-nuim", "",
            "all", "Format of both files (default auto: detected from extension and content; the report says what "
            + "was chosen and why). nclt, robotcar-ins, robotcar-vo and icl-nuim read those datasets' own files "
            + "(README, \"Datasets\")."),
    REF_FORMAT("ref_format", "--ref-format", SettingKind.CHOICE, SettingScope.READ_REFERENCE,
            "auto|csv|tum|kitti|euroc|nclt|robotcar-ins|robotcar-vo|icl-nuim", "", "all", "Format of the reference when the two differ."),
    EST_FORMAT("est_format", "--est-format", SettingKind.CHOICE, SettingScope.READ_ESTIMATE,
            "auto|csv|tum|kitti|euroc|nclt|robotcar-ins|robotcar-vo|icl-nuim", "", "all", "Format of the estimate when the two differ."),
    TIME_UNIT("time_unit", "--time-unit", SettingKind.CHOICE, SettingScope.READ_BOTH, "s|ms|us|ns", "",
            "csv", "Unit of CSV timestamps (default s)."),
    COLUMNS("columns", "--columns", SettingKind.TEXT, SettingScope.READ_BOTH, "T,X,Y,YAW", "",
            "csv", "CSV column names of time (s), x (m), y (m) and yaw (rad) (default t,x,y,yaw)."),
    DELIMITER("delimiter", "--delimiter", SettingKind.TEXT, SettingScope.READ_BOTH, "CHAR", "",
            "csv", "CSV field delimiter, one character (default ',')."),
    SORT("sort", "--sort", SettingKind.SWITCH, SettingScope.READ_BOTH, "", "", "all",
            "Sort poses by timestamp instead of refusing a decreasing one (duplicates are still refused)."),
    DUPLICATES("duplicates", "--duplicates", SettingKind.CHOICE, SettingScope.READ_BOTH, "refuse|keep", "",
            "all", "Poses with equal timestamps: refuse (default; names both lines) or keep them in file order "
            + "as evo does (default of convention evo)."),
    REF_TIMES("ref_times", "--ref-times", SettingKind.PATH, SettingScope.READ_REFERENCE, "FILE", "s",
            "kitti", "KITTI times file of the reference (one time in s per line)."),
    EST_TIMES("est_times", "--est-times", SettingKind.PATH, SettingScope.READ_ESTIMATE, "FILE", "s",
            "kitti", "KITTI times file of the estimate (one time in s per line)."),
    REF_TOPIC("ref_topic", "--ref-topic", SettingKind.TEXT, SettingScope.READ_REFERENCE, "TOPIC", "", "bag",
            "Topic of the reference when it is a ROS bag (MCAP, ROS 1 bag, rosbag2 sqlite3 file or folder), or a TF "
            + "trajectory /tf:PARENT.CHILD; a path written BAG:TOPIC names it too. A given topic makes evo the "
            + "default convention."),
    EST_TOPIC("est_topic", "--est-topic", SettingKind.TEXT, SettingScope.READ_ESTIMATE, "TOPIC", "", "bag",
            "Topic (or /tf:PARENT.CHILD) of the estimate when it is a bag."),
    STAMPS("stamps", "--stamps", SettingKind.CHOICE, SettingScope.READ_BOTH, "header|log", "", "bag",
            "Times of poses read from bags: header (the messages' header.stamp, default, as evo) or log (the "
            + "recording's log time)."),
    POSE_FIELD("pose_field", "--pose-field", SettingKind.TEXT, SettingScope.READ_BOTH, "FIELD.PATH", "", "bag",
            "Field of a bag message type holding the pose (a geometry_msgs Pose or Transform), for types trajeval "
            + "does not know (it knows PoseStamped, PoseWithCovarianceStamped, TransformStamped, Odometry, Path)."),
    BAG_CRC("bag_crc", "--bag-crc", SettingKind.CHOICE, SettingScope.READ_BOTH, "all|chunks", "", "bag",
            "Checksums an MCAP bag must pass: chunks (default: the summary and every chunk read, so each pose scored "
            + "is checked and only the wanted channels' chunks are touched) or all (the data section CRC too: one "
            + "sequential pass over the whole file, for an archive's integrity check). A CRC of 0 is 'not computed' "
            + "and never compared."),
    CONVENTION("convention", "--convention", SettingKind.CHOICE, SettingScope.EVALUATION, "lesson|evo|kitti", "",
            "all", "Preset of rules (default lesson; evo when a bag topic is given). lesson: interpolated association, crop, se2/se3 alignment "
            + "(se2 for planar data, se3 for SE(3) data), RPE over 1 s for every start pose; evo: nearest within "
            + "0.01 s, duplicates kept, no alignment, RPE over 1 frame; kitti: index pairing, drift. Explicit "
            + "settings override the preset."),
    ASSOCIATION("association", "--association", SettingKind.CHOICE, SettingScope.EVALUATION,
            "interpolate|nearest|nearest-interpolated", "", "all", "interpolate: the reference interpolated at "
            + "the estimate stamps (lesson); nearest: evo's nearest stamp within max diff; nearest-interpolated: "
            + "evo's --sync_method interpolation."),
    MAX_DIFF_S("max_diff_s", "--max-diff", SettingKind.NUMBER, SettingScope.EVALUATION, "S", "s", "all",
            "Max timestamp difference for nearest association (s, > 0; default 0.01)."),
    T_OFFSET_S("t_offset_s", "--t-offset", SettingKind.NUMBER_OR_AUTO, SettingScope.EVALUATION, "S|auto", "s",
            "all", "Offset added to the estimate's timestamps (s; default 0). auto: estimated by cross-correlating "
            + "the angular speeds within +-2 s, then refined on the ATE; the report gives the value and its "
            + "uncertainty."),
    MAX_GAP_S("max_gap_s", "--max-gap", SettingKind.NUMBER_OR_AUTO, SettingScope.EVALUATION, "S|auto", "s", "all",
            "Longest reference gap the interpolated association bridges (s, > 0; default auto: 10 median "
            + "reference periods); estimate poses inside longer gaps are dropped, counted and located in the "
            + "report."),
    OVERLAP("overlap", "--overlap", SettingKind.CHOICE, SettingScope.EVALUATION, "crop|strict", "", "all",
            "Estimate poses outside the reference's time span: crop (drop and count them; default) or strict "
            + "(refuse)."),
    ALIGNMENT("alignment", "--align", SettingKind.CHOICE, SettingScope.EVALUATION,
            "none|se2|sim2|se3|sim3|origin|posyaw", "", "all", "Alignment fitted on positions and applied to "
            + "whole poses (default: lesson se2 for planar data, se3 for SE(3) data; evo and kitti none)."),
    N_TO_ALIGN("n_to_align", "--n-to-align", SettingKind.INTEGER, SettingScope.EVALUATION, "N", "", "all",
            "Fit the alignment on the first N associated poses (N >= 1; default all)."),
    PLANAR("planar", "--planar", SettingKind.SWITCH, SettingScope.EVALUATION, "", "", "all",
            "Project SE(3) poses onto the ground plane xy before alignment (an SE(2) evaluation)."),
    PROJECT_TO_PLANE("project_to_plane", "--project-to-plane", SettingKind.CHOICE, SettingScope.EVALUATION,
            "xy|xz", "", "all", "evo's projection after a 3D alignment (xz for camera frames such as KITTI's); "
            + "excludes planar."),
    RPE_DELTA("rpe_delta", "--rpe-delta", SettingKind.NUMBER, SettingScope.EVALUATION, "D", "rpe_unit", "all",
            "RPE horizon in rpe_unit (> 0; whole for frames; default: lesson 1 s, evo and kitti 1 frame)."),
    RPE_UNIT("rpe_unit", "--rpe-unit", SettingKind.CHOICE, SettingScope.EVALUATION, "s|frames|m", "", "all",
            "Unit of the RPE horizon: seconds, frames or metres travelled."),
    RPE_PAIRS("rpe_pairs", "--rpe-pairs", SettingKind.CHOICE, SettingScope.EVALUATION, "all-pairs|consecutive",
            "", "all", "all-pairs: every start pose; consecutive: chained, non-overlapping pairs (lesson default "
            + "all-pairs; evo and kitti consecutive). --all-pairs and --no-all-pairs are short for it.",
            "--all-pairs=all-pairs", "--no-all-pairs=consecutive"),
    PAIRS_FROM("pairs_from", "--pairs-from", SettingKind.CHOICE, SettingScope.EVALUATION, "reference|estimate",
            "", "all", "Trajectory the RPE pairs are chosen on (default estimate, as evo)."),
    EXTRA_METRICS("extra_metrics", "--extra-metrics", SettingKind.SWITCH, SettingScope.EVALUATION, "", "", "all",
            "Also report per-axis translation errors (world frame of the reference, signed), the planar heading "
            + "error and the speed error over the RPE horizon (off by default: the table and the report then have "
            + "an extra section)."),
    DRIFT("drift", "--drift", SettingKind.SWITCH, SettingScope.EVALUATION, "", "", "all",
            "Compute KITTI-style length-normalised drift (on with convention kitti or any drift setting)."),
    DRIFT_SEGMENT_LENGTHS_M("drift_segment_lengths_m", "--drift-lengths", SettingKind.NUMBERS,
            SettingScope.EVALUATION, "M,M,...", "m", "all", "Drift segment lengths (m; default 100,200,...,800)."),
    DRIFT_STEP_FRAMES("drift_step_frames", "--drift-step", SettingKind.INTEGER, SettingScope.EVALUATION, "FRAMES",
            "frames", "all", "Frames between drift segment starts (>= 1; default 10)."),
    SUBTRAJ_LENGTHS_M("subtraj_lengths_m", "--subtraj-lengths", SettingKind.NUMBERS, SettingScope.EVALUATION,
            "M,M,...", "m", "all", "Sub-trajectory lengths of the relative errors per length that plots draw and "
            + "saved series keep (m; default 10,20,30,40,50 % of the reference path; KITTI's segment rule).");

    private static final Pattern DECIMAL = Pattern.compile("[+-]?(\\d+\\.?\\d*|\\.\\d+)([eE][+-]?\\d{1,3})?");
    private static final Pattern WHOLE = Pattern.compile("[+-]?\\d{1,18}");

    private final String key;
    private final String flag;
    private final SettingKind kind;
    private final SettingScope scope;
    private final String values;
    private final String unit;
    private final String formats;
    private final String help;
    private final Map<String, String> switches;

    Setting(String key, String flag, SettingKind kind, SettingScope scope, String values, String unit,
            String formats, String help, String... switches) {
        this.key = key;
        this.flag = flag;
        this.kind = kind;
        this.scope = scope;
        this.values = values;
        this.unit = unit;
        this.formats = formats;
        this.help = help;
        Map<String, String> s = new LinkedHashMap<>();
        for (String sw : switches) {
            s.put(sw.substring(0, sw.indexOf('=')), sw.substring(sw.indexOf('=') + 1));
        }
        this.switches = java.util.Collections.unmodifiableMap(s);
    }

    /** @return the key in files and events ({@code max_diff_s}) */
    public String key() {
        return key;
    }

    /** @return the command-line flag ({@code --max-diff}) */
    public String flag() {
        return flag;
    }

    /** @return the value type */
    public SettingKind kind() {
        return kind;
    }

    /** @return what the setting acts on */
    public SettingScope scope() {
        return scope;
    }

    /** @return the allowed words of a choice ({@code a|b|c}), else the value's label ({@code S}, {@code N}) */
    public String allowed() {
        return values;
    }

    /** @return the unit of the value ({@code s}, {@code m}, ...), or "" */
    public String unit() {
        return unit;
    }

    /** @return the formats the setting applies to ({@code all}, {@code csv}, {@code kitti}) */
    public String formats() {
        return formats;
    }

    /** @return the help text */
    public String help() {
        return help;
    }

    /** @return extra command-line flags without an argument, each standing for one value (flag to value) */
    public Map<String, String> switches() {
        return switches;
    }

    /** @return the setting with this key, or {@code null} */
    public static Setting fromKey(String key) {
        for (Setting s : values()) {
            if (s.key.equals(key)) {
                return s;
            }
        }
        return null;
    }

    /** @return every key, in table order, comma separated */
    public static String knownKeys() {
        List<String> keys = new ArrayList<>();
        for (Setting s : values()) {
            keys.add(s.key);
        }
        return String.join(", ", keys);
    }

    /** @return what a value must look like, as said in a refusal */
    public String expected() {
        String u = unit.isEmpty() || unit.equals("rpe_unit") ? "" : " (" + unit + ")";
        return switch (kind) {
            case CHOICE -> "one of " + values.replace("|", ", ");
            case NUMBER -> (this == T_OFFSET_S ? "a finite number" : "a number > 0") + u;
            case NUMBER_OR_AUTO -> (this == T_OFFSET_S ? "auto or a finite number" : "auto or a number > 0") + u;
            case INTEGER -> "a whole number >= 1" + u;
            case SWITCH -> "true or false";
            case NUMBERS -> "numbers > 0 separated by commas" + u;
            case PATH -> "a file path";
            case TEXT -> this == COLUMNS ? "4 column names separated by commas (time, x, y, yaw)"
                    : this == DELIMITER ? "a single character" : "a non-empty " + values.toLowerCase(Locale.ROOT);
        };
    }

    /**
     * Checks and converts a value written as text.
     *
     * @param text the value as written
     * @param source the file or event the value came from, or {@code null} (command line)
     * @param where how to name the value in a refusal ({@code --max-diff}, {@code metrics.max_diff_s})
     * @return a canonical choice word, a {@code Double}, {@code Integer}, {@code Boolean},
     *     {@code double[]}, {@code String} (path, delimiter) or {@code String[]} (columns)
     * @throws InputException naming {@code where}, what was expected and what was found
     */
    public Object parse(String text, String source, String where) {
        String t = text == null ? "" : text.trim();
        Object v = switch (kind) {
            case CHOICE -> choice(t);
            case NUMBER -> number(t, this != T_OFFSET_S);
            case NUMBER_OR_AUTO -> t.equalsIgnoreCase("auto") ? "auto" : number(t, this != T_OFFSET_S);
            case INTEGER -> WHOLE.matcher(t).matches() && Long.parseLong(t) >= 1 && Long.parseLong(t) <= Integer.MAX_VALUE
                    ? Integer.valueOf(Integer.parseInt(t)) : null;
            case SWITCH -> t.equalsIgnoreCase("true") ? Boolean.TRUE : t.equalsIgnoreCase("false") ? Boolean.FALSE : null;
            case NUMBERS -> numbers(t);
            case PATH -> t.isEmpty() ? null : t;
            case TEXT -> this == COLUMNS ? columns(t) : this == DELIMITER ? (text != null && text.length() == 1 ? text
                    : null) : t.isEmpty() ? null : t;
        };
        if (v == null) {
            String name = where.startsWith("--") ? where : "'" + where + "'";
            throw new InputException(source, 0, where, problem(source), name + " must be " + expected(),
                    text == null ? "" : text);
        }
        return v;
    }

    /**
     * @return INVALID_OPTION for a value from the command line ({@code source == null}),
     *     INVALID_CONFIGURATION for one from a file or event
     */
    static InputProblem problem(String source) {
        return source == null ? InputProblem.INVALID_OPTION : InputProblem.INVALID_CONFIGURATION;
    }

    private String choice(String t) {
        String w = t.toLowerCase(Locale.ROOT).replace('_', '-');
        for (String a : values.split("\\|")) {
            if (a.equals(w)) {
                return a;
            }
        }
        return null;
    }

    private static Double number(String t, boolean positive) {
        if (!DECIMAL.matcher(t).matches()) {
            return null;
        }
        double v = Double.parseDouble(t);
        return Double.isFinite(v) && (!positive || v > 0.0) ? v : null;
    }

    private static double[] numbers(String t) {
        String[] parts = t.split(",", -1);
        double[] v = new double[parts.length];
        for (int i = 0; i < parts.length; i++) {
            Double d = number(parts[i].trim(), true);
            if (d == null) {
                return null;
            }
            v[i] = d;
        }
        return v;
    }

    private static String[] columns(String t) {
        String[] parts = t.split(",", -1);
        if (parts.length != 4) {
            return null;
        }
        for (int i = 0; i < 4; i++) {
            parts[i] = parts[i].trim();
            if (parts[i].isEmpty()) {
                return null;
            }
        }
        return parts;
    }
}
