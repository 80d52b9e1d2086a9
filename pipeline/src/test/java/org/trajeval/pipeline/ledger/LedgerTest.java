package org.trajeval.pipeline.ledger;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class LedgerTest {
    @TempDir
    Path dir;

    @Test
    void entriesSurviveARestart() {
        Path f = dir.resolve("ledger.log");
        try (Ledger l = Ledger.open(f)) {
            l.locked(v -> {
                v.append(new LedgerEntry("r1", "h1", 1, 10, "b1"));
                v.append(new LedgerEntry("r1", "h2", 2, 20, "b2"));
                return null;
            });
        }
        try (Ledger l = Ledger.open(f)) {
            assertEquals(2, (int) l.locked(v -> v.latestVersion("r1")));
            assertTrue(l.locked(v -> v.find("r1", "h2")).isPresent());
            assertEquals(0, (int) l.locked(v -> v.latestVersion("r2")));
        }
    }

    @Test
    void aGroupOfEntriesIsAppendedInOrderAndEachIsFoundAtOnceAndAfterARestart() throws IOException {
        Path f = dir.resolve("ledger.log");
        var group = java.util.List.of(new LedgerEntry("r1", "h1", 1, 10, "b1"), new LedgerEntry("r2", "h2", 1, 11, "b2"),
                new LedgerEntry("r1", "h3", 2, 12, "b3"));
        try (Ledger l = Ledger.open(f)) {
            l.locked(v -> {
                v.appendAll(group);
                // indexed where each line lies: found by content, in this process, without a re-read
                assertEquals("b3", v.find("r1", "h3").orElseThrow().source());
                assertEquals("b2", v.find("r2", "h2").orElseThrow().source());
                return null;
            });
            assertEquals(2, l.probableLatestVersion("r1"));
            assertTrue(l.probablyReported("r1", "h1"));
        }
        // one line per entry, in the group's order
        assertEquals(3, Files.readAllLines(f).size());
        assertTrue(Files.readAllLines(f).get(2).startsWith("R\tr1\th3\t2\t"));
        try (Ledger l = Ledger.open(f)) {
            assertEquals(group, l.entries());
        }
    }

    @Test
    void aLineCutShortByACrashIsIgnoredAndCutOff() throws IOException {
        Path f = dir.resolve("ledger.log");
        try (Ledger l = Ledger.open(f)) {
            l.locked(v -> {
                v.append(new LedgerEntry("r1", "h1", 1, 10, "b1"));
                return null;
            });
        }
        Files.writeString(f, "R\tr2\th9\t1\t3", StandardOpenOption.APPEND); // no newline: the append never finished
        try (Ledger l = Ledger.open(f)) {
            assertTrue(l.locked(v -> v.find("r2", "h9")).isEmpty());
            l.locked(v -> {
                v.append(new LedgerEntry("r3", "h3", 1, 30, "b3"));
                return null;
            });
        }
        assertEquals(2, Files.readAllLines(f).size());
        try (Ledger l = Ledger.open(f)) {
            assertTrue(l.locked(v -> v.find("r3", "h3")).isPresent());
        }
    }

    @Test
    void twoLedgersOnOneFileSeeEachOthersAppends() {
        Path f = dir.resolve("ledger.log");
        try (Ledger a = Ledger.open(f); Ledger b = Ledger.open(f)) {
            a.locked(v -> {
                v.append(new LedgerEntry("r1", "h1", 1, 10, "a"));
                return null;
            });
            assertEquals(1, (int) b.locked(v -> v.latestVersion("r1")));
        }
    }

    @Test
    void aLookupComparesTheWholeHashReadBackFromTheFile() {
        // the ledger keeps only a hash code per version in memory: "Aa" and "BB" share String.hashCode (2112),
        // so finding "BB" must read the "Aa" line back and tell them apart
        assertEquals("Aa".hashCode(), "BB".hashCode());
        Path f = dir.resolve("ledger.log");
        try (Ledger a = Ledger.open(f); Ledger b = Ledger.open(f)) {
            a.locked(v -> {
                v.append(new LedgerEntry("r1", "Aa", 1, 10, "first"));
                v.append(new LedgerEntry("r2", "x", 1, 11, "other"));
                return null;
            });
            for (Ledger l : new Ledger[] {a, b}) { // the appender, and a reader that caught up from the file
                assertTrue(l.locked(v -> v.find("r1", "BB")).isEmpty());
                assertEquals(new LedgerEntry("r1", "Aa", 1, 10, "first"), l.locked(v -> v.find("r1", "Aa")).orElseThrow());
                assertTrue(l.probablyReported("r1", "Aa"));
                assertEquals(java.util.List.of(new LedgerEntry("r1", "Aa", 1, 10, "first"),
                        new LedgerEntry("r2", "x", 1, 11, "other")), l.entries());
            }
        }
    }
}
