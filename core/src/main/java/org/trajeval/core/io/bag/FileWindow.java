package org.trajeval.core.io.bag;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.channels.FileChannel;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;

/**
 * Random-access reads of byte ranges of one file, each range checked against the file size and
 * the record limit before anything is allocated: nothing is read past the file's end.
 */
final class FileWindow implements AutoCloseable {
    private final FileChannel channel;
    private final long size;
    private final String source;
    private final BagLimits limits;
    /** The block buffer of {@link #crc}, made on first use. */
    private ByteBuffer block;

    FileWindow(Path path, String source, BagLimits limits) {
        this.source = source;
        this.limits = limits;
        try {
            this.channel = FileChannel.open(path, StandardOpenOption.READ);
            this.size = channel.size();
        } catch (IOException e) {
            throw BagProblems.io(source, e);
        }
    }

    long size() {
        return size;
    }

    String source() {
        return source;
    }

    BagLimits limits() {
        return limits;
    }

    /**
     * @param offset file offset of the first byte
     * @param length number of bytes, as claimed by the file
     * @param what the field that claimed it, for the refusal
     * @return exactly {@code length} bytes
     */
    byte[] read(long offset, long length, String what) {
        if (offset < 0 || offset > size) {
            throw BagProblems.corrupt(source, -1, what + " points to byte " + Long.toUnsignedString(offset)
                    + ", past the end of the file (" + size + " bytes)");
        }
        if (length < 0 || length > size - offset) {
            throw BagProblems.length(source, offset, what, length, size - offset);
        }
        if (length > limits.maxRecordBytes()) {
            throw BagProblems.corrupt(source, offset, what + " claims " + length + " bytes, more than the limit of "
                    + limits.maxRecordBytes() + " bytes for one record");
        }
        byte[] b = new byte[(int) length];
        ByteBuffer bb = ByteBuffer.wrap(b);
        try {
            long at = offset;
            while (bb.hasRemaining()) {
                int r = channel.read(bb, at);
                if (r < 0) {
                    throw BagProblems.corrupt(source, at, "the file ended while reading " + what
                            + " (it shrank while being read?)");
                }
                at += r;
            }
        } catch (IOException e) {
            throw BagProblems.io(source, e);
        }
        return b;
    }

    /**
     * Feeds the bytes {@code [offset, offset + length)} to a CRC, in blocks of 1 MiB through one
     * reused buffer (never more in memory, whatever the length).
     *
     * @param what the range, for the refusal when the file ends early
     */
    void crc(java.util.zip.CRC32 crc, long offset, long length, String what) {
        if (offset < 0 || length < 0 || length > size - offset) {
            throw BagProblems.length(source, offset, what, length, size - Math.max(0, offset));
        }
        int want = (int) Math.max(4096, Math.min(1 << 20, length)); // at most 1 MiB; a small file, a small buffer
        if (block == null || block.capacity() < want) {
            block = ByteBuffer.allocateDirect(want);
        }
        long at = offset;
        long end = offset + length;
        try {
            while (at < end) {
                block.clear();
                block.limit((int) Math.min(block.capacity(), end - at));
                int r = channel.read(block, at);
                if (r < 0) {
                    throw BagProblems.corrupt(source, at, "the file ended while reading " + what
                            + " (it shrank while being read?)");
                }
                block.flip();
                crc.update(block);
                at += r;
            }
        } catch (IOException e) {
            throw BagProblems.io(source, e);
        }
    }

    @Override
    public void close() {
        try {
            channel.close();
        } catch (IOException e) {
            // read-only channel: nothing was written that could be lost
        }
    }
}
