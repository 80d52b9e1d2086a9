package org.trajeval.core.io;

import java.io.Closeable;
import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Path;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.Arrays;
import java.util.HexFormat;
import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;

/**
 * Reads a file line by line as bytes, in big blocks, without a String or any other object per
 * line, and hashes every byte (SHA-256) in the same pass. After {@link #next()} returns true the
 * current line is {@code buffer()[start() .. end())}, without its {@code \n} or {@code \r\n}.
 * A UTF-8 byte-order mark at the start of the file is skipped.
 */
final class ByteLines implements Closeable {
    /** Block size of one read (bytes). */
    static final int BLOCK_BYTES = 1 << 20;
    /** Longest accepted line (bytes). */
    static final int MAX_LINE_BYTES = 1 << 26;
    /**
     * Bytes kept readable after the last byte read (never filled from the file): a parser may read
     * this far past {@link #completeLinesEnd()} without checking (an eight-byte word at a line's end).
     */
    static final int READ_AHEAD = 64;

    private final String source;
    private final InputStream in;
    private final MessageDigest sha;
    private final long maxBytes;
    private byte[] buf;
    private int pos;
    private int limit;
    private int scanFrom;
    /** Offset just past the last '\n' read into buf (0 when there is none after pos). */
    private int complete;
    private boolean eof;
    /** True once {@link #buf} no longer starts with the file's first byte (its lines were moved down). */
    private boolean shifted;
    private boolean started;
    private long bytesRead;
    private long lineNumber;
    private int start;
    private int end;

    private final long expectedBytes;

    private ByteLines(String source, InputStream in, long maxBytes, long expectedBytes) {
        this(source, in, maxBytes, expectedBytes, sha256(), SpareBuffer.take());
        borrowed = true;
    }

    /** True when {@link #buf} came from {@link SpareBuffer} and goes back there at {@link #close}. */
    private boolean borrowed;

    private ByteLines(String source, InputStream in, long maxBytes, long expectedBytes, MessageDigest sha,
            byte[] buf) {
        this.source = source;
        this.in = in;
        this.maxBytes = maxBytes;
        this.expectedBytes = expectedBytes;
        this.sha = sha;
        this.buf = buf;
    }

    /**
     * The lines of a block of a file already read, {@code buf[0, length)}, cut just after a '\n'
     * ({@link BlockRead}, which reads and hashes the bytes itself): nothing more is read, and a
     * byte-order mark is skipped only at the file's start.
     *
     * @param buf the block's bytes, then at least {@link #READ_AHEAD} more (any values)
     * @param fileStart true for the block at byte 0 of the file
     */
    static ByteLines inMemory(byte[] buf, int length, String source, boolean fileStart) {
        if (buf.length - length < READ_AHEAD) {
            throw new IllegalArgumentException("a block needs " + READ_AHEAD + " bytes after it");
        }
        ByteLines lines = new ByteLines(source, InputStream.nullInputStream(), Long.MAX_VALUE, length, null, buf);
        lines.limit = length;
        lines.bytesRead = length;
        lines.eof = true;
        lines.started = true;
        for (int i = length - 1; i >= 0; i--) {
            if (buf[i] == '\n') {
                lines.complete = i + 1;
                break;
            }
        }
        if (fileStart && length >= 3 && (buf[0] & 0xff) == 0xEF && (buf[1] & 0xff) == 0xBB && (buf[2] & 0xff) == 0xBF) {
            lines.pos = 3;
            lines.scanFrom = 3;
        }
        return lines;
    }

    /** Opens a file; refuses a missing or unreadable one as {@link InputProblem#UNREADABLE}. */
    static ByteLines open(Path path, String source, long maxBytes) {
        return open(ByteSource.of(path), source, maxBytes);
    }

