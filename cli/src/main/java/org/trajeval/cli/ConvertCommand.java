package org.trajeval.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.Callable;
import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;
import org.trajeval.core.io.LoadedTrajectory;
import org.trajeval.core.io.TrajectoryFormat;
import org.trajeval.core.io.TrajectoryWriter;
import java.util.ArrayList;
import java.util.List;
import org.trajeval.core.io.DuplicateTimestamps;
import org.trajeval.core.io.ReadOptions;
import org.trajeval.core.io.TrajectoryReader;
import org.trajeval.core.io.bag.BagSource;
import org.trajeval.core.options.FileRole;
import org.trajeval.core.options.PathResolver;
import org.trajeval.core.options.Setting;
import org.trajeval.core.options.SettingText;
import org.trajeval.core.options.SettingValues;
import org.trajeval.core.options.SettingsResolver;
import org.trajeval.core.report.ReportJson;
import org.trajeval.core.traj.PlaneProjection;
import org.trajeval.core.traj.Plane;
import org.trajeval.core.traj.PlanarTrajectory;
import org.trajeval.core.traj.PoseSequence;
import org.trajeval.core.traj.SpatialTrajectory;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;

/** {@code trajeval convert BAG --topic T --to tum|kitti|csv --out FILE}: a bag topic or TF trajectory to a file. */
@Command(name = "convert", mixinStandardHelpOptions = true, sortOptions = false,
        description = {"Writes one topic (or TF trajectory /tf:PARENT.CHILD) of a ROS bag to a trajectory file, as "
            + "evo_traj's export does: tum (t tx ty tz qx qy qz qw; s, m), kitti (3x4 pose matrices, no stamps) or csv "
            + "(planar t,x,y,yaw: s, m, m, rad; z, roll and pitch dropped). The file is written atomically."},
        exitCodeListHeading = "%nExit codes:%n",
        exitCodeList = {"0:success", "1:internal error (a bug; rerun with --verbose)",
            "2:bad input or usage (one line names the file and what is wrong)"})
public final class ConvertCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Parameters(index = "0", paramLabel = "BAG", description = "The bag (file or rosbag2 folder), or BAG:TOPIC.")
    Path bag;

    @Option(names = "--topic", paramLabel = "TOPIC", description = "Topic, or /tf:PARENT.CHILD.")
    String topic;

    @Option(names = "--to", paramLabel = "tum|kitti|csv", required = true, converter = OutputFormat.class,
            description = "Format of the file written.")
    TrajectoryFormat to;

    @Option(names = "--out", paramLabel = "FILE", required = true, description = "The file to write (replaced).")
    Path out;

    @Option(names = "--stamps", paramLabel = "header|log", description = "Pose times: header (the messages' "
            + "header.stamp, default) or log (the recording's log time).")
    String stamps;

    @Option(names = "--pose-field", paramLabel = "FIELD.PATH", description = "Field holding the pose, for types "
            + "trajeval does not know.")
    String poseField;

    @Option(names = "--sort", description = "Sort poses by stamp instead of refusing a decreasing one.")
    boolean sort;

    @Option(names = "--duplicates", paramLabel = "refuse|keep", description = "Poses with equal stamps: refuse "
            + "(default) or keep them.")
    String duplicates;

    @Option(names = "--verbose", description = "Print stack traces of errors.")
    boolean verbose;

    @Override
    public Integer call() {
        // the same settings (and checks) as eval's reference: ref_topic, stamps, pose_field, sort, duplicates
        List<SettingText> given = new ArrayList<>();
        Path path = bag;
        if (topic != null) {
            given.add(new SettingText(Setting.REF_TOPIC.key(), topic, "--topic"));
        } else if (!Files.exists(bag)) {
            BagSource s = BagSource.resolve(bag.toString(), null);
            if (s != null) {
                given.add(new SettingText(Setting.REF_TOPIC.key(), s.topic(), "BAG"));
                path = s.path();
            }
        }
        if (given.isEmpty() && Files.exists(bag)) {
            throw UsageProblem.of("--topic", "name the topic to convert: --topic TOPIC, or BAG:TOPIC", null);
        }
        if (stamps != null) {
            given.add(new SettingText(Setting.STAMPS.key(), stamps, "--stamps"));
        }
        if (poseField != null) {
            given.add(new SettingText(Setting.POSE_FIELD.key(), poseField, "--pose-field"));
        }
        if (sort) {
            given.add(new SettingText(Setting.SORT.key(), "true", "--sort"));
        }
        if (duplicates != null) {
            given.add(new SettingText(Setting.DUPLICATES.key(), duplicates, "--duplicates"));
        }
        if (Files.exists(out) && Files.exists(path) && sameFile(out, path)) {
            throw new InputException(out.toString(), 0, null, InputProblem.INVALID_OPTION,
                    "--out names the bag itself; choose another file", null);
        }
        SettingValues settings = SettingValues.of(given, null);
        ReadOptions read = SettingsResolver.readOptions(settings, FileRole.REFERENCE, ReadOptions.defaults()
                .withDuplicates(DuplicateTimestamps.REFUSE), PathResolver.asWritten());
        LoadedTrajectory t = TrajectoryReader.read(path, read);
        SpatialTrajectory s = (SpatialTrajectory) t.trajectory();
        StringWriter w = new StringWriter();
        try {
            switch (to) {
                case TUM -> TrajectoryWriter.writeTum(s, w);
                case KITTI -> TrajectoryWriter.writeKitti(s, w);
                default -> TrajectoryWriter.writeCsv(planar(s), w);
            }
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        ReportJson.writeAtomically(out, w.toString());
        PrintWriter o = spec.commandLine().getOut();
        o.println("wrote " + s.size() + " poses of " + t.source() + " to " + out + " (" + to.id() + ")");
        o.flush();
        return ExitCodes.OK;
    }

    private static PlanarTrajectory planar(SpatialTrajectory s) {
        PoseSequence p = PlaneProjection.project(s.poses(), Plane.XY);
        int n = s.size();
        double[] t = new double[n];
        double[] x = new double[n];
        double[] y = new double[n];
        double[] yaw = new double[n];
        for (int i = 0; i < n; i++) {
            t[i] = s.t(i);
            x[i] = p.x(i);
            y[i] = p.y(i);
            yaw[i] = Math.atan2(p.r(i, 1, 0), p.r(i, 0, 0));
        }
        return PlanarTrajectory.of(t, x, y, yaw);
    }

    /** tum|kitti|csv: the formats convert writes. */
    static final class OutputFormat implements picocli.CommandLine.ITypeConverter<TrajectoryFormat> {
        @Override
        public TrajectoryFormat convert(String v) {
            return switch (v.trim().toLowerCase(java.util.Locale.ROOT)) {
                case "tum" -> TrajectoryFormat.TUM;
                case "kitti" -> TrajectoryFormat.KITTI;
                case "csv" -> TrajectoryFormat.CSV;
                default -> throw new picocli.CommandLine.TypeConversionException("expected one of tum|kitti|csv, found \""
                        + v + "\"");
            };
        }
    }

    private static boolean sameFile(Path a, Path b) {
        try {
            return Files.isSameFile(a, b);
        } catch (IOException e) {
            return false;
        }
    }
}
