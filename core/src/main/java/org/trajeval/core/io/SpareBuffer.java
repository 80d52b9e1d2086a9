package org.trajeval.core.io;

/**
 * One read buffer kept per thread for the next file read on it: {@code eval --batch} and the
 * pipeline read two files per run, and a fresh 1 MiB buffer is zeroed for each (1.3 % of a
 * 10^4-pose file's read). A buffer is lent to one reader at a time (a reader opened while
 * another is open on the same thread gets a fresh one), and only a buffer of {@link #LENGTH}
 * bytes is kept (one grown for a long line is left to the collector). The bytes it holds are
 * the last file's; {@link ByteLines} zeroes what a parser may read past the bytes read, so a
 * reader sees what it would in a fresh buffer. Memory: one
 * buffer (about 1 MiB) per thread that has read a file, until the thread ends.
 */
final class SpareBuffer {
    /** Bytes of a spare buffer: one read block and the bytes a parser may read past it. */
    static final int LENGTH = ByteLines.BLOCK_BYTES + ByteLines.READ_AHEAD;
    private static final ThreadLocal<byte[][]> SPARE = ThreadLocal.withInitial(() -> new byte[1][]);

    private SpareBuffer() {
    }

    /** @return this thread's spare buffer (taken: no longer spare), or a new one; {@link #LENGTH} bytes */
    static byte[] take() {
        byte[][] slot = SPARE.get();
        byte[] b = slot[0];
        if (b == null) {
            return new byte[LENGTH];
        }
        slot[0] = null;
        return b;
    }

    /** Keeps {@code b} as this thread's spare buffer (the caller no longer uses it) if it has {@link #LENGTH} bytes. */
    static void giveBack(byte[] b) {
        if (b != null && b.length == LENGTH) {
            SPARE.get()[0] = b;
        }
    }
}
