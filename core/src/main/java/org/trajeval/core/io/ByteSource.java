package org.trajeval.core.io;

import java.io.IOException;
import java.io.InputStream;
import java.nio.ByteBuffer;
import java.nio.file.Path;

/**
 * The bytes of one trajectory file as the readers see them, wherever they are: a local file
 * ({@link LocalFile}) or a file read once into memory from a stream ({@link InputBytes}, e.g. an
 * {@code hdfs:} or {@code s3a:} file). The readers read it twice (format detection, then the
 * data), so {@link #open()} may be called more than once, each time from the first byte.
 */
interface ByteSource {
    /** @return a new stream over every byte, from the first */
    InputStream open() throws IOException;

    /** @return a new stream over the bytes from byte {@code from} on (a block of the file, {@link BlockRead}) */
    default InputStream open(long from) throws IOException {
        InputStream in = open();
        in.skipNBytes(from);
        return in;
    }

    /** @return the number of bytes, 0 when unknown (a size hint: the readers count what they read) */
    long size() throws IOException;

    /** @return the file's name without its folder (format detection looks at the extension), "" if none */
    String fileName();

    /**
     * Reads up to {@code dst.remaining()} bytes starting at byte {@code position} (sampling a big
     * file's line length before it is read).
     *
     * @return the number of bytes read, -1 at the end
     */
    int readAt(long position, ByteBuffer dst) throws IOException;

    static ByteSource of(Path path) {
        return new LocalFile(path);
    }
}
