package org.trajeval.pipeline.ledger;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Random;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicReference;
import java.util.function.ToLongFunction;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The ledger's compact index ({@link RunIndex}): a run id is found by a 64-bit key, and every key match is
 * confirmed from the file, so keys that collide never make two runs one. Reference answers come from the
 * general path: a plain map of the entries the test appended.
 */
class LedgerIndexTest {
    private static final ToLongFunction<String> ONE_KEY = id -> 42L;

    @TempDir
    Path dir;

    private static void append(Ledger l, LedgerEntry... es) {
        l.locked(v -> {
            v.appendAll(List.of(es));
            return null;
        });
    }

    @Test
    void twoRunIdsWithTheSameKeyStayTwoRuns() {
        Path f = dir.resolve("ledger.log");
        try (Ledger l = Ledger.open(f, ONE_KEY)) {
            append(l, new LedgerEntry("r1", "h1", 1, 10, "a"), new LedgerEntry("r2", "h1", 1, 11, "b"));
            append(l, new LedgerEntry("r1", "h2", 2, 12, "c"));
            for (int pass = 0; pass < 2; pass++) {
                assertEquals(2, l.probableLatestVersion("r1"));
                assertEquals(1, l.probableLatestVersion("r2"));
                assertEquals(0, l.probableLatestVersion("r3"));
                assertEquals("b", l.locked(v -> v.find("r2", "h1")).orElseThrow().source());
                assertEquals("a", l.locked(v -> v.find("r1", "h1")).orElseThrow().source());
                assertTrue(l.locked(v -> v.find("r2", "h2")).isEmpty());
                assertFalse(l.probablyReported("r3", "h1"));
            }
        }
        try (Ledger l = Ledger.open(f, ONE_KEY)) { // rebuilt from the file
            assertEquals(2, l.probableLatestVersion("r1"));
            assertEquals(1, l.probableLatestVersion("r2"));
            assertEquals("c", l.locked(v -> v.find("r1", "h2")).orElseThrow().source());
            assertTrue(l.locked(v -> v.find("r2", "h2")).isEmpty());
        }
    }

    @Test
    void versionsChainAndEveryOneIsFound() {
        Path f = dir.resolve("ledger.log");
        try (Ledger l = Ledger.open(f)) {
            for (int v = 1; v <= 50; v++) {
                append(l, new LedgerEntry("run", "h" + v, v, v, "s" + v));
            }
            assertEquals(50, l.probableLatestVersion("run"));
            for (int v = 1; v <= 50; v++) {
                String hash = "h" + v;
                assertEquals(new LedgerEntry("run", hash, v, v, "s" + v), l.locked(view -> view.find("run", hash)).orElseThrow());
            }
            assertTrue(l.locked(view -> view.find("run", "h51")).isEmpty());
        }
    }

    @Test
    void manyRunsWithFewKeysGiveTheAnswersOfAPlainMapBeforeAndAfterAReopen() {
        // 3000 versions of 2000 runs (more than one page of entries, the table grown twice) under keys that
        // collide in groups of about 100; the answers must equal those of a map of what was appended
        ToLongFunction<String> fewKeys = id -> id.hashCode() % 20;
        Path f = dir.resolve("ledger.log");
        Random rnd = new Random(13);
        Map<String, List<LedgerEntry>> appended = new HashMap<>();
        try (Ledger l = Ledger.open(f, fewKeys)) {
            List<LedgerEntry> group = new ArrayList<>();
            for (int i = 0; i < 3000; i++) {
                String run = "run-" + rnd.nextInt(2000);
                List<LedgerEntry> versions = appended.computeIfAbsent(run, k -> new ArrayList<>());
                LedgerEntry e = new LedgerEntry(run, "hash-" + i, versions.size() + 1, i, "src-" + i);
                versions.add(e);
                group.add(e);
                if (group.size() == 7) {
                    append(l, group.toArray(new LedgerEntry[0]));
                    group.clear();
                }
            }
            append(l, group.toArray(new LedgerEntry[0]));
            assertSameAnswers(appended, l);
        }
        try (Ledger l = Ledger.open(f, fewKeys)) {
            assertSameAnswers(appended, l);
        }
        try (Ledger l = Ledger.open(f)) { // the default key gives the same answers
            assertSameAnswers(appended, l);
        }
    }

    private static void assertSameAnswers(Map<String, List<LedgerEntry>> appended, Ledger l) {
        for (int r = 0; r < 2100; r++) { // includes ids never appended
            String run = "run-" + r;
            List<LedgerEntry> versions = appended.getOrDefault(run, List.of());
            assertEquals(versions.size(), l.probableLatestVersion(run), run);
            for (LedgerEntry e : versions) {
                assertEquals(Optional.of(e), l.locked(v -> v.find(run, e.contentHash())), run);
            }
            assertFalse(l.probablyReported(run, "hash-none"), run);
        }
    }

    @Test
    void aSecondProcessAppendingUnderACollidingKeyIsSeen() {
        Path f = dir.resolve("ledger.log");
        try (Ledger a = Ledger.open(f, ONE_KEY); Ledger b = Ledger.open(f, ONE_KEY)) {
            append(a, new LedgerEntry("r1", "h1", 1, 10, "a"));
            append(b, new LedgerEntry("r2", "h2", 1, 11, "b")); // b catches up with a's line first
            append(a, new LedgerEntry("r2", "h3", 2, 12, "a2"));
            for (Ledger l : new Ledger[] {a, b}) {
                l.locked(v -> null); // catch up
                assertEquals(1, l.probableLatestVersion("r1"));
                assertEquals(2, l.probableLatestVersion("r2"));
                assertEquals("b", l.locked(v -> v.find("r2", "h2")).orElseThrow().source());
                assertEquals("a2", l.locked(v -> v.find("r2", "h3")).orElseThrow().source());
                assertTrue(l.locked(v -> v.find("r1", "h2")).isEmpty());
            }
        }
    }

    @Test
    void theHintsReadWithoutTheLockSeeEveryCommitThatReturned() throws InterruptedException {
        // a reader polls the hints while the writer commits 2000 runs in groups of 10 (the table grows
        // and pages are added meanwhile): a run whose commit returned before the read is always seen, with
        // its version, and no run is ever seen with a version it was not given
        Path f = dir.resolve("ledger.log");
        int runs = 2000;
        try (Ledger l = Ledger.open(f)) {
            AtomicInteger committed = new AtomicInteger();
            AtomicReference<String> failure = new AtomicReference<>();
            Thread reader = new Thread(() -> {
                Random rnd = new Random(5);
                while (committed.get() < runs && failure.get() == null) {
                    int done = committed.get();
                    int r = rnd.nextInt(runs);
                    int version = l.probableLatestVersion("run-" + r);
                    boolean reported = l.probablyReported("run-" + r, "hash-" + r);
                    if (r < done && (version != 1 || !reported) || version > 1) {
                        failure.set("run-" + r + " read as version " + version + ", reported " + reported
                                + " with " + done + " committed");
                    }
                }
            });
            reader.start();
            for (int i = 0; i < runs; i += 10) {
                LedgerEntry[] group = new LedgerEntry[10];
                for (int k = 0; k < 10; k++) {
                    group[k] = new LedgerEntry("run-" + (i + k), "hash-" + (i + k), 1, i + k, "");
                }
                append(l, group);
                committed.set(i + 10);
            }
            reader.join();
            assertEquals(null, failure.get());
        }
    }
}
