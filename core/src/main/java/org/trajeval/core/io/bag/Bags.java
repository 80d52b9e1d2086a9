package org.trajeval.core.io.bag;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;

/**
 * Opens a bag of any supported container, told from its content: the MCAP magic, {@code #ROSBAG V2.0},
 * the SQLite header (a rosbag2 {@code .db3}), or a folder with a rosbag2 {@code metadata.yaml}.
 */
public final class Bags {
    /** First bytes of a ROS 1 bag, version 2.0. */
    static final byte[] ROS1_MAGIC = "#ROSBAG V2.0\n".getBytes(StandardCharsets.US_ASCII);
    /** First bytes of an SQLite 3 database. */
    static final byte[] SQLITE_MAGIC = "SQLite format 3\0".getBytes(StandardCharsets.US_ASCII);

    /** The containers trajeval reads. */
    public enum Kind {
        /** MCAP (ROS 2's default storage since Iron). */
        MCAP,
        /** ROS 1 bag, format 2.0. */
        ROS1,
        /** rosbag2 sqlite3 storage ({@code .db3}). */
        SQLITE3,
        /** A rosbag2 folder ({@code metadata.yaml} beside its storage files). */
        ROSBAG2_FOLDER
    }

    private Bags() {
    }

    /** @return the container kind of a path, or null when it is not a bag */
    public static Kind kind(Path path) {
        if (Files.isDirectory(path)) {
            return Files.isRegularFile(path.resolve("metadata.yaml")) ? Kind.ROSBAG2_FOLDER : null;
        }
        if (!Files.isRegularFile(path)) {
            return null; // a FIFO or device is never opened here (it could block); the reader refuses it
        }
        byte[] head = new byte[16];
        int n = 0;
        try (InputStream in = Files.newInputStream(path)) {
            int r;
            while (n < head.length && (r = in.read(head, n, head.length - n)) > 0) {
                n += r;
            }
        } catch (IOException | SecurityException e) {
            return null;
        }
        return kindOfHead(head, n);
    }

    /**
     * @param head the first bytes of a file
     * @param n how many of them there are
     * @return the container kind those bytes start, or null when they start no bag
     */
    public static Kind kindOfHead(byte[] head, int n) {
        if (startsWith(head, n, McapReader.MAGIC)) {
            return Kind.MCAP;
        }
        if (startsWith(head, n, ROS1_MAGIC)) {
            return Kind.ROS1;
        }
        if (startsWith(head, n, SQLITE_MAGIC)) {
            return Kind.SQLITE3;
        }
        return null;
    }

    private static boolean startsWith(byte[] head, int n, byte[] magic) {
        return n >= magic.length && Arrays.equals(Arrays.copyOf(head, magic.length), magic);
    }

    /**
     * @param source the name used in messages
     * @throws InputException when the path is not a bag or its structure is broken
     */
    public static BagContainer open(Path path, String source, BagLimits limits) {
        return open(path, source, limits, BagIntegrity.CHUNKS);
    }

    /**
     * @param source the name used in messages
     * @param integrity the MCAP checksums to verify
     * @throws InputException when the path is not a bag, its structure is broken or a checksum does not match
     */
    public static BagContainer open(Path path, String source, BagLimits limits, BagIntegrity integrity) {
        if (!Files.exists(path)) {
            throw new InputException(source, 0, null, InputProblem.UNREADABLE, "the file does not exist", null);
        }
        Kind k = kind(path);
        if (k == null) {
            throw new InputException(source, 0, null, InputProblem.UNKNOWN_FORMAT, "not a bag (expected the MCAP "
                    + "magic, '#ROSBAG V2.0', an SQLite header, or a folder with metadata.yaml)", null);
        }
        return switch (k) {
            case MCAP -> new McapReader(path, source, limits, integrity);
            case ROS1 -> new Ros1BagReader(path, source, limits);
            case SQLITE3 -> new Sqlite3BagReader(path, source, limits);
            case ROSBAG2_FOLDER -> Rosbag2Folder.open(path, source, limits, integrity);
        };
    }
}
