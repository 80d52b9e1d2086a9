package org.trajeval.core.io.bag;

import io.airlift.compress.MalformedInputException;
import io.airlift.compress.lz4.Lz4Decompressor;
import io.airlift.compress.zstd.ZstdDecompressor;
import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.util.Locale;
import org.apache.commons.compress.compressors.bzip2.BZip2CompressorInputStream;
import org.trajeval.core.InputException;

/**
 * Decompresses one chunk of a bag: zstd (aircompressor), LZ4 frames (frame parsing here, blocks by
 * aircompressor), bzip2 (Commons Compress), or none. The output must have exactly the size the
 * chunk claims; a codec failure becomes a {@link InputException} naming the chunk.
 */
final class ChunkCodec {
    /** LZ4 frame magic number, little-endian. */
    static final int LZ4_MAGIC = 0x184D2204;

    private ChunkCodec() {
    }

    /**
     * @param compression the container's name for it: "" or "none", "zstd", "lz4", "bz2"
     * @param size the uncompressed size the chunk claims (bytes), already checked against the limit
     * @param where the chunk, for messages ("chunk at byte 4711")
     */
    static byte[] decompress(String source, String where, String compression, byte[] in, int off, int len, int size) {
        String c = compression.toLowerCase(Locale.ROOT);
        byte[] out;
        try {
            switch (c) {
                case "", "none" -> {
                    if (len != size) {
                        throw BagProblems.corrupt(source, -1, where + " is uncompressed but holds " + len
                                + " bytes, not the " + size + " it claims");
                    }
                    out = new byte[size];
                    System.arraycopy(in, off, out, 0, len);
                    return out;
                }
                case "zstd" -> {
                    out = new byte[size];
                    int n = new ZstdDecompressor().decompress(in, off, len, out, 0, size);
                    checkSize(source, where, n, size);
                    return out;
                }
                case "lz4" -> {
                    return lz4Frames(source, where, in, off, len, size);
                }
                case "bz2" -> {
                    return bzip2(source, where, in, off, len, size);
                }
                default -> throw BagProblems.unsupported(source, where + " uses compression '" + compression
                        + "'; trajeval reads none, zstd, lz4 and bz2", compression);
            }
        } catch (MalformedInputException | IllegalArgumentException | IndexOutOfBoundsException e) {
            throw BagProblems.corrupt(source, -1, where + ": the " + c + " data is corrupt ("
                    + e.getClass().getSimpleName() + (e.getMessage() == null ? "" : ": " + e.getMessage()) + ")");
        }
    }

    private static void checkSize(String source, String where, int n, int size) {
        if (n != size) {
            throw BagProblems.corrupt(source, -1, where + " decompresses to " + n + " bytes, not the " + size
                    + " it claims");
        }
    }

    private static byte[] bzip2(String source, String where, byte[] in, int off, int len, int size) {
        byte[] out = new byte[size];
        int n = 0;
        try (InputStream s = new BZip2CompressorInputStream(new ByteArrayInputStream(in, off, len), true)) {
            int r;
            while (n < size && (r = s.read(out, n, size - n)) > 0) {
                n += r;
            }
            if (n == size && s.read() >= 0) {
                n++;
            }
        } catch (IOException e) {
            throw BagProblems.corrupt(source, -1, where + ": the bz2 data is corrupt (" + e.getMessage() + ")");
        }
        checkSize(source, where, n > size ? size + 1 : n, size);
        return out;
    }

    /**
     * LZ4 frame format (lz4.github.io/lz4/lz4_Frame_format): magic, FLG, BD, optional content
     * size and dictionary id, header checksum, then blocks (uint32 size, high bit = stored) up to
     * an end mark, optional block and content checksums (skipped, not verified). Frames may follow
     * one another. Blocks must be independent (ROS 1's roslz4 writes them so).
     */
    private static byte[] lz4Frames(String source, String where, byte[] in, int off, int len, int size) {
        byte[] out = new byte[size];
        ByteCursor c = new ByteCursor(in, off, off + len, source, -1, where + " (lz4 frame)");
        int n = 0;
        Lz4Decompressor block = new Lz4Decompressor();
        while (c.remaining() > 0) {
            long magic = c.u32("lz4 magic");
            if (magic != (LZ4_MAGIC & 0xffffffffL)) {
                throw BagProblems.corrupt(source, -1, where + ": not an LZ4 frame (magic 0x"
                        + Long.toHexString(magic) + ", expected 0x184d2204)");
            }
            int flg = c.u8("lz4 FLG");
            c.u8("lz4 BD");
            if ((flg >> 6) != 1) {
                throw BagProblems.unsupported(source, where + ": LZ4 frame version " + (flg >> 6) + ", expected 1", null);
            }
            boolean independent = (flg & 0x20) != 0;
            boolean blockChecksum = (flg & 0x10) != 0;
            boolean contentSize = (flg & 0x08) != 0;
            boolean contentChecksum = (flg & 0x04) != 0;
            boolean dictionary = (flg & 0x01) != 0;
            if (contentSize) {
                c.skip(8, "lz4 content size");
            }
            if (dictionary) {
                throw BagProblems.unsupported(source, where + ": LZ4 frame with a dictionary", null);
            }
            c.u8("lz4 header checksum");
            while (true) {
                long word = c.u32("lz4 block size");
                if (word == 0) {
                    break;
                }
                boolean stored = (word & 0x80000000L) != 0;
                int blen = (int) (word & 0x7fffffffL);
                if (blen > c.remaining()) {
                    throw BagProblems.length(source, -1, where + ": lz4 block", blen, c.remaining());
                }
                if (stored) {
                    if (blen > size - n) {
                        throw tooBig(source, where, size);
                    }
                    System.arraycopy(in, c.pos, out, n, blen);
                    n += blen;
                } else {
                    if (!independent && n > 0) {
                        throw BagProblems.unsupported(source, where + ": LZ4 frame with linked blocks", null);
                    }
                    n += block.decompress(in, c.pos, blen, out, n, size - n);
                }
                c.pos += blen;
                if (blockChecksum) {
                    c.skip(4, "lz4 block checksum");
                }
            }
            if (contentChecksum) {
                c.skip(4, "lz4 content checksum");
            }
        }
        checkSize(source, where, n, size);
        return out;
    }

    private static InputException tooBig(String source, String where, int size) {
        return BagProblems.corrupt(source, -1, where + " decompresses to more than the " + size + " bytes it claims");
    }
}