    /** Opens a file wherever it is; refuses a missing or unreadable one as {@link InputProblem#UNREADABLE}. */
    static ByteLines open(ByteSource file, String source, long maxBytes) {
        try {
            long size = file.size();
            ByteLines lines = new ByteLines(source, file.open(), maxBytes, size);
            if (size > SAMPLES * SAMPLE_BYTES) {
                lines.toSample = file;
            }
            return lines;
        } catch (IOException | SecurityException e) {
            throw FileProblems.unreadable(source, e);
        }
    }

    /** Number of places a big file's line length is sampled at, evenly spread from start to end. */
    static final int SAMPLES = 16;
    /** Bytes read at each sampled place. */
    static final int SAMPLE_BYTES = 1 << 14;
    private double sampledBytesPerLine = Double.NaN;
    /** The file whose line length {@link #sampledBytesPerLine()} samples when first asked; null once sampled (or too small). */
    private ByteSource toSample;

    /**
     * @return mean line length (bytes, line end included) over {@link #SAMPLES} stretches of
     *     {@link #SAMPLE_BYTES} spread evenly over the file, NaN if it cannot be told; numbers
     *     often grow along a file, so its first lines alone would misjudge the pose count
     */
    static double sampleLineLength(ByteSource file, long size) {
        java.nio.ByteBuffer buf = java.nio.ByteBuffer.allocate(SAMPLE_BYTES);
        long[] spannedAndLines = new long[2];
        try {
            for (int k = 0; k < SAMPLES; k++) {
                buf.clear();
                long at = sampleStart(size, k);
                while (buf.hasRemaining() && file.readAt(at + buf.position(), buf) > 0) {
                    // a regular file fills the buffer in one or two reads
                }
                countLines(buf.array(), 0, buf.position(), spannedAndLines);
            }
        } catch (IOException e) {
            return Double.NaN; // only a size hint: the real read reports any problem
        }
        return meanLineLength(spannedAndLines);
    }

    /**
     * {@link #sampleLineLength(ByteSource, long)} of a file whose {@code size} bytes are all in
     * {@code b}, from its index 0: the same stretches, read from memory (no open, no read).
     */
    static double sampleLineLength(byte[] b, long size) {
        long[] spannedAndLines = new long[2];
        for (int k = 0; k < SAMPLES; k++) {
            int at = (int) sampleStart(size, k);
            countLines(b, at, (int) Math.min(SAMPLE_BYTES, size - at), spannedAndLines);
        }
        return meanLineLength(spannedAndLines);
    }

    /** @return the file offset of sampled stretch {@code k}: the stretches spread evenly from the first byte to the last */
    private static long sampleStart(long size, int k) {
        return (size - SAMPLE_BYTES) * k / (SAMPLES - 1);
    }

    /**
     * Adds to {@code acc} the bytes from the first to the last '\n' of {@code b[from, from + length)}
     * ({@code acc[0]}) and the lines they hold ({@code acc[1]}: the '\n's less one), when there are two or more.
     */
    private static void countLines(byte[] b, int from, int length, long[] acc) {
        int to = from + length;
        int first = indexOfNewline(b, from, to);
        if (first < 0) {
            return;
        }
        int last = to - 1;
        while (b[last] != '\n') {
            last--;
        }
        if (last > first) {
            acc[0] += last - first;
            acc[1] += countNewlines(b, first, last + 1) - 1;
        }
    }

    private static final long LOW_SEVEN_BITS = 0x7F7F7F7F7F7F7F7FL;

    /**
     * @return the number of '\n' in {@code b[from..to)}, eight bytes at a time: in {@code x = w ^ NEWLINES}
     *     a byte is zero exactly where w has '\n'; {@code ((x & 0x7F..) + 0x7F.. | x) & HIGHS} flags
     *     every non-zero byte (the sum stays within each byte, so no byte disturbs another)
     */
    static int countNewlines(byte[] b, int from, int to) {
        int count = 0;
        int i = from;
        for (; i + 8 <= to; i += 8) {
            long x = (long) LONGS.get(b, i) ^ NEWLINES;
            long nonZero = (((x & LOW_SEVEN_BITS) + LOW_SEVEN_BITS) | x) & HIGHS;
            count += 8 - Long.bitCount(nonZero);
        }
        for (; i < to; i++) {
            if (b[i] == '\n') {
                count++;
            }
        }
        return count;
    }

