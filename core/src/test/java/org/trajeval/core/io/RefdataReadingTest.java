package org.trajeval.core.io;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.HexFormat;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;
import org.trajeval.core.traj.SpatialTrajectory;

/**
 * Reads the real files in ../shared/refdata (evo's test data). Pose counts come from the table in
 * refdata/README.md; first-pose values are read by hand from the file text (quoted in comments).
 */
class RefdataReadingTest {

    static Path refdata(String file) {
        return org.trajeval.core.RefData.dir().resolve(file);
    }

    @ParameterizedTest(name = "{0}: {2} poses as {1}")
    @CsvSource({
        "fr2_desk_ORB.txt, TUM, 2893, auto: 8 numeric columns (TUM)",
        "fr2_desk_ORB_kf_mono.txt, TUM, 157, auto: 8 numeric columns (TUM)",
        "freiburg1_xyz-groundtruth.txt, TUM, 3000, auto: 8 numeric columns (TUM)",
        "freiburg1_xyz-rgbdslam.txt, TUM, 788, auto: 8 numeric columns (TUM)",
        "freiburg1_xyz-rgbdslam_drift.txt, TUM, 788, auto: 8 numeric columns (TUM)",
        "freiburg1_xyz-rgbdslam_drift_short.txt, TUM, 40, auto: 8 numeric columns (TUM)",
        "freiburg1_xyz-ORB_kf_mono.txt, TUM, 32, auto: 8 numeric columns (TUM)",
        "KITTI_00_gt.txt, KITTI, 4541, auto: 12 numeric columns (KITTI)",
        "KITTI_00_ORB.txt, KITTI, 4541, auto: 12 numeric columns (KITTI)",
        "KITTI_00_SPTAM.txt, KITTI, 4541, auto: 12 numeric columns (KITTI)",
        "V102_groundtruth.csv, EUROC, 16702, auto: first line starts with '#timestamp' (EuRoC header)",
        "georeferenced.tum, TUM, 1000, auto: extension .tum (TUM)",
    })
    void realFileReadsWithTheReadmePoseCountAndDetectedFormat(String file, TrajectoryFormat format, int poses,
            String reason) throws IOException {
        LoadedTrajectory t = TrajectoryReader.read(refdata(file), ReadOptions.defaults());
        assertEquals(poses, t.trajectory().size());
        assertEquals(format, t.format());
        assertEquals(reason, t.formatReason());
        assertEquals(sha256(refdata(file)), t.sha256());
        assertEquals(format == TrajectoryFormat.KITTI, t.indexTimestamps());
        // the same when the format is given instead of detected
        LoadedTrajectory given = TrajectoryReader.read(refdata(file), ReadOptions.defaults().withFormat(format));
        assertEquals(poses, given.trajectory().size());
        assertEquals("given", given.formatReason());
    }

    /**
     * Two real files repeat a timestamp on consecutive lines (fr2_desk_groundtruth.txt lines
     * 10862/10863 "1311868229.5760"; V102.txt lines 432/433 "1.403715572212143183e+09", and
     * three more). By default they are refused; with {@link DuplicateTimestamps#KEEP} they read
     * with the README counts (20957, 807), which include the repeated lines, as evo keeps them.
     */
    @ParameterizedTest(name = "{0}: line {1} repeats line {2}")
    @CsvSource({
        "fr2_desk_groundtruth.txt, 10863, 10862, 20957",
        "V102.txt, 433, 432, 807",
    })
    void realFileWithARepeatedTimestampIsRefusedNamingBothLines(String file, long line, long firstLine,
            long readmePoses) throws IOException {
        Path path = refdata(file);
        InputException e = assertThrows(InputException.class, () -> TrajectoryReader.read(path, ReadOptions.defaults()));
        assertEquals(InputProblem.DUPLICATE_TIMESTAMP, e.problem());
        assertEquals(line, e.line());
        assertTrue(e.getMessage().contains("line " + firstLine), e.getMessage());
        try (var lines = Files.lines(path)) {
            assertEquals(readmePoses, lines.filter(l -> !l.startsWith("#") && !l.isBlank()).count());
        }
        InputException sorted = assertThrows(InputException.class,
                () -> TrajectoryReader.read(path, ReadOptions.defaults().withOrder(TimestampOrder.SORT)));
        assertEquals(InputProblem.DUPLICATE_TIMESTAMP, sorted.problem());

        ReadOptions keep = ReadOptions.defaults().withDuplicates(DuplicateTimestamps.KEEP);
        assertEquals(readmePoses, TrajectoryReader.read(path, keep).trajectory().size());
        assertEquals(readmePoses, TrajectoryReader.read(path, keep.withOrder(TimestampOrder.SORT)).trajectory().size());
    }

