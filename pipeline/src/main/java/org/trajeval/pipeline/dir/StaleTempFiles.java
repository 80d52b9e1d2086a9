package org.trajeval.pipeline.dir;

import java.io.IOException;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.time.Clock;
import java.time.Duration;
import java.util.regex.Pattern;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import org.trajeval.core.InputText;

/**
 * Removes the temporary files of atomic writes that a killed process left behind
 * ({@code reports/.RUN_ID.json.123.tmp}, {@code failed/.SLOT.error.json.123.tmp}). Only names of
 * that exact pattern (the one {@code ReportJson.writeAtomically} makes) and only files older than
 * {@link #MIN_AGE}: another live instance may be writing one right now, and a write takes
 * milliseconds, so a file that old belongs to nobody.
 */
final class StaleTempFiles {
    /** Age from which a temporary file is taken as abandoned. */
    static final Duration MIN_AGE = Duration.ofMinutes(10);
    /** {@code .NAME.json.DIGITS.tmp}: the temporary name {@code ReportJson.writeBeside} gives a file NAME.json. */
    static final Pattern OURS = Pattern.compile("\\..+\\.json\\.[0-9]+\\.tmp");
    private static final Logger LOG = LoggerFactory.getLogger(StaleTempFiles.class);

    private StaleTempFiles() {
    }

    /** @return how many stale temporary files were removed from {@code dir} */
    static int clean(Path dir, Clock clock) {
        int removed = 0;
        long cutoff = clock.millis() - MIN_AGE.toMillis();
        try (DirectoryStream<Path> ds = Files.newDirectoryStream(dir)) {
            for (Path p : ds) {
                if (OURS.matcher(p.getFileName().toString()).matches()
                        && Files.isRegularFile(p, LinkOption.NOFOLLOW_LINKS)
                        && Files.getLastModifiedTime(p, LinkOption.NOFOLLOW_LINKS).toMillis() < cutoff
                        && Files.deleteIfExists(p)) {
                    removed++;
                }
            }
        } catch (IOException e) {
            LOG.warn("could not clean temporary files in {}: {}", InputText.escape(dir.toString()), e.toString());
        }
        if (removed > 0) {
            LOG.info("removed {} stale temporary file(s) from {}", removed, InputText.escape(dir.toString()));
        }
        return removed;
    }
}
