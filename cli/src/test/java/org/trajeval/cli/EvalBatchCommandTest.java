package org.trajeval.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** {@code trajeval eval --batch}: exit codes, one stderr line per failed pair, the files written. */
class EvalBatchCommandTest {
    @TempDir
    Path dir;

    private Path pairs(String table) throws IOException {
        StringBuilder sb = new StringBuilder("t,x,y,yaw\n");
        for (int i = 0; i <= 50; i++) {
            sb.append(i * 0.1).append(',').append(i * 0.1).append(",0,0\n");
        }
        Files.writeString(dir.resolve("gt.csv"), sb.toString());
        Files.writeString(dir.resolve("est.csv"), sb.toString().replace(",0,0\n", ",0.2,0\n"));
        Path p = dir.resolve("pairs.csv");
        Files.writeString(p, table);
        return p;
    }

    @Test
    void everyPairScoredExitsZeroAndWritesReportsAndSummary() throws IOException {
        Path table = pairs("name,ref,est,alignment\na,gt.csv,est.csv,none\nb,gt.csv,gt.csv,none\n");
        CliRun r = CliRun.of("eval", "--batch", table.toString(), "--reports",
                dir.resolve("out").toString(), "--threads", "2");
        assertEquals(0, r.code(), r.err());
        assertTrue(r.out().startsWith("scored 2 of 2 pairs"), r.out());
        assertTrue(Files.exists(dir.resolve("out/a.json")));
        assertTrue(Files.exists(dir.resolve("out/b.json")));
        assertEquals(3, Files.readAllLines(dir.resolve("out/summary.csv")).size());
    }

    @Test
    void aBadPairIsAFailedRowExitFourAndTheOthersAreStillScored() throws IOException {
        Path table = pairs("ref,est\ngt.csv,nowhere.csv\ngt.csv,est.csv\n");
        CliRun r = CliRun.of("eval", "--batch", table.toString(), "--reports",
                dir.resolve("out").toString());
        assertEquals(ExitCodes.SOME_FAILED, r.code(), r.err());
        assertEquals(1, r.err().lines().count(), r.err());
        assertTrue(r.err().startsWith("trajeval: " + table + ":2: pair not scored (unreadable): "), r.err());
        assertTrue(Files.exists(dir.resolve("out/line-0003.json")));
    }

    @Test
    void aBadTableOrMissingReportsFolderIsExitTwoAndNothingIsScored() throws IOException {
        Path table = pairs("reference,est\ngt.csv,est.csv\n");
        CliRun noRef = CliRun.of("eval", "--batch", table.toString(), "--reports",
                dir.resolve("out").toString());
        assertEquals(2, noRef.code());
        assertTrue(noRef.err().contains("the header must name the columns 'ref' and 'est'"), noRef.err());
        assertEquals(2, CliRun.of("eval", "--batch", table.toString()).code());
        assertEquals(2, CliRun.of("eval", "gt.csv", "--batch", table.toString(), "--reports",
                dir.resolve("out").toString()).code());
        assertTrue(!Files.exists(dir.resolve("out")));
    }
}