    private static double meanLineLength(long[] spannedAndLines) {
        return spannedAndLines[1] > 0 ? (double) spannedAndLines[0] / spannedAndLines[1] : Double.NaN;
    }

    /**
     * @return mean line length sampled over the whole file (bytes, line end included), NaN when not
     *     sampled (a file of at most {@link #SAMPLES} times {@link #SAMPLE_BYTES}). Sampled when
     *     first asked: from the buffer when the whole file is in it (a file within one block read,
     *     no further open or read), else from the file.
     */
    double sampledBytesPerLine() {
        if (toSample != null) {
            ByteSource file = toSample;
            toSample = null;
            sampledBytesPerLine = !shifted && bytesRead == expectedBytes ? sampleLineLength(buf, expectedBytes)
                    : sampleLineLength(file, expectedBytes);
        }
        return sampledBytesPerLine;
    }

    static MessageDigest sha256() {
        try {
            return MessageDigest.getInstance("SHA-256");
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException("every Java platform has SHA-256", e);
        }
    }

    /**
     * Advances to the next line.
     *
     * @return false at the end of the file
     */
    boolean next() {
        while (true) {
            int nl = indexOfNewline(buf, scanFrom, limit);
            if (nl >= 0) {
                setLine(pos, nl);
                pos = nl + 1;
                scanFrom = pos;
                return true;
            }
            scanFrom = limit;
            if (eof) {
                if (pos < limit) {
                    setLine(pos, limit);
                    pos = limit;
                    return true;
                }
                return false;
            }
            fill();
        }
    }

    private static final java.lang.invoke.VarHandle LONGS =
            java.lang.invoke.MethodHandles.byteArrayViewVarHandle(long[].class, java.nio.ByteOrder.LITTLE_ENDIAN);
    private static final long ONES = 0x0101010101010101L;
    private static final long HIGHS = 0x8080808080808080L;
    private static final long NEWLINES = 0x0A0A0A0A0A0A0A0AL;

    /**
     * @return index of the first '\n' in {@code b[from..to)}, or -1; eight bytes at a time (a byte
     *     is zero in {@code w ^ NEWLINES} exactly where w has '\n'; the lowest flagged byte of
     *     {@code (x - ONES) & ~x & HIGHS} is the first zero byte)
     */
    static int indexOfNewline(byte[] b, int from, int to) {
        int i = from;
        for (; i + 8 <= to; i += 8) {
            long x = (long) LONGS.get(b, i) ^ NEWLINES;
            long found = (x - ONES) & ~x & HIGHS;
            if (found != 0) {
                return i + (Long.numberOfTrailingZeros(found) >>> 3);
            }
        }
        for (; i < to; i++) {
            if (b[i] == '\n') {
                return i;
            }
        }
        return -1;
    }

    /** @return offset in {@link #buffer()} where the line after the current one starts */
    int position() {
        return pos;
    }

    /**
     * @return offset just past the last '\n' in {@link #buffer()}: a line that starts at
     *     {@link #position()} below it ends in the buffer, with its '\n', before it (so a parser may
     *     read ahead up to it, and past it: every byte below {@code completeLinesEnd() + READ_AHEAD}
     *     lies in {@link #buffer()})
     */
    int completeLinesEnd() {
        return complete;
    }

    /**
     * Makes the line from {@link #position()} to the '\n' at {@code newline} the current line, as
     * {@link #next()} would (a '\r' before the '\n' is not part of it), for a parser that found
     * the line end itself; {@code newline} must lie below {@link #completeLinesEnd()}.
     */
    void acceptLine(int newline) {
        setLine(pos, newline);
        pos = newline + 1;
        scanFrom = pos;
    }

