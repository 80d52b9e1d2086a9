package org.trajeval.core.io;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Auto-detection on small synthetic files; the real files are covered in {@link RefdataReadingTest}. */
class FormatDetectionTest {
    @TempDir
    Path dir;

    private LoadedTrajectory read(String name, String content) throws IOException {
        return TrajectoryReader.read(Files.writeString(dir.resolve(name), content), ReadOptions.defaults());
    }

    @Test
    void csvHeaderIsRecognisedWhateverTheExtension() throws IOException {
        LoadedTrajectory t = read("run.txt", "# planar\nt,x,y,yaw\n0,1,2,0.5\n");
        assertEquals(TrajectoryFormat.CSV, t.format());
        assertEquals("auto: header names t, x, y, yaw (CSV)", t.formatReason());
    }

    @Test
    void eurocWithoutHeaderIsRecognisedByNanosecondStampsAndSeventeenColumns() throws IOException {
        LoadedTrajectory t = read("gt.csv",
                "1403715524907143168,0.515356,1.996773,0.971104,0.161996,0.789985,-0.205376,0.554528,"
                        + "-0.002276,-0.009616,-0.005214,-0.002153,0.020744,0.075806,-0.013337,0.103464,0.093086\n");
        assertEquals(TrajectoryFormat.EUROC, t.format());
        assertEquals("auto: 17 comma-separated numeric columns, the first of nanosecond size (EuRoC)", t.formatReason());
    }

    @Test
    void eightNumbersAreTumAndTwelveAreKitti() throws IOException {
        assertEquals("auto: 8 numeric columns (TUM)", read("a.txt", "1.0 0 0 0 0 0 0 1\n").formatReason());
        LoadedTrajectory kitti = read("b.txt", "1 0 0 0 0 1 0 0 0 0 1 0\n");
        assertEquals(TrajectoryFormat.KITTI, kitti.format());
        assertEquals("auto: 12 numeric columns (KITTI)", kitti.formatReason());
    }

    @Test
    void tumExtensionWinsOverContent() throws IOException {
        LoadedTrajectory t = read("x.tum", "1.0\t0 0 0   0 0 0 1\n");
        assertEquals(TrajectoryFormat.TUM, t.format());
        assertEquals("auto: extension .tum (TUM)", t.formatReason());
    }

    @Test
    void windowsLineEndsAndAByteOrderMarkReadAsPlainLines() throws IOException {
        LoadedTrajectory t = read("w.csv", "\uFEFFt,x,y,yaw\r\n0,1,2,3\r\n1,4,5,6");
        assertEquals(TrajectoryFormat.CSV, t.format());
        assertEquals(2, t.trajectory().size());
        assertEquals(4.0, t.trajectory().x(1), 0.0);
    }

    @Test
    void columnsAreFoundByNameInAnyOrderWithOtherDelimiterAndUnit() throws IOException {
        Path file = Files.writeString(dir.resolve("ms.csv"), "heading;time_ms;px;py;speed\n0.5;1500;1;2;9\n");
        ReadOptions options = ReadOptions.defaults()
                .withCsv(new CsvLayout("time_ms", "px", "py", "heading", ';', TimeUnit.MS));
        LoadedTrajectory t = TrajectoryReader.read(file, options);
        assertEquals(1.5, t.trajectory().t(0), 0.0); // 1500 ms
        assertEquals(1.0, t.trajectory().x(0), 0.0);
        assertEquals(0.5, ((org.trajeval.core.traj.PlanarTrajectory) t.trajectory()).yaw(0), 0.0);
    }
}
