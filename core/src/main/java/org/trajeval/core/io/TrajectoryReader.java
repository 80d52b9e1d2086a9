package org.trajeval.core.io;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Objects;
import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;
import org.trajeval.core.io.bag.BagReadOptions;
import org.trajeval.core.io.bag.BagSource;
import org.trajeval.core.io.bag.BagTrajectoryReader;
import org.trajeval.core.io.bag.Bags;

/**
 * Reads trajectory files of every supported format ({@link TrajectoryFormat}): planar CSV, TUM,
 * KITTI and EuRoC, and one topic of a ROS bag ({@link BagTrajectoryReader}: the topic from the
 * read options or from a path written {@code BAG:TOPIC}). Numbers are read as evo reads them (the double nearest to the decimal text);
 * times end up in seconds. Every refusal is an {@link InputException} naming file, line, column,
 * what was expected and what was found; no other exception escapes for bad file content.
 */
public final class TrajectoryReader {
    private TrajectoryReader() {
    }

    /**
     * Reads one file.
     *
     * @param path the file
     * @param options format (or {@code null} to detect it), CSV layout, order policy, limits
     * @return the trajectory, its format, why that format, and the SHA-256 of the file's bytes
     * @throws InputException on any bad input, naming file, line, column and what was expected
     */
    public static LoadedTrajectory read(Path path, ReadOptions options) {
        return read(path, options, ReadThreads.ONE);
    }

    /**
     * Reads one file as {@link #read(Path, ReadOptions)}, a big CSV or TUM file in blocks parsed by
     * every free thread of {@code threads} (the same values, hash and refusals).
     */
    public static LoadedTrajectory read(Path path, ReadOptions options, ReadThreads threads) {
        Objects.requireNonNull(path, "path");
        Objects.requireNonNull(threads, "threads");
        Objects.requireNonNull(options, "options");
        checkOptions(options);
        String source = path.toString();
        BagReadOptions bagOptions = options.bag() != null ? options.bag() : BagReadOptions.DEFAULT;
        BagSource bag = BagSource.resolve(source, bagOptions.topic());
        if (bag != null) {
            return BagTrajectoryReader.read(bag.path(), bagOptions.withTopic(bag.topic()), options);
        }
        if (Bags.kind(path) != null || options.format() == TrajectoryFormat.BAG) {
            throw BagTopics.needed(path, source);
        }
        checkFile(path, source, options.maxBytes());
        return readText(ByteSource.of(path), source, options, threads);
    }

    /**
     * Reads one text trajectory file held in memory ({@link InputBytes}: a file read from a stream,
     * e.g. {@code hdfs:} or {@code s3a:}) exactly as {@link #read(Path, ReadOptions)} reads the same
     * bytes from a local file: same format detection, numbers and SHA-256; the source is
     * {@link InputBytes#name()}. Bags are refused: their readers seek in a local file.
     *
     * @throws InputException on any bad input, naming the file as given
     */
    public static LoadedTrajectory read(InputBytes bytes, ReadOptions options) {
        Objects.requireNonNull(bytes, "bytes");
        Objects.requireNonNull(options, "options");
        checkOptions(options);
        String source = bytes.name();
        byte[] head = new byte[16];
        int n = Math.max(0, bytes.readAt(0, java.nio.ByteBuffer.wrap(head)));
        if (options.format() == TrajectoryFormat.BAG || (options.bag() != null && options.bag().topic() != null)
                || Bags.kindOfHead(head, n) != null) {
            throw new InputException(source, 0, null, InputProblem.UNREADABLE, "ROS bags (MCAP, ROS 1, rosbag2 "
                    + "sqlite3) are read from a local file only (their readers seek in the file); copy the bag to a "
                    + "local disk or a mounted folder", null);
        }
        if (bytes.size() > options.maxBytes()) {
            throw FileProblems.tooManyBytes(source, bytes.size(), options.maxBytes());
        }
        checkBytes(source, bytes.size(), head, n);
        return readText(bytes, source, options, ReadThreads.ONE);
    }

