package org.trajeval.pipeline;

import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.function.BiConsumer;
import org.trajeval.core.report.ReportJson;

/**
 * How report files become durable in two steps, so that a group commit holds the ledger's lock only
 * for the renames: {@link #stage} writes the text to a temporary file beside the report's name
 * ({@code .NAME.json.DIGITS.tmp}, mode 0644) and fsyncs it, outside the lock; {@link #publish} renames
 * it into place (atomic) under the lock; {@link #syncFolder} fsyncs the folder once for every report a
 * group renamed. Until the folder's fsync a report may be lost by a crash, and its run is then
 * scored again (its ledger line is appended only after that fsync).
 */
public interface ReportFiles {
    /** A report written and fsync'd, not yet in place. */
    interface Staged {
        /** @return the file it becomes */
        Path target();
    }

    /**
     * Writes {@code text} for {@code target} and fsyncs it.
     *
     * @throws UncheckedIOException when it cannot be written (the caller's run is not at fault)
     */
    Staged stage(Path target, String text);

    /** Moves a staged report to its target, replacing a file left there by a crash. */
    void publish(Staged staged);

    /** Fsyncs a folder after {@link #publish} of its reports (a file system that cannot: ignored). */
    void syncFolder(Path dir);

    /** Deletes a staged report that is not published (a duplicate, a failed group, a changed version). */
    void discard(Staged staged);

    /** @return report files written as above (temporary file, fsync, rename, the folder's fsync) */
    static ReportFiles durable() {
        return new Durable();
    }

    /**
     * @return report files written by {@code writer} whole (it writes atomically and durably on its own)
     *     at {@link #publish}, under the lock; {@link #stage} only keeps the text (tests inject storage
     *     faults through such a writer)
     */
    static ReportFiles writtenBy(BiConsumer<Path, String> writer) {
        record Kept(Path target, String text) implements Staged {
        }
        return new ReportFiles() {
            @Override
            public Staged stage(Path target, String text) {
                return new Kept(target, text);
            }

            @Override
            public void publish(Staged staged) {
                Kept k = (Kept) staged;
                writer.accept(k.target(), k.text());
            }

            @Override
            public void syncFolder(Path dir) {
                // the writer synced its folder
            }

            @Override
            public void discard(Staged staged) {
                // nothing written
            }
        };
    }

    /** The temporary file, fsync, rename and folder fsync of {@code ReportJson.writeAtomically}, in two steps. */
    final class Durable implements ReportFiles {
        private record Written(Path target, Path tmp) implements Staged {
        }

        @Override
        public Staged stage(Path target, String text) {
            byte[] bytes = text.getBytes(StandardCharsets.UTF_8);
            return new Written(target, ReportJson.writeBeside(target, out -> out.write(bytes)));
        }

        @Override
        public void publish(Staged staged) {
            Written w = (Written) staged;
            try {
                ReportJson.moveIntoPlace(w.tmp(), w.target());
            } catch (UncheckedIOException e) {
                ReportJson.deleteQuietly(w.tmp());
                throw e;
            }
        }

        @Override
        public void syncFolder(Path dir) {
            ReportJson.fsyncDirectory(dir);
        }

        @Override
        public void discard(Staged staged) {
            ReportJson.deleteQuietly(((Written) staged).tmp());
        }
    }
}
