package org.trajeval.core.io.bag;

import java.nio.charset.StandardCharsets;

/**
 * Little-endian reads from a window of a byte array, every read and every length field checked
 * against what remains of the window (a length in a file is a claim, not a fact). Offsets in
 * messages are file offsets when the window holds file bytes ({@code base} is the file offset of
 * {@code buf[0]}), else offsets inside a decompressed chunk.
 */
final class ByteCursor {
    final byte[] buf;
    final String source;
    final long base;
    final String where;
    int pos;
    final int limit;

    /**
     * @param where what the window is, for messages ("chunk at byte 123", "summary")
     * @param base file offset of {@code buf[0]}, or -1 when the bytes are not the file's (decompressed)
     */
    ByteCursor(byte[] buf, int pos, int limit, String source, long base, String where) {
        this.buf = buf;
        this.pos = pos;
        this.limit = limit;
        this.source = source;
        this.base = base;
        this.where = where;
    }

    int remaining() {
        return limit - pos;
    }

    long offset() {
        return base >= 0 ? base + pos : pos;
    }

    private void need(int n, String field) {
        if (n < 0 || n > limit - pos) {
            throw BagProblems.corrupt(source, base >= 0 ? base + pos : -1, field + " needs " + n + " bytes but only "
                    + (limit - pos) + " remain in " + where);
        }
    }

    int u8(String field) {
        need(1, field);
        return buf[pos++] & 0xff;
    }

    int u16(String field) {
        need(2, field);
        int v = (buf[pos] & 0xff) | (buf[pos + 1] & 0xff) << 8;
        pos += 2;
        return v;
    }

    /** @return an unsigned 32-bit value */
    long u32(String field) {
        need(4, field);
        long v = le32(buf, pos) & 0xffffffffL;
        pos += 4;
        return v;
    }

    long u64(String field) {
        need(8, field);
        long v = le64(buf, pos);
        pos += 8;
        return v;
    }

    /**
     * A length field that must fit in what remains of the window.
     *
     * @param bytes size of the field (4 or 8)
     */
    int length(int bytes, String field) {
        long at = offset();
        long n = bytes == 4 ? u32(field) : u64(field);
        if (n < 0 || n > limit - pos) {
            throw BagProblems.length(source, at, field + " in " + where, n, limit - pos);
        }
        return (int) n;
    }

    /** @return a string prefixed by its uint32 byte length, UTF-8 */
    String string(String field) {
        int n = length(4, field);
        String s = new String(buf, pos, n, StandardCharsets.UTF_8);
        pos += n;
        return s;
    }

    void skip(int n, String field) {
        need(n, field);
        pos += n;
    }

    static int le32(byte[] b, int i) {
        return (b[i] & 0xff) | (b[i + 1] & 0xff) << 8 | (b[i + 2] & 0xff) << 16 | (b[i + 3] & 0xff) << 24;
    }

    static long le64(byte[] b, int i) {
        return (le32(b, i) & 0xffffffffL) | ((long) le32(b, i + 4)) << 32;
    }
}