    private void setLine(int from, int to) {
        lineNumber++;
        start = from;
        end = to > from && buf[to - 1] == '\r' ? to - 1 : to;
    }

    private void fill() {
        if (pos > 0) {
            shifted = true;
            int keep = limit - pos;
            System.arraycopy(buf, pos, buf, 0, keep);
            scanFrom -= pos;
            limit = keep;
            pos = 0;
            complete = 0; // fill is only called when no '\n' is left after pos
        }
        int capacity = buf.length - READ_AHEAD;
        if (limit == capacity) {
            if (capacity >= MAX_LINE_BYTES) {
                throw new InputException(source, lineNumber + 1, null, InputProblem.TOO_LARGE,
                        "a line must be shorter than " + MAX_LINE_BYTES + " bytes (is this a trajectory file?)", null);
            }
            capacity *= 2;
            byte[] bigger = new byte[capacity + READ_AHEAD];
            System.arraycopy(buf, 0, bigger, 0, limit);
            buf = bigger;
        }
        int n;
        try {
            n = in.read(buf, limit, capacity - limit);
        } catch (IOException e) {
            throw FileProblems.unreadable(source, e);
        }
        if (n < 0) {
            eof = true;
            return;
        }
        if (sha != null) {
            sha.update(buf, limit, n);
        }
        for (int i = limit + n - 1; i >= limit; i--) {
            if (buf[i] == '\n') {
                complete = i + 1;
                break;
            }
        }
        limit += n;
        bytesRead += n;
        // what a parser may read past the bytes read is zero, as in a fresh buffer (a spare one held another file)
        Arrays.fill(buf, limit, Math.min(buf.length, limit + READ_AHEAD), (byte) 0);
        if (bytesRead > maxBytes) {
            throw FileProblems.tooManyBytes(source, bytesRead, maxBytes);
        }
        if (!started && (limit >= 3 || eof)) {
            started = true;
            if (limit >= 3 && (buf[0] & 0xff) == 0xEF && (buf[1] & 0xff) == 0xBB && (buf[2] & 0xff) == 0xBF) {
                pos = 3;
                scanFrom = 3;
            }
        }
    }

    /** @return the bytes holding the current line (valid until the next call of {@link #next()}) */
    byte[] buffer() {
        return buf;
    }

    /** @return offset of the current line's first byte */
    int start() {
        return start;
    }

    /** @return offset just past the current line's last byte (line end excluded) */
    int end() {
        return end;
    }

    /** @return 1-based number of the current line */
    long lineNumber() {
        return lineNumber;
    }

    /** @return the file size when it was opened (bytes), 0 if unknown */
    long expectedBytes() {
        return expectedBytes;
    }

    /** @return bytes of the file up to the end of the current line */
    long consumedBytes() {
        return bytesRead - (limit - pos);
    }

    /** @return the current line as text (for messages only) */
    String lineText() {
        return new String(buf, start, end - start, java.nio.charset.StandardCharsets.UTF_8);
    }

    /** Reads the rest of the file (so that the hash covers every byte) and returns the SHA-256, lower-case hex. */
    String finishSha256() {
        while (!eof) {
            pos = limit;
            scanFrom = limit;
            fill();
        }
        return HexFormat.of().formatHex(sha.digest());
    }

    /**
     * Closes the file; a buffer borrowed from {@link SpareBuffer} goes back for the next file
     * read on this thread, so nothing may read {@link #buffer()} after this.
     */
    @Override
    public void close() {
        try {
            in.close();
        } catch (IOException e) {
            // nothing was lost: every byte needed is already read
        }
        if (borrowed) {
            borrowed = false;
            SpareBuffer.giveBack(buf);
            buf = null;
        }
    }
}
