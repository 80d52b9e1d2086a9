package org.trajeval.spark;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.ObjectOutputStream;
import java.io.Serializable;
import java.io.UncheckedIOException;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.Iterator;
import java.util.Map;
import org.apache.spark.api.java.function.MapPartitionsFunction;
import org.apache.spark.sql.Row;
import org.apache.spark.sql.RowFactory;
import org.trajeval.core.io.LoadedTrajectory;
import org.trajeval.core.protocol.RunEngine;
import org.trajeval.core.protocol.RunResult;
import org.trajeval.core.protocol.RunScorer;
import org.trajeval.core.protocol.RunTask;

/**
 * Scores the run tasks of one partition ({@link SuiteJob#TASKS} rows in, {@link SuiteJob#RESULTS}
 * rows out) with core's per-run step: the manifest is parsed once per partition (and must be the one
 * the driver planned from: same SHA-256), each sequence's reference read once per partition, each
 * task scored by {@link RunScorer#score}. A run that cannot be scored is a failed result, as in
 * {@code trajeval suite}; the task is deterministic, so a rerun gives the same bytes.
 */
final class SuiteRunScorer implements MapPartitionsFunction<Row, Row>, Serializable {
    private static final long serialVersionUID = 1L;

    private final String manifest;
    private final String sha256;

    /**
     * @param manifest the manifest's absolute path
     * @param sha256 its SHA-256 when the driver planned the suite
     */
    SuiteRunScorer(String manifest, String sha256) {
        this.manifest = manifest;
        this.sha256 = sha256;
    }

    @Override
    public Iterator<Row> call(Iterator<Row> tasks) {
        RunScorer scorer = RunScorer.of(RunEngine.standard(), Path.of(manifest), sha256);
        Map<String, LoadedTrajectory> references = new HashMap<>();
        return new Iterator<>() {
            @Override
            public boolean hasNext() {
                return tasks.hasNext();
            }

            @Override
            public Row next() {
                Row r = tasks.next();
                RunTask t = new RunTask(r.getInt(0), r.getString(1), r.getString(2), r.getLong(3), r.getString(4));
                RunResult result = scorer.score(t, references.computeIfAbsent(t.sequence(), scorer::reference));
                return RowFactory.create(t.index(), serialise(result));
            }
        };
    }

    private static byte[] serialise(RunResult result) {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        try (ObjectOutputStream out = new ObjectOutputStream(bytes)) {
            out.writeObject(result);
        } catch (IOException e) {
            throw new UncheckedIOException("a run's result could not be serialised", e);
        }
        return bytes.toByteArray();
    }
}
