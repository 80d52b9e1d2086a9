package org.trajeval.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Clock;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.trajeval.store.ResultsStore;
import org.trajeval.store.RunRecord;
import org.trajeval.store.Selection;
import org.trajeval.store.StoreLocation;

/** {@code eval --db}: the evaluation goes into the results store once, with its labels. */
class EvalDbTest {
    private static final double ATE_TOL_M = 1e-12;

    @TempDir
    Path dir;

    /** A straight line at 1 m/s, 10 Hz for 10 s; the estimate 0.1 m to the left: ATE 0.1 m by hand. */
    private Path[] pair() throws IOException {
        StringBuilder gt = new StringBuilder("t,x,y,yaw\n");
        StringBuilder est = new StringBuilder("t,x,y,yaw\n");
        for (int i = 0; i <= 100; i++) {
            double t = i * 0.1;
            gt.append(t).append(',').append(t).append(",0,0\n");
            est.append(t).append(',').append(t).append(",0.1,0\n");
        }
        Path g = Files.writeString(dir.resolve("gt.csv"), gt);
        Path e = Files.writeString(dir.resolve("est.csv"), est);
        return new Path[] {g, e};
    }

    private List<RunRecord> stored(Path db) {
        try (ResultsStore s = ResultsStore.open(StoreLocation.sqlite(db), Clock.systemUTC())) {
            return s.select(Selection.all());
        }
    }

    @Test
    void evalRecordsOneRowWithItsLabelsAndARerunAddsNothing() throws IOException {
        Path[] p = pair();
        Path db = dir.resolve("fleet.db");
        String[] args = {"eval", p[0].toString(), p[1].toString(), "--align", "none", "--db", db.toString(), "--tag",
            "software_version=2.4", "--tag", "route=hall", "--tag", "method=orb", "--tag", "seed=3", "--tag",
            "robot=bot-1", "--tag", "site=hamburg", "--tag", "shift=night"};
        CliRun first = CliRun.of(args);
        assertEquals(0, first.code(), first.err());
        assertTrue(first.err().contains("recorded the result in"), first.err());
        CliRun again = CliRun.of(args);
        assertEquals(0, again.code(), again.err());
        assertTrue(again.err().contains("the result was already in"), again.err());
        List<RunRecord> rows = stored(db);
        assertEquals(1, rows.size());
        RunRecord r = rows.get(0);
        assertEquals("eval", r.origin());
        assertEquals("2.4", r.softwareVersion());
        assertEquals("hall", r.route());
        assertEquals("orb", r.method());
        assertEquals(3L, r.seed());
        assertEquals("bot-1", r.robot());
        assertEquals("hamburg", r.site());
        assertEquals(Map.of("shift", "night"), r.tags());
        assertEquals(0.1, r.metric("ate_trans_rmse_m"), ATE_TOL_M);
    }

    @Test
    void importingTheOutFileOfARecordedEvalAddsNothing() throws IOException {
        Path[] p = pair();
        Path db = dir.resolve("fleet.db");
        Path out = dir.resolve("reports/r.json");
        CliRun r = CliRun.of("eval", p[0].toString(), p[1].toString(), "--out", out.toString(), "--db",
                db.toString(), "--tag", "software_version=2.4");
        assertEquals(0, r.code(), r.err());
        CliRun imp = CliRun.of("db", "import", out.getParent().toString(), "--db", db.toString(), "--tag",
                "software_version=2.4");
        assertEquals(0, imp.code(), imp.err());
        assertTrue(imp.out().contains("1 result(s), 0 new"), imp.out());
        // other labels are another result
        CliRun other = CliRun.of("db", "import", out.toString(), "--db", db.toString(), "--tag",
                "software_version=2.5");
        assertTrue(other.out().contains("1 result(s), 1 new"), other.out());
        assertEquals(2, stored(db).size());
    }

    @Test
    void aTagWithoutDbOrASeedThatIsNoNumberIsRefusedBeforeEvaluating() throws IOException {
        Path[] p = pair();
        CliRun noDb = CliRun.of("eval", p[0].toString(), p[1].toString(), "--tag", "route=hall");
        assertEquals(ExitCodes.BAD_INPUT, noDb.code());
        assertTrue(noDb.err().contains("--tag labels the stored result: it needs --db"), noDb.err());
        Path db = dir.resolve("fleet.db");
        CliRun seed = CliRun.of("eval", p[0].toString(), p[1].toString(), "--db", db.toString(), "--tag",
                "seed=three");
        assertEquals(ExitCodes.BAD_INPUT, seed.code());
        assertEquals("trajeval: seed: expected an integer, found \"three\"", seed.err().strip());
        assertFalse(Files.exists(db), "nothing evaluated or stored");
    }
}
