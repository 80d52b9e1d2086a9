package org.trajeval.core.eval;

import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.nio.file.Path;
import java.util.StringJoiner;
import org.trajeval.core.align.AlignmentModel;
import org.trajeval.core.assoc.AssociationMethod;
import org.trajeval.core.io.LoadedTrajectory;
import org.trajeval.core.io.ReadOptions;
import org.trajeval.core.io.TrajectoryReader;
import org.trajeval.core.metric.RpeUnit;
import org.trajeval.core.report.EvaluationReport;
import org.trajeval.core.report.ReportJson;

/**
 * Not a test: times the evaluation alone, without reading, in one warm JVM. Reads REF and EST once,
 * evaluates the pair RUNS times on this thread with the benchmark's lesson options (interpolation,
 * SE(2) for planar pairs or SE(3), RPE over 1 s) or, with CASE {@code evo-se3} or {@code evo-sim3},
 * evo's (nearest matching, RPE over 1 frame) with that alignment, and prints the thread CPU time of
 * each evaluation (ms) and the hash of the last report's JSON (equal hashes: equal numbers). Usage, with the
 * launcher's jars (an A/B runs it against two installs in turn):
 * {@code java -XX:+UseParallelGC -cp core/build/classes/java/test:cli/build/install/trajeval/lib/*
 * org.trajeval.core.eval.EvalSpeed REF EST [runs] [lesson|evo-se3|evo-sim3]}.
 */
public final class EvalSpeed {
    private EvalSpeed() {
    }

    public static void main(String[] args) {
        LoadedTrajectory ref = TrajectoryReader.read(Path.of(args[0]), ReadOptions.defaults());
        LoadedTrajectory est = TrajectoryReader.read(Path.of(args[1]), ReadOptions.defaults());
        int runs = args.length > 2 ? Integer.parseInt(args[2]) : 12;
        boolean planar = ref.trajectory() instanceof org.trajeval.core.traj.PlanarTrajectory;
        String kase = args.length > 3 ? args[3] : "lesson";
        EvaluationOptions options = switch (kase) {
            case "evo-se3" -> EvaluationOptions.preset(Convention.EVO, planar).withAlignment(AlignmentModel.SE3);
            case "evo-sim3" -> EvaluationOptions.preset(Convention.EVO, planar).withAlignment(AlignmentModel.SIM3);
            default -> EvaluationOptions.preset(Convention.LESSON, planar)
                    .withAssociation(AssociationMethod.INTERPOLATE).withAlignment(planar ? AlignmentModel.SE2 : AlignmentModel.SE3).withRpe(1, RpeUnit.SECONDS);
        };
        ThreadMXBean mx = ManagementFactory.getThreadMXBean();
        StringJoiner times = new StringJoiner(" ");
        int hash = 0;
        for (int run = 0; run < runs; run++) {
            long start = mx.getCurrentThreadCpuTime();
            EvaluationReport report = Evaluator.evaluate(ref, est, options, Parallelism.SEQUENTIAL);
            hash = ReportJson.toJson(report).hashCode();
            times.add(String.valueOf((mx.getCurrentThreadCpuTime() - start) / 1_000_000));
        }
        System.out.println(times + " hash " + Integer.toHexString(hash));
    }
}
