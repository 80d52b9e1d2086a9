package org.trajeval.core.report;

import org.trajeval.core.InputException;
import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.DeserializationFeature;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.SerializationFeature;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.channels.FileChannel;
import java.nio.charset.StandardCharsets;
import java.nio.file.AtomicMoveNotSupportedException;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.StandardOpenOption;
import java.nio.file.attribute.FileAttribute;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.EnumSet;
import java.util.Set;
import java.util.concurrent.ThreadLocalRandom;

/** Reads and writes reports as JSON (Jackson stays behind this package). */
public final class ReportJson {
    private ReportJson() {
    }

    /**
     * The mapper, made on first use: a process that only writes an evaluation report (one
     * {@code eval --json}) never pays for its set-up (about 0.1 s cold), see {@link RecordJson}.
     */
    private static final class Mapper {
        static final ObjectMapper MAPPER = org.trajeval.core.io.StrictMappers.json()
                .registerModule(new com.fasterxml.jackson.databind.module.SimpleModule("finite-numbers")
                        .addSerializer(Double.class, new FiniteOrNull()).addSerializer(double.class, new FiniteOrNull()))
                .enable(SerializationFeature.INDENT_OUTPUT)
                .disable(DeserializationFeature.FAIL_ON_UNKNOWN_PROPERTIES);
    }

    /**
     * Writes a non-finite number as {@code null}: the report schema allows numbers or null, and
     * Jackson's default ("NaN", "Infinity" as strings) would break it. The readers bound their
     * inputs so that no statistic overflows; this is the last line of defence.
     */
    private static final class FiniteOrNull extends com.fasterxml.jackson.databind.ser.std.StdSerializer<Double> {
        private static final long serialVersionUID = 1L;

        FiniteOrNull() {
            super(Double.class);
        }

        @Override
        public void serialize(Double v, com.fasterxml.jackson.core.JsonGenerator g,
                com.fasterxml.jackson.databind.SerializerProvider p) throws IOException {
            if (v == null || !Double.isFinite(v)) {
                g.writeNull();
            } else {
                g.writeNumber(v);
            }
        }
    }

    /** @return the report as pretty-printed JSON, keys in schema order */
    public static String toJson(Object report) {
        if (report != null && RecordJson.supports(report.getClass())) {
            return RecordJson.write(report);
        }
        return mapperJson(report);
    }

    /** @return {@code report} as {@link #toJson} writes it, always through the Jackson mapper */
    static String mapperJson(Object report) {
        try {
            return Mapper.MAPPER.writeValueAsString(report);
        } catch (JsonProcessingException e) {
            throw new IllegalStateException("report could not be serialised", e);
        }
    }

    /** @return the evaluation report in {@code json} */
    public static EvaluationReport parseEvaluation(String json) {
        try {
            return Mapper.MAPPER.readValue(json, EvaluationReport.class);
        } catch (JsonProcessingException e) {
            throw InputException.unreadable("not an evaluation report: " + e.getOriginalMessage(), e);
        }
    }

    /**
     * Writes text atomically: a temporary file in the same folder, fsync, atomic rename, mode 0644.
     * A reader never sees a half-written file.
     */
    public static void writeAtomically(Path target, String text) {
        writeAtomically(target, text.getBytes(StandardCharsets.UTF_8));
    }

    /** As {@link #writeAtomically(Path, String)}, for bytes (images, gzip files). */
    public static void writeAtomically(Path target, byte[] bytes) {
        writeAtomically(target, out -> out.write(bytes));
    }

    /** What a streamed file holds: written to the stream, which the caller must not close. */
    @FunctionalInterface
    public interface Content {
        void writeTo(java.io.OutputStream out) throws IOException;
    }

    /**
     * As {@link #writeAtomically(Path, String)}, streaming the content into the temporary file
     * (large series are never held in memory whole).
     */
    public static void writeAtomically(Path target, Content content) {
        Path tmp = writeBeside(target, content);
        try {
            moveIntoPlace(tmp, target);
            fsyncDirectory(target.toAbsolutePath().getParent());
        } finally {
            deleteQuietly(tmp);
        }
    }

