package org.trajeval.bench;

import java.nio.file.Path;
import java.util.concurrent.TimeUnit;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Fork;
import org.openjdk.jmh.annotations.Level;
import org.openjdk.jmh.annotations.Measurement;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Param;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.Warmup;
import org.trajeval.core.align.Alignment;
import org.trajeval.core.align.AlignmentModel;
import org.trajeval.core.align.AlignmentTransform;
import org.trajeval.core.assoc.AssociatedPoses;
import org.trajeval.core.assoc.AssociationMethod;
import org.trajeval.core.assoc.AssociationOptions;
import org.trajeval.core.assoc.OverlapPolicy;
import org.trajeval.core.assoc.TimeAssociation;
import org.trajeval.core.eval.Convention;
import org.trajeval.core.eval.EvaluationOptions;
import org.trajeval.core.eval.Evaluator;
import org.trajeval.core.io.LoadedTrajectory;
import org.trajeval.core.io.ReadOptions;
import org.trajeval.core.io.TrajectoryFormat;
import org.trajeval.core.io.TrajectoryReader;
import org.trajeval.core.metric.AbsoluteTrajectoryError;
import org.trajeval.core.metric.AteResult;
import org.trajeval.core.metric.DriftOptions;
import org.trajeval.core.metric.DriftResult;
import org.trajeval.core.metric.LengthNormalisedDrift;
import org.trajeval.core.metric.PairSelection;
import org.trajeval.core.metric.PairsFrom;
import org.trajeval.core.metric.RelativePoseError;
import org.trajeval.core.metric.RpeOptions;
import org.trajeval.core.metric.RpeResult;
import org.trajeval.core.metric.RpeUnit;
import org.trajeval.core.report.EvaluationReport;
import org.trajeval.core.traj.PlanarTrajectory;
import org.trajeval.core.traj.PoseSequence;
import org.trajeval.core.traj.SpatialTrajectory;

/**
 * One benchmark per stage of an evaluation, on a seeded pair of {@code poses} poses each
 * (score: ms per operation; divide poses by it for a rate): parse (CSV and TUM files written
 * once in setup), associate (interpolation of the reference at the estimate's stamps), align
 * (SE(3) Umeyama and planar SE(2)), ATE, RPE (1 s, every start pose, the lesson's rule), KITTI
 * drift, and the whole planar lesson evaluation in memory (what {@code trajeval eval} does after
 * reading).
 */
@State(Scope.Benchmark)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.MILLISECONDS)
@Fork(value = 1, jvmArgsAppend = {"-Xmx6g"})
@Warmup(iterations = 3, time = 2)
@Measurement(iterations = 5, time = 2)
public class PipelineBenchmarks {
    @Param({"1000000"})
    public int poses;

    private Path planarCsv;
    private Path spatialTum;
    private LoadedTrajectory planarRef;
    private LoadedTrajectory planarEst;
    private SpatialTrajectory spatialRef;
    private SpatialTrajectory spatialEst;
    private AssociatedPoses associated;
    private PoseSequence alignedEstimate;
    private double[] stamps;

    @Setup(Level.Trial)
    public void setUp() {
        PlanarTrajectory[] p = BenchmarkData.planarPair(poses, 42);
        SpatialTrajectory[] s = BenchmarkData.spatialPair(poses, 42);
        planarCsv = BenchmarkData.write(p[1], ".csv");
        spatialTum = BenchmarkData.write(s[1], ".txt");
        planarRef = new LoadedTrajectory("ref.csv", TrajectoryFormat.CSV, "given", p[0], "0", false);
        planarEst = new LoadedTrajectory("est.csv", TrajectoryFormat.CSV, "given", p[1], "0", false);
        spatialRef = s[0];
        spatialEst = s[1];
        associated = associateSpatial();
        AlignmentTransform a = Alignment.fit(AlignmentModel.SE3, associated.reference(), associated.estimate(), -1,
                "est");
        alignedEstimate = a.apply(associated.estimate());
        stamps = associated.timestamps();
    }

    @Benchmark
    public LoadedTrajectory parseCsv() {
        return TrajectoryReader.read(planarCsv, ReadOptions.defaults().withFormat(TrajectoryFormat.CSV));
    }

    @Benchmark
    public LoadedTrajectory parseTum() {
        return TrajectoryReader.read(spatialTum, ReadOptions.defaults().withFormat(TrajectoryFormat.TUM));
    }

    @Benchmark
    public AssociatedPoses associateSpatial() {
        return TimeAssociation.compute(spatialRef, spatialEst,
                new AssociationOptions(AssociationMethod.INTERPOLATE, 0.01, 0.0, OverlapPolicy.CROP), "ref", "est");
    }

    @Benchmark
    public AlignmentTransform alignSe3() {
        return Alignment.fit(AlignmentModel.SE3, associated.reference(), associated.estimate(), -1, "est");
    }

    @Benchmark
    public AlignmentTransform alignSe2() {
        return Alignment.fit(AlignmentModel.SE2, associated.reference(), associated.estimate(), -1, "est");
    }

    @Benchmark
    public AteResult ate() {
        return AbsoluteTrajectoryError.compute(associated.reference(), alignedEstimate);
    }

    @Benchmark
    public RpeResult rpe() {
        return RelativePoseError.compute(associated.reference(), alignedEstimate, stamps,
                new RpeOptions(1.0, RpeUnit.SECONDS, PairSelection.ALL_PAIRS, PairsFrom.ESTIMATE));
    }

    @Benchmark
    public DriftResult drift() {
        return LengthNormalisedDrift.compute(associated.reference(), alignedEstimate, DriftOptions.KITTI);
    }

    @Benchmark
    public EvaluationReport evaluatePlanarLesson() {
        return Evaluator.evaluate(planarRef, planarEst, EvaluationOptions.preset(Convention.LESSON));
    }
}
