package org.trajeval.cli;

import java.nio.file.Path;
import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;
import org.trajeval.core.io.CsvLayout;
import org.trajeval.core.io.DuplicateTimestamps;
import org.trajeval.core.io.LoadedTrajectory;
import org.trajeval.core.io.ReadOptions;
import org.trajeval.core.io.TimeUnit;
import org.trajeval.core.io.TimestampOrder;
import org.trajeval.core.io.TrajectoryFormat;
import org.trajeval.core.io.TrajectoryReader;
import picocli.CommandLine.Option;

/** How trajectory files are read: the options shared by every command that reads trajectories. */
public final class InputOptions {

    @Option(names = "--format", paramLabel = "auto|csv|tum|kitti|euroc", defaultValue = "auto",
            converter = Enums.FormatConverter.class,
            description = "Format of both files (default: auto, detected from extension and content; the report "
                    + "says what was chosen and why).")
    TrajectoryFormat format;

    @Option(names = "--ref-format", paramLabel = "FORMAT", converter = Enums.FormatConverter.class,
            description = "Format of the reference when the two differ.")
    TrajectoryFormat refFormat;

    @Option(names = "--est-format", paramLabel = "FORMAT", converter = Enums.FormatConverter.class,
            description = "Format of the estimate when the two differ.")
    TrajectoryFormat estFormat;

    @Option(names = "--time-unit", paramLabel = "s|ms|us|ns",
            converter = Enums.TimeUnitConverter.class, description = "Unit of CSV timestamps (default: s).")
    TimeUnit timeUnit;

    @Option(names = "--columns", paramLabel = "T,X,Y,YAW", description = "CSV column names of "
            + "time (s), x (m), y (m) and yaw (rad) (default: t,x,y,yaw).")
    String columnsText;

    @Option(names = "--delimiter", paramLabel = "CHAR", description = "CSV field delimiter (default: ',').")
    Character delimiter;

    @Option(names = "--sort", description = "Sort poses by timestamp instead of refusing a decreasing one "
            + "(duplicate timestamps are still refused).")
    boolean sort;

    @Option(names = "--duplicates", paramLabel = "refuse|keep", converter = Enums.DuplicatesConverter.class,
            description = "Poses with equal timestamps: refuse (default; names both lines) or keep them in file "
                    + "order as evo does (default with --convention evo).")
    DuplicateTimestamps duplicates;

    /** Policy used when --duplicates is not given (the convention's). */
    DuplicateTimestamps defaultDuplicates = DuplicateTimestamps.REFUSE;

    @Option(names = "--ref-times", paramLabel = "FILE", description = "KITTI times file of the reference "
            + "(one time in s per line).")
    Path refTimes;

    @Option(names = "--est-times", paramLabel = "FILE", description = "KITTI times file of the estimate.")
    Path estTimes;

    @Option(names = "--max-poses", paramLabel = "N", description = "Refuse files with more poses "
            + "(default: 200000000).")
    Long maxPoses;

    @Option(names = "--max-file-size", paramLabel = "BYTES", description = "Refuse larger files "
            + "(default: 4 GiB).")
    Long maxBytes;

    /** @return the read options for the reference ({@code reference = true}) or the estimate */
    public ReadOptions readOptions(boolean reference) {
        ReadOptions o = ReadOptions.defaults();
        TrajectoryFormat f = reference ? (refFormat != null ? refFormat : format)
                : (estFormat != null ? estFormat : format);
        o = o.withFormat(f);
        CsvLayout base = CsvLayout.DEFAULT;
        String[] columns = columnsText == null ? null : columnsText.split(",", -1);
        if (columns != null && columns.length != 4) {
            throw new IllegalArgumentException("--columns needs 4 names (time, x, y, yaw), found " + columns.length);
        }
        CsvLayout layout = new CsvLayout(columns != null ? columns[0] : base.timeColumn(),
                columns != null ? columns[1] : base.xColumn(), columns != null ? columns[2] : base.yColumn(),
                columns != null ? columns[3] : base.yawColumn(), delimiter != null ? delimiter : base.delimiter(),
                timeUnit != null ? timeUnit : base.timeUnit());
        o = o.withCsv(layout);
        if (sort) {
            o = o.withOrder(TimestampOrder.SORT);
        }
        o = o.withDuplicates(duplicates != null ? duplicates : defaultDuplicates);
        Path times = reference ? refTimes : estTimes;
        if (times != null) {
            o = o.withKittiTimes(times);
        }
        if (maxPoses != null || maxBytes != null) {
            o = o.withLimits(maxBytes != null ? maxBytes : o.maxBytes(), maxPoses != null ? maxPoses : o.maxPoses());
        }
        return o;
    }

    /**
     * Reads a trajectory with these options.
     *
     * @throws InputException ({@link InputProblem#INVALID_OPTION}) when a times file is given for a file that is
     *     not KITTI
     */
    public LoadedTrajectory read(Path file, boolean reference) {
        LoadedTrajectory t = TrajectoryReader.read(file, readOptions(reference));
        String source = file.toString();
        Path times = reference ? refTimes : estTimes;
        if (times != null && t.format() != TrajectoryFormat.KITTI) {
            throw notApplicable(source, reference ? "--ref-times" : "--est-times", times.toString(), "KITTI", t);
        }
        return t;
    }

    /**
     * Refuses CSV layout options ({@code --time-unit}, {@code --columns}, {@code --delimiter}) when neither file
     * was read as CSV: they would be silently ignored.
     *
     * @throws InputException ({@link InputProblem#INVALID_OPTION}) naming the option and the formats read
     */
    public void checkCsvOptionsApply(Path reference, LoadedTrajectory ref, LoadedTrajectory est) {
        if (ref.format() == TrajectoryFormat.CSV || est.format() == TrajectoryFormat.CSV) {
            return;
        }
        for (String[] given : new String[][] {{"--time-unit", timeUnit == null ? null : timeUnit.id()},
            {"--columns", columnsText}, {"--delimiter", delimiter == null ? null : delimiter.toString()}}) {
            if (given[1] != null) {
                throw notApplicable(reference.toString(), given[0], given[1], "CSV", ref);
            }
        }
    }

    private static InputException notApplicable(String source, String option, String value, String format,
            LoadedTrajectory t) {
        return new InputException(source, 0, option, InputProblem.INVALID_OPTION, option + " applies to " + format
                + " files only, and this file was read as " + t.format().id() + " (" + t.formatReason()
                + "); drop the option or pass --format", value);
    }
}
