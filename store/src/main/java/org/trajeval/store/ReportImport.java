package org.trajeval.store;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;

/**
 * {@code trajeval db import DIR}: records every trajeval report under a folder (or one file):
 * pipeline reports, suite {@code report.json} files and eval reports ({@code eval --out}); other JSON files are counted and left
 * alone, hidden and temporary names ({@code .x}, {@code *.tmp}) skipped. Results already stored
 * are no-ops, so an import can be repeated, run beside a live pipeline, or rebuild a lost store.
 */
public final class ReportImport {
    private static final int BATCH = 2000;

    /**
     * @param files report files read
     * @param results results found in them
     * @param inserted results that were new to the store
     * @param skipped JSON files that are no trajeval report
     */
    public record Summary(int files, int results, int inserted, int skipped) {
    }

    private ReportImport() {
    }

    /**
     * @param store where to record
     * @param root a folder (searched recursively) or one report file
     * @param labels labels for every result
     * @throws StoreException BAD_REPORT on a file that is not JSON or a broken trajeval report
     */
    public static Summary run(ResultsStore store, Path root, Labels labels) {
        List<Path> files;
        if (Files.isDirectory(root)) {
            try (Stream<Path> s = Files.walk(root)) {
                files = s.filter(Files::isRegularFile).filter(ReportImport::looksLikeReport).sorted().toList();
            } catch (IOException e) {
                throw new UncheckedIOException("cannot list " + root + ": " + e.getMessage(), e);
            }
        } else if (Files.isRegularFile(root)) {
            files = List.of(root);
        } else {
            throw new StoreException(StoreException.Problem.BAD_REPORT, root + ": no such file or folder", null);
        }
        int results = 0;
        int inserted = 0;
        int skipped = 0;
        List<RunRecord> batch = new ArrayList<>();
        for (Path f : files) {
            String json;
            Instant mtime;
            try {
                json = Files.readString(f, StandardCharsets.UTF_8);
                mtime = Files.getLastModifiedTime(f).toInstant();
            } catch (IOException e) {
                throw new StoreException(StoreException.Problem.BAD_REPORT, f + ": cannot read ("
                        + e.getClass().getSimpleName() + ")", e);
            }
            switch (ReportRecords.kind(json, f.toString())) {
                case PIPELINE -> batch.add(ReportRecords.fromPipeline(json, f.toString(), labels));
                case EVALUATION -> batch.add(ReportRecords.fromEvaluation(json, f.toString(), mtime, labels));
                case SUITE -> batch.addAll(ReportRecords.fromSuite(ReportRecords.parseSuite(json, f.toString()),
                        f.toString(), mtime, labels));
                default -> skipped++;
            }
            if (batch.size() >= BATCH) {
                results += batch.size();
                inserted += store.record(batch);
                batch.clear();
            }
        }
        results += batch.size();
        inserted += store.record(batch);
        if (inserted >= ResultsStore.OPTIMIZE_EVERY) {
            store.optimize(); // statistics for the planner after a bulk load
        }
        return new Summary(files.size(), results, inserted, skipped);
    }

    private static boolean looksLikeReport(Path p) {
        String n = p.getFileName().toString();
        return n.endsWith(".json") && !n.startsWith(".") && !n.endsWith(".error.json");
    }
}
