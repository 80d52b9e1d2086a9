package org.trajeval.core.io;

import java.io.IOException;
import java.io.InputStream;
import java.io.SequenceInputStream;
import java.nio.ByteBuffer;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Objects;

/**
 * The bytes of one trajectory file read once from a stream into memory, in chunks of at most
 * {@link #CHUNK_BYTES} (no single array of the file's size, no copy on a local disk), for files
 * that are not on a local file system ({@code hdfs:}, {@code s3a:}, ...: the stream comes from
 * Hadoop's FileSystem API in {@code trajeval-spark}). {@link TrajectoryReader#read(InputBytes,
 * ReadOptions)} reads them exactly as it reads the same bytes from a local file: same format
 * detection (from the first bytes and the name's extension), same numbers, same SHA-256; every
 * message names the file as given ({@link #name()}, e.g. the URI).
 *
 * <p>Memory: the file's size on the heap while it is read (a 10^7-pose TUM file is about 0.7 GB).
 */
public final class InputBytes implements ByteSource {
    /** Largest chunk held (bytes). */
    public static final int CHUNK_BYTES = 1 << 20;

    private final String name;
    private final List<byte[]> chunks;
    private final long size;

    private InputBytes(String name, List<byte[]> chunks, long size) {
        this.name = name;
        this.chunks = chunks;
        this.size = size;
    }

    /** Opens a stream (throwing {@link IOException} on a missing or unreadable file). */
    @FunctionalInterface
    public interface Opener {
        InputStream open() throws IOException;
    }

    /**
     * Reads every byte of a stream (and closes it).
     *
     * @param name the file as given (a path or URI): the trajectory's source in messages and reports
     * @param opener opens the stream
     * @param maxBytes the byte limit ({@link ReadOptions#maxBytes()})
     * @throws org.trajeval.core.InputException UNREADABLE when the stream cannot be opened or read,
     *     TOO_LARGE past {@code maxBytes}, both naming {@code name}
     */
    public static InputBytes read(String name, Opener opener, long maxBytes) {
        return read(name, opener, maxBytes, CHUNK_BYTES);
    }

    static InputBytes read(String name, Opener opener, long maxBytes, int chunkBytes) {
        Objects.requireNonNull(name, "name");
        List<byte[]> chunks = new ArrayList<>();
        long total = 0;
        try (InputStream in = opener.open()) {
            while (true) {
                byte[] chunk = new byte[chunkBytes];
                int n = in.readNBytes(chunk, 0, chunkBytes);
                if (n == 0) {
                    break;
                }
                total += n;
                if (total > maxBytes) {
                    throw FileProblems.tooManyBytes(name, total, maxBytes);
                }
                chunks.add(n == chunkBytes ? chunk : java.util.Arrays.copyOf(chunk, n));
                if (n < chunkBytes) {
                    break;
                }
            }
        } catch (IOException | SecurityException e) {
            throw FileProblems.unreadable(name, e);
        }
        return new InputBytes(name, List.copyOf(chunks), total);
    }

    /** @return the file as given (a path or URI) */
    public String name() {
        return name;
    }

    @Override
    public long size() {
        return size;
    }

    @Override
    public String fileName() {
        String n = name;
        int q = n.indexOf('?');
        if (q >= 0 && n.contains("://")) {
            n = n.substring(0, q); // an object store's query string is not part of the name
        }
        return n.substring(n.lastIndexOf('/') + 1);
    }

    @Override
    public InputStream open() {
        List<InputStream> streams = new ArrayList<>(chunks.size());
        for (byte[] c : chunks) {
            streams.add(new java.io.ByteArrayInputStream(c));
        }
        return new SequenceInputStream(Collections.enumeration(streams));
    }

    @Override
    public int readAt(long position, ByteBuffer dst) {
        if (position >= size) {
            return -1;
        }
        int read = 0;
        long at = position;
        // chunks before the last are all full: chunk k starts at k * chunks.get(0).length
        int full = chunks.get(0).length;
        while (dst.hasRemaining() && at < size) {
            byte[] c = chunks.get((int) (at / full));
            int off = (int) (at % full);
            int n = Math.min(dst.remaining(), c.length - off);
            dst.put(c, off, n);
            read += n;
            at += n;
        }
        return read;
    }
}
