package org.trajeval.pipeline;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.ByteBuffer;
import java.nio.channels.FileChannel;
import java.nio.charset.StandardCharsets;
import java.nio.file.AtomicMoveNotSupportedException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.StandardOpenOption;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.function.BiConsumer;

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
            Path dir = target.toAbsolutePath().getParent();
            Path tmp = null;
            try {
                Files.createDirectories(dir);
                tmp = Files.createTempFile(dir, "." + target.getFileName() + ".", ".tmp");
                try (FileChannel ch = FileChannel.open(tmp, StandardOpenOption.WRITE,
                        StandardOpenOption.TRUNCATE_EXISTING)) {
                    ByteBuffer b = ByteBuffer.wrap(text.getBytes(StandardCharsets.UTF_8));
                    while (b.hasRemaining()) {
                        ch.write(b);
                    }
                    ch.force(true);
                }
                try {
                    Files.setPosixFilePermissions(tmp, PosixFilePermissions.fromString("rw-r--r--"));
                } catch (UnsupportedOperationException ignored) {
                    // not a POSIX file system: keep the default mode
                }
                return new Written(target, tmp);
            } catch (IOException e) {
                deleteQuietly(tmp);
                throw new UncheckedIOException("could not write " + target, e);
            }
        }

        @Override
        public void publish(Staged staged) {
            Written w = (Written) staged;
            try {
                try {
                    Files.move(w.tmp(), w.target(), StandardCopyOption.ATOMIC_MOVE,
                            StandardCopyOption.REPLACE_EXISTING);
                } catch (AtomicMoveNotSupportedException e) {
                    Files.move(w.tmp(), w.target(), StandardCopyOption.REPLACE_EXISTING);
                }
            } catch (IOException e) {
                deleteQuietly(w.tmp());
                throw new UncheckedIOException("could not write " + w.target(), e);
            }
        }

        @Override
        public void syncFolder(Path dir) {
            try (FileChannel ch = FileChannel.open(dir, StandardOpenOption.READ)) {
                ch.force(true);
            } catch (IOException ignored) {
                // some file systems cannot open a directory for fsync; the rename is still atomic
            }
        }

        @Override
        public void discard(Staged staged) {
            deleteQuietly(((Written) staged).tmp());
        }

        private static void deleteQuietly(Path p) {
            if (p == null) {
                return;
            }
            try {
                Files.deleteIfExists(p);
            } catch (IOException ignored) {
                // a leftover temporary file is removed by the next start once stale (StaleTempFiles)
            }
        }
    }
}
