package org.trajeval.core.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;
import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;

/**
 * The limits that protect a shared service ({@code --max-poses}, {@code --max-file-size}) hold
 * for every format, as given and as detected: one pose or one byte over the limit is refused
 * with {@link InputProblem#TOO_LARGE}; exactly at the limit is accepted.
 */
class ReadLimitsTest {
    @TempDir
    Path dir;

    /** Five valid poses of each format; the fifth pose is on {@link Sample#fifthPoseLine}. */
    enum Sample {
        CSV("five.csv", "t,x,y,yaw\n0,0,0,0\n1,1,0,0\n2,2,0,0\n3,3,0,0\n4,4,0,0\n", 6),
        TUM("five.txt", "0 0 0 0 0 0 0 1\n1 1 0 0 0 0 0 1\n2 2 0 0 0 0 0 1\n3 3 0 0 0 0 0 1\n4 4 0 0 0 0 0 1\n", 5),
        KITTI("five.kitti", "1 0 0 0 0 1 0 0 0 0 1 0\n1 0 0 1 0 1 0 0 0 0 1 0\n1 0 0 2 0 1 0 0 0 0 1 0\n"
                + "1 0 0 3 0 1 0 0 0 0 1 0\n1 0 0 4 0 1 0 0 0 0 1 0\n", 5),
        EUROC("five.csv", "#timestamp,p_x,p_y,p_z,q_w,q_x,q_y,q_z\n"
                + "1403715271000000000,0,0,0,1,0,0,0\n1403715272000000000,1,0,0,1,0,0,0\n"
                + "1403715273000000000,2,0,0,1,0,0,0\n1403715274000000000,3,0,0,1,0,0,0\n"
                + "1403715275000000000,4,0,0,1,0,0,0\n", 6);

        final String name;
        final String text;
        final int fifthPoseLine;

        Sample(String name, String text, int fifthPoseLine) {
            this.name = name;
            this.text = text;
            this.fifthPoseLine = fifthPoseLine;
        }

        TrajectoryFormat format() {
            return TrajectoryFormat.valueOf(name());
        }
    }

    private Path write(Sample s) throws IOException {
        Path p = dir.resolve(s.name);
        Files.write(p, s.text.getBytes(StandardCharsets.US_ASCII));
        return p;
    }

    @ParameterizedTest
    @EnumSource(Sample.class)
    void onePoseOverTheLimitIsRefusedAtItsLine(Sample s) throws IOException {
        Path p = write(s);
        for (TrajectoryFormat f : new TrajectoryFormat[] {s.format(), null}) {
            InputException e = assertThrows(InputException.class, () -> TrajectoryReader.read(p,
                    ReadOptions.defaults().withFormat(f).withLimits(ReadOptions.DEFAULT_MAX_BYTES, 4)));
            assertEquals(InputProblem.TOO_LARGE, e.problem());
            assertEquals(s.fifthPoseLine, e.line());
            assertEquals(5, TrajectoryReader.read(p, ReadOptions.defaults().withFormat(f)
                    .withLimits(ReadOptions.DEFAULT_MAX_BYTES, 5)).trajectory().size());
        }
    }

    @ParameterizedTest
    @EnumSource(Sample.class)
    void oneByteOverTheLimitIsRefusedBeforeReading(Sample s) throws IOException {
        Path p = write(s);
        long size = Files.size(p);
        for (TrajectoryFormat f : new TrajectoryFormat[] {s.format(), null}) {
            InputException e = assertThrows(InputException.class, () -> TrajectoryReader.read(p,
                    ReadOptions.defaults().withFormat(f).withLimits(size - 1, ReadOptions.DEFAULT_MAX_POSES)));
            assertEquals(InputProblem.TOO_LARGE, e.problem());
            assertEquals(0, e.line());
            assertEquals(5, TrajectoryReader.read(p, ReadOptions.defaults().withFormat(f)
                    .withLimits(size, ReadOptions.DEFAULT_MAX_POSES)).trajectory().size());
        }
    }

    @ParameterizedTest
    @EnumSource(Sample.class)
    void nonPositiveLimitsAreRefusedAsOptions(Sample s) throws IOException {
        Path p = write(s);
        InputException e = assertThrows(InputException.class, () -> TrajectoryReader.read(p,
                ReadOptions.defaults().withFormat(s.format()).withLimits(0, 10)));
        assertEquals(InputProblem.INVALID_OPTION, e.problem());
    }
}
