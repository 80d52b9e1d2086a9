package org.trajeval.core.options;

import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;
import org.trajeval.core.io.LoadedTrajectory;
import org.trajeval.core.io.TrajectoryFormat;

/**
 * Refuses read settings that the formats actually read would silently ignore: the CSV layout
 * ({@code time_unit}, {@code columns}, {@code delimiter}) when neither file is CSV, and a KITTI
 * times file ({@code ref_times}, {@code est_times}) for a file that is not KITTI. Checked after
 * reading, because the format is often detected; the message names the setting as it was given
 * ({@code --time-unit} on the command line, {@code metrics.time_unit} in a run.yaml), the format
 * read and why it was chosen.
 */
public final class FormatApplicability {
    private static final Setting[] CSV_ONLY = {Setting.TIME_UNIT, Setting.COLUMNS, Setting.DELIMITER};

    private FormatApplicability() {
    }

    /**
     * @param s the settings the files were read with
     * @param ref the reference as read, named {@code refSource} in messages
     * @param est the estimate as read, named {@code estSource} in messages
     * @throws InputException ({@link InputProblem#INVALID_OPTION}) naming the first setting that does not apply
     */
    public static void check(SettingValues s, LoadedTrajectory ref, String refSource, LoadedTrajectory est,
            String estSource) {
        if (ref.format() != TrajectoryFormat.CSV && est.format() != TrajectoryFormat.CSV) {
            for (Setting c : CSV_ONLY) {
                if (s.has(c)) {
                    throw refuse(s, c, "CSV", refSource, ref);
                }
            }
        }
        if (s.has(Setting.REF_TIMES) && ref.format() != TrajectoryFormat.KITTI) {
            throw refuse(s, Setting.REF_TIMES, "KITTI", refSource, ref);
        }
        if (s.has(Setting.EST_TIMES) && est.format() != TrajectoryFormat.KITTI) {
            throw refuse(s, Setting.EST_TIMES, "KITTI", estSource, est);
        }
    }

    private static InputException refuse(SettingValues s, Setting setting, String format, String source,
            LoadedTrajectory t) {
        return new InputException(source, 0, s.where(setting), InputProblem.INVALID_OPTION, "'" + s.where(setting)
                + "' applies to " + format + " files only, and this file was read as " + t.format().id() + " ("
                + t.formatReason() + "); drop it or give the format", s.asText().get(setting.key()));
    }
}
