package org.trajeval.pipeline.dir;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.FileTime;
import java.time.Clock;
import java.time.Instant;
import java.time.ZoneOffset;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.trajeval.core.report.ReportJson;

class StaleTempFilesTest {
    @TempDir
    Path dir;

    @Test
    void theNameOfCoresTemporaryReportFileIsOneItRecognises() {
        Path tmp = ReportJson.writeBeside(dir.resolve("run-7.json"), out -> out.write("{}".getBytes(StandardCharsets.UTF_8)));
        try {
            assertTrue(StaleTempFiles.OURS.matcher(tmp.getFileName().toString()).matches(), tmp.getFileName().toString());
        } finally {
            ReportJson.deleteQuietly(tmp);
        }
    }

    @Test
    void removesOnlyItsOwnTemporaryFilesOlderThanTheMinimumAge() throws Exception {
        Instant now = Instant.parse("2026-11-26T12:00:00Z");
        Path old = touch(".run-1.json.123.tmp", now.minus(StaleTempFiles.MIN_AGE).minusSeconds(1));
        Path fresh = touch(".run-2.json.456.tmp", now.minus(StaleTempFiles.MIN_AGE).plusSeconds(60));
        Path notOurs = touch("run-3.json.789.tmp", now.minusSeconds(3600));
        Path report = touch("run-4.json", now.minusSeconds(3600));

        int removed = StaleTempFiles.clean(dir, Clock.fixed(now, ZoneOffset.UTC));

        assertEquals(1, removed);
        assertFalse(Files.exists(old));
        assertTrue(Files.exists(fresh));
        assertTrue(Files.exists(notOurs));
        assertTrue(Files.exists(report));
    }

    private Path touch(String name, Instant modified) throws Exception {
        Path p = Files.writeString(dir.resolve(name), "x");
        Files.setLastModifiedTime(p, FileTime.from(modified));
        return p;
    }
}