    /** Detects the format unless given, then reads the text file with that format's reader. */
    private static LoadedTrajectory readText(ByteSource in, String source, ReadOptions options, ReadThreads threads) {
        TrajectoryFormat format = options.format();
        String reason = "given";
        if (format == null) {
            FormatDetector.Detection d = FormatDetector.detect(in, source, options.csv());
            format = d.format();
            reason = d.reason();
        }
        return switch (format) {
            case CSV -> CsvTrajectoryReader.read(in, source, options, reason, threads);
            case TUM -> TumReader.read(in, source, options, reason, threads);
            case KITTI -> KittiReader.read(in, source, options, reason);
            case EUROC -> EurocReader.read(in, source, options, reason);
            case NCLT, ROBOTCAR_INS, ROBOTCAR_VO -> EulerPoseReader.read(in, source, options, reason, format);
            case ICL_NUIM -> IclNuimReader.read(in, source, options, reason);
            case BAG -> throw BagTopics.needed(Path.of(in.fileName()), source);
        };
    }

    /** Refuses a missing file, a directory, an empty file or one over the byte limit. */
    static void checkFile(Path path, String source, long maxBytes) {
        long size;
        try {
            if (Files.isDirectory(path)) {
                throw new InputException(source, 0, null, InputProblem.UNREADABLE,
                        "this is a directory, a trajectory file was expected", null);
            }
            if (Files.exists(path) && !Files.isRegularFile(path)) {
                // a pipe, socket or device: format detection would consume what the reader needs,
                // and opening a FIFO without a writer blocks forever
                throw new InputException(source, 0, null, InputProblem.UNREADABLE, "this is not a regular file "
                        + "(a pipe, socket or device); trajeval reads trajectory files twice (format, then data): "
                        + "save the stream to a file first", null);
            }
            size = Files.size(path);
        } catch (IOException | SecurityException e) {
            throw FileProblems.unreadable(source, e);
        }
        if (size > maxBytes) {
            throw FileProblems.tooManyBytes(source, size, maxBytes);
        }
        byte[] head = new byte[4];
        int n = 0;
        if (size > 0) {
            try (var in = Files.newInputStream(path)) {
                n = in.readNBytes(head, 0, head.length);
            } catch (IOException | SecurityException e) {
                throw FileProblems.unreadable(source, e);
            }
        }
        checkBytes(source, size, head, n);
    }

    /**
     * Refuses an empty file, and UTF-16 text (by its byte-order mark or NUL bytes), which would
     * otherwise read as "not a number".
     *
     * @param head the file's first bytes, {@code n} of them (at least 4 unless the file is shorter)
     */
    private static void checkBytes(String source, long size, byte[] head, int n) {
        if (size == 0) {
            throw FileProblems.empty(source, "it is empty (0 bytes)");
        }
        String utf16 = TextFiles.utf16(java.util.Arrays.copyOf(head, Math.min(n, 4)));
        if (utf16 != null) {
            throw new InputException(source, 1, null, InputProblem.NOT_UTF8, "the file is " + utf16
                    + "; trajeval reads UTF-8 or ASCII text (convert it, e.g. iconv -f UTF-16 -t UTF-8)", null);
        }
    }

    private static void checkOptions(ReadOptions o) {
        if (o.csv() == null || o.order() == null || o.duplicates() == null || o.csv().timeUnit() == null || o.csv().timeColumn() == null
                || o.csv().xColumn() == null || o.csv().yColumn() == null || o.csv().yawColumn() == null) {
            throw new InputException(null, 0, null, InputProblem.INVALID_OPTION,
                    "the read options must give a CSV layout (column names, time unit), an order and a duplicate policy", null);
        }
        CsvTrajectoryReader.checkDelimiter(o.csv().delimiter());
        CsvLayout c = o.csv();
        java.util.List<String> names = java.util.List.of(c.timeColumn(), c.xColumn(), c.yColumn(), c.yawColumn());
        if (new java.util.HashSet<>(names).size() < 4 || names.stream().anyMatch(String::isBlank)) {
            throw new InputException(null, 0, "columns", InputProblem.DUPLICATE_COLUMN,
                    "the CSV columns of time, x, y and yaw (--columns T,X,Y,YAW) must be four different, non-blank "
                            + "names", String.join(",", names));
        }
        if (!(o.quaternionTolerance() >= 0.0 && o.quaternionTolerance() < 1.0)) {
            throw new InputException(null, 0, "quaternionTolerance", InputProblem.INVALID_OPTION,
                    "the quaternion tolerance must be at least 0 and below 1", String.valueOf(o.quaternionTolerance()));
        }
        if (o.maxBytes() <= 0 || o.maxPoses() <= 0) {
            throw new InputException(null, 0, "limits", InputProblem.INVALID_OPTION,
                    "the byte and pose limits must be positive", o.maxBytes() + " bytes, " + o.maxPoses() + " poses");
        }
    }
}