    /**
     * The first step of {@link #writeAtomically(Path, Content)}: the content in a temporary file
     * beside {@code target} ({@code .NAME.DIGITS.tmp}), fsync'd, mode 0644 (where the file system has
     * POSIX modes); the caller then {@link #moveIntoPlace moves it into place} or deletes it.
     * The file is created new (never an existing file or link; mode 0600 until written) under a
     * random name; a name another writer holds is skipped for the next. The folder is created
     * (with its parents) only when the file cannot be: a report beside others costs no failed
     * {@code mkdir}. The random names need no {@code SecureRandom}: exclusive creation, not an
     * unguessable name, is what keeps two writers apart.
     *
     * @return the temporary file
     * @throws UncheckedIOException when it cannot be written (nothing is left behind)
     */
    public static Path writeBeside(Path target, Content content) {
        Path tmp = null;
        try {
            Path dir = target.toAbsolutePath().getParent();
            String prefix = "." + target.getFileName() + ".";
            FileChannel created = null;
            boolean folderMade = false;
            for (int clashes = 0; created == null; ) {
                tmp = dir.resolve(prefix + Long.toUnsignedString(ThreadLocalRandom.current().nextLong()) + ".tmp");
                try {
                    created = FileChannel.open(tmp, NEW_FILE, ownerOnly(dir));
                } catch (FileAlreadyExistsException e) {
                    tmp = null;
                    if (++clashes >= MAX_NAME_CLASHES) {
                        throw e;
                    }
                } catch (IOException e) {
                    tmp = null;
                    if (folderMade) {
                        throw e;
                    }
                    Files.createDirectories(dir); // the folder is missing (or not one: this throws what it did before)
                    folderMade = true;
                }
            }
            try (FileChannel ch = created) {
                java.io.OutputStream out = java.nio.channels.Channels.newOutputStream(ch);
                content.writeTo(out);
                out.flush();
                ch.force(true);
            }
            try {
                Files.setPosixFilePermissions(tmp, PosixFilePermissions.fromString("rw-r--r--"));
            } catch (UnsupportedOperationException ignored) {
                // not a POSIX file system: keep the default mode
            }
            return tmp;
        } catch (IOException e) {
            deleteQuietly(tmp);
            throw new UncheckedIOException("could not write " + target, e);
        }
    }

    /** How a temporary file is opened: created here (never an existing file or link), for writing. */
    private static final Set<StandardOpenOption> NEW_FILE =
            EnumSet.of(StandardOpenOption.CREATE_NEW, StandardOpenOption.WRITE);
    /** Mode 0600, as a temporary file is created where the file system has POSIX modes. */
    private static final FileAttribute<?>[] OWNER_ONLY =
            {PosixFilePermissions.asFileAttribute(PosixFilePermissions.fromString("rw-------"))};
    private static final FileAttribute<?>[] NO_ATTRIBUTES = {};
    /** Names tried before a clash is reported (each clash means another writer took that name). */
    private static final int MAX_NAME_CLASHES = 100;

    /** @return mode 0600 on creation where {@code dir}'s file system has POSIX modes (none otherwise) */
    private static FileAttribute<?>[] ownerOnly(Path dir) {
        return dir.getFileSystem().supportedFileAttributeViews().contains("posix") ? OWNER_ONLY : NO_ATTRIBUTES;
    }

    /**
     * The second step: renames a file {@link #writeBeside written beside} {@code target} over it,
     * atomically where the file system can. The folder is not fsync'd ({@link #fsyncDirectory}).
     *
     * @throws UncheckedIOException when the rename fails
     */
    public static void moveIntoPlace(Path tmp, Path target) {
        try {
            try {
                Files.move(tmp, target, StandardCopyOption.ATOMIC_MOVE, StandardCopyOption.REPLACE_EXISTING);
            } catch (AtomicMoveNotSupportedException e) {
                Files.move(tmp, target, StandardCopyOption.REPLACE_EXISTING);
            }
        } catch (IOException e) {
            throw new UncheckedIOException("could not write " + target, e);
        }
    }

    /** Deletes {@code p} if it exists (null: nothing); a file that cannot be deleted is left. */
    public static void deleteQuietly(Path p) {
        if (p == null) {
            return;
        }
        try {
            Files.deleteIfExists(p);
        } catch (IOException ignored) {
            // a leftover temporary file is hidden (.NAME.*.tmp); the pipeline removes stale ones at start
        }
    }

    /** Fsyncs a folder, so that a rename in it is durable; a file system that cannot open one is skipped. */
    public static void fsyncDirectory(Path dir) {
        try (FileChannel ch = FileChannel.open(dir, StandardOpenOption.READ)) {
            ch.force(true);
        } catch (IOException ignored) {
            // some file systems cannot open a directory for fsync; the rename is still atomic
        }
    }
}
