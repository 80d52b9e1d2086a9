package org.trajeval.pipeline;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Moving a run's figures into place: one rename, an earlier folder (a retried run) replaced whole. */
class RunPlotsPublishTest {
    @TempDir
    Path reports;

    private static List<String> names(Path dir) throws IOException {
        try (Stream<Path> s = Files.list(dir)) {
            return s.map(p -> p.getFileName().toString()).sorted().toList();
        }
    }

    @Test
    void aRetryReplacesTheEarlierFolderWholeAndLeavesNoHiddenFolder() throws IOException {
        // a crash after the figures moved but before the report was written leaves a complete folder;
        // the retry draws again and moves its draft over it
        Path target = reports.resolve("run-1.plots");
        Files.createDirectories(target);
        Files.writeString(target.resolve("index.html"), "old");
        Files.writeString(target.resolve("stale.svg"), "old");
        Path draft = Files.createTempDirectory(reports, ".run-1.plots.");
        Files.writeString(draft.resolve("index.html"), "new");
        RunPlots.publish(draft, target);
        assertEquals(List.of("index.html"), names(target));
        assertEquals("new", Files.readString(target.resolve("index.html")));
        assertFalse(Files.exists(draft));
        assertEquals(List.of("run-1.plots"), names(reports));
    }
}