    @Test
    void tumFirstPoseIsTheFileTextWithWLast() {
        // freiburg1_xyz-groundtruth.txt line 4: "1305031098.6659 1.3563 0.6305 1.6380 0.6132 0.5962 -0.3311 -0.3986"
        SpatialTrajectory t = (SpatialTrajectory) TrajectoryReader.read(refdata("freiburg1_xyz-groundtruth.txt"),
                ReadOptions.defaults()).trajectory();
        assertEquals(1305031098.6659, t.t(0), 0.0);
        assertEquals(1.3563, t.x(0), 0.0);
        assertEquals(0.6305, t.y(0), 0.0);
        assertEquals(1.6380, t.z(0), 0.0);
        // quaternions are kept as read (evo does not normalise them either)
        assertEquals(-0.3986, t.qw(0), 0.0);
        assertEquals(0.6132, t.qx(0), 0.0);
        assertEquals(0.5962, t.qy(0), 0.0);
        assertEquals(-0.3311, t.qz(0), 0.0);
    }

    @Test
    void tumLongDigitsAreTheNearestDoubles() {
        // georeferenced.tum line 3: "1.706282470098386526e+09 4.580746042933629942e+05 5.429380172093272209e+06 ..."
        SpatialTrajectory t = (SpatialTrajectory) TrajectoryReader.read(refdata("georeferenced.tum"),
                ReadOptions.defaults()).trajectory();
        assertEquals(1.706282470098386526e+09, t.t(0), 0.0);
        assertEquals(4.580746042933629942e+05, t.x(0), 0.0);
        assertEquals(5.429380172093272209e+06, t.y(0), 0.0);
        assertEquals(1.629059191997378946e+02, t.z(0), 0.0);
    }

    @Test
    void eurocStampIsNanosecondsDividedAsEvoDoes() {
        // V102_groundtruth.csv line 2: "1403715524907143168,0.515356,1.996773,0.971104,0.161996,0.789985,-0.205376,0.554528,..."
        // evo: np.loadtxt (nearest double) then np.divide(stamps, 1e9)
        SpatialTrajectory t = (SpatialTrajectory) TrajectoryReader.read(refdata("V102_groundtruth.csv"),
                ReadOptions.defaults()).trajectory();
        assertEquals(Double.parseDouble("1403715524907143168") / 1e9, t.t(0), 0.0);
        assertEquals(0.515356, t.x(0), 0.0);
        assertEquals(1.996773, t.y(0), 0.0);
        assertEquals(0.971104, t.z(0), 0.0);
        assertEquals(0.161996, t.qw(0), 0.0);
        assertEquals(0.789985, t.qx(0), 0.0);
        assertEquals(-0.205376, t.qy(0), 0.0);
        assertEquals(0.554528, t.qz(0), 0.0);
    }

    @Test
    void kittiPoseIsTheMatrixAsRead() {
        // KITTI_00_gt.txt line 2: "9.999978e-01 5.272628e-04 -2.066935e-03 -4.690294e-02 -5.296506e-04 9.999992e-01
        //   -1.154865e-03 -2.839928e-02 2.066324e-03 1.155958e-03 9.999971e-01 8.586941e-01"
        LoadedTrajectory loaded = TrajectoryReader.read(refdata("KITTI_00_gt.txt"), ReadOptions.defaults());
        SpatialTrajectory t = (SpatialTrajectory) loaded.trajectory();
        assertTrue(loaded.indexTimestamps());
        assertEquals(0.0, t.t(0), 0.0);
        assertEquals(1.0, t.t(1), 0.0);
        assertEquals(4540.0, t.t(4540), 0.0);
        assertEquals(-4.690294e-02, t.x(1), 0.0);
        assertEquals(-2.839928e-02, t.y(1), 0.0);
        assertEquals(8.586941e-01, t.z(1), 0.0);
        double[] r = new double[9];
        t.poses().rotation(1, r, 0);
        double[] file = {
            9.999978e-01, 5.272628e-04, -2.066935e-03,
            -5.296506e-04, 9.999992e-01, -1.154865e-03,
            2.066324e-03, 1.155958e-03, 9.999971e-01};
        assertArrayEquals(file, r, 0.0);
    }

    @Test
    void kittiTimesFileGivesRealStamps() {
        // KITTI_00_gt_times.txt line 2 "1.037359e-01", last line (4541) "4.705816e+02"
        LoadedTrajectory loaded = TrajectoryReader.read(refdata("KITTI_00_gt.txt"),
                ReadOptions.defaults().withKittiTimes(refdata("KITTI_00_gt_times.txt")));
        assertFalse(loaded.indexTimestamps());
        assertEquals(4541, loaded.trajectory().size());
        assertEquals(1.037359e-01, loaded.trajectory().t(1), 0.0);
        assertEquals(4.705816e+02, loaded.trajectory().t(4540), 0.0);
        assertEquals(8.586941e-01, loaded.trajectory().z(1), 0.0);
    }

    @Test
    void timesFileAloneIsNotATrajectory() {
        InputException e = assertThrows(InputException.class,
                () -> TrajectoryReader.read(refdata("KITTI_00_gt_times.txt"), ReadOptions.defaults()));
        assertEquals(InputProblem.UNKNOWN_FORMAT, e.problem());
        assertEquals(1, e.line());
    }

    static String sha256(Path p) throws IOException {
        try {
            return HexFormat.of().formatHex(MessageDigest.getInstance("SHA-256").digest(Files.readAllBytes(p)));
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException(e);
        }
    }
}
