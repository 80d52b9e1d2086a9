package org.trajeval.core.io.bag;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Comparator;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.function.Predicate;
import java.util.zip.CRC32;

/**
 * MCAP files (mcap.dev/spec): magic, then records of {@code opcode u8, length u64, content}. With a
 * summary section (found through the footer), only the chunks whose message indexes name a wanted
 * channel are read and decompressed; without one, the data section is scanned from the start. The
 * data section CRC ({@link McapDataCrc}, one sequential pass over the data section at open, unless
 * {@link BagIntegrity#CHUNKS}), the summary CRC and each read chunk's CRC of its uncompressed records are checked when the writer set
 * them (0 means "not computed", as the spec says).
 */
final class McapReader implements BagContainer {
    static final byte[] MAGIC = {(byte) 0x89, 'M', 'C', 'A', 'P', 0x30, '\r', '\n'};
    static final int OP_HEADER = 0x01;
    static final int OP_FOOTER = 0x02;
    static final int OP_SCHEMA = 0x03;
    static final int OP_CHANNEL = 0x04;
    static final int OP_MESSAGE = 0x05;
    static final int OP_CHUNK = 0x06;
    static final int OP_CHUNK_INDEX = 0x08;
    static final int OP_DATA_END = 0x0F;
    /** Footer record: opcode, length, summary start, summary offset start, summary CRC. */
    static final int FOOTER_RECORD_BYTES = 1 + 8 + 8 + 8 + 4;
    /** Message record header: channel id u16, sequence u32, log time u64, publish time u64. */
    static final int MESSAGE_HEADER_BYTES = 2 + 4 + 8 + 8;

    private record Schema(String name, String encoding, String text) {
    }

    /** A chunk index entry: where the chunk is, and the channels it holds (empty: unknown). */
    private record ChunkRef(long startTime, long offset, long length, int[] channels) {
    }

    private final FileWindow file;
    private final String source;
    private final Map<Integer, Schema> schemas = new HashMap<>();
    private final Map<Integer, BagChannel> channels = new TreeMap<>();
    /** The same channels by id (MCAP channel ids are u16): one array load per message. */
    private final BagChannel[] byId = new BagChannel[1 << 16];
    private final List<ChunkRef> chunks = new ArrayList<>();
    private boolean indexed;
    /** During a linear scan: which channels are wanted, updated as channel records appear. */
    private Predicate<BagChannel> scanWanted;
    private boolean[] scanWant;

    McapReader(Path path, String source, BagLimits limits, BagIntegrity integrity) {
        this.file = new FileWindow(path, source, limits);
        this.source = source;
        try {
            open(integrity);
        } catch (RuntimeException e) {
            file.close();
            throw e;
        }
    }

    @Override
    public String kind() {
        return "MCAP";
    }

    private void open(BagIntegrity integrity) {
        long size = file.size();
        if (size < MAGIC.length || !Arrays.equals(file.read(0, MAGIC.length, "magic"), MAGIC)) {
            throw BagProblems.corrupt(source, 0, "not an MCAP file (the first 8 bytes are not the MCAP magic)");
        }
        long footerAt = size - MAGIC.length - FOOTER_RECORD_BYTES;
        long dataEndAt = -1;
        if (footerAt >= MAGIC.length) {
            byte[] tail = file.read(footerAt, FOOTER_RECORD_BYTES + MAGIC.length, "footer");
            boolean magicEnd = Arrays.equals(Arrays.copyOfRange(tail, FOOTER_RECORD_BYTES, tail.length), MAGIC);
            if (magicEnd && tail[0] == OP_FOOTER && ByteCursor.le64(tail, 1) == 20) {
                long summaryStart = ByteCursor.le64(tail, 9);
                long summaryCrc = ByteCursor.le32(tail, 25) & 0xffffffffL;
                dataEndAt = (summaryStart != 0 ? summaryStart : footerAt) - McapDataCrc.DATA_END_RECORD_BYTES;
                if (summaryStart != 0) {
                    readSummary(summaryStart, footerAt, tail, summaryCrc);
                    indexed = !chunks.isEmpty() || !channels.isEmpty();
                }
            }
        }
        if (integrity == BagIntegrity.ALL) {
            McapDataCrc.verify(file, source, dataEndAt);
        }
        if (!indexed) {
            // no summary: the channels come from one pass over the data section
            scan(c -> false, (ch, t, d, o, l) -> {
            });
        }
    }

    private void readSummary(long start, long footerAt, byte[] tail, long expectedCrc) {
        if (start < MAGIC.length || start > footerAt) {
            throw BagProblems.corrupt(source, footerAt, "the footer's summary start " + Long.toUnsignedString(start)
                    + " lies outside the file's data (" + MAGIC.length + ".." + footerAt + ")");
        }
        byte[] summary = file.read(start, footerAt - start, "summary section");
        if (expectedCrc != 0) {
            CRC32 crc = new CRC32();
            crc.update(summary);
            crc.update(tail, 0, 1 + 8 + 8 + 8);
            if (crc.getValue() != expectedCrc) {
                throw BagProblems.corrupt(source, start, "summary CRC mismatch (computed " + hex(crc.getValue())
                        + ", footer says " + hex(expectedCrc) + ")");
            }
        }
        ByteCursor c = new ByteCursor(summary, 0, summary.length, source, start, "the summary section");
        while (c.remaining() > 0) {
            long at = c.offset();
            int op = c.u8("record opcode");
            int len = c.length(8, "record length");
            ByteCursor r = new ByteCursor(summary, c.pos, c.pos + len, source, start, "record at byte " + at);
            c.pos += len;
            switch (op) {
                case OP_SCHEMA -> schema(r);
                case OP_CHANNEL -> channel(r);
                case OP_CHUNK_INDEX -> chunkIndex(r);
                default -> {
                    // statistics, attachment and metadata indexes, summary offsets: not needed
                }
            }
        }
        chunks.sort(Comparator.comparingLong(ChunkRef::startTime).thenComparingLong(ChunkRef::offset));
    }

    private void schema(ByteCursor r) {
        int id = r.u16("schema id");
        String name = r.string("schema name");
        String encoding = r.string("schema encoding");
        int n = r.length(4, "schema data length");
        String text = new String(r.buf, r.pos, n, java.nio.charset.StandardCharsets.UTF_8);
        r.pos += n;
        schemas.putIfAbsent(id, new Schema(name, encoding, text));
    }

    private void channel(ByteCursor r) {
        int id = r.u16("channel id");
        int schemaId = r.u16("channel schema id");
        String topic = r.string("channel topic");
        String encoding = r.string("channel message encoding");
        Schema s = schemas.get(schemaId);
        if (schemaId != 0 && s == null) {
            throw BagProblems.corrupt(source, r.offset(), "channel " + id + " (" + topic + ") names schema " + schemaId
                    + ", which is not defined before it");
        }
        if (!channels.containsKey(id)) {
            BagChannel ch = new BagChannel(id, topic, s == null ? "" : s.name(), s == null ? "" : s.encoding(),
                    s == null ? "" : s.text(), encoding);
            channels.put(id, ch);
            byId[id] = ch;
            if (scanWant != null) {
                scanWant[id] = scanWanted.test(ch);
            }
        }
    }

    private void chunkIndex(ByteCursor r) {
        long startTime = r.u64("chunk index message start time");
        r.u64("chunk index message end time");
        long offset = r.u64("chunk start offset");
        long length = r.u64("chunk length");
        int mapBytes = r.length(4, "message index offsets length");
        if (mapBytes % 10 != 0) {
            throw BagProblems.corrupt(source, r.offset(), "message index offsets of " + mapBytes
                    + " bytes are not a whole number of (u16 channel, u64 offset) entries");
        }
        int[] ids = new int[mapBytes / 10];
        for (int i = 0; i < ids.length; i++) {
            ids[i] = r.u16("message index channel");
            r.u64("message index offset");
        }
        chunks.add(new ChunkRef(startTime, offset, length, ids));
    }

    @Override
    public List<BagChannel> channels() {
        return List.copyOf(channels.values());
    }

    @Override
    public void read(Predicate<BagChannel> wanted, MessageSink sink) {
        if (!indexed) {
            scan(wanted, sink);
            return;
        }
        boolean[] want = new boolean[1 << 16];
        boolean any = false;
        for (BagChannel ch : channels.values()) {
            want[ch.id()] = wanted.test(ch);
            any |= want[ch.id()];
        }
        if (!any) {
            return;
        }
        for (ChunkRef ref : chunks) {
            if (!holdsWanted(ref, want)) {
                continue;
            }
            String where = "chunk at byte " + Long.toUnsignedString(ref.offset());
            byte[] rec = file.read(ref.offset(), ref.length(), "the chunk index's chunk at byte "
                    + Long.toUnsignedString(ref.offset()));
            if (rec.length < 9 || rec[0] != OP_CHUNK || ByteCursor.le64(rec, 1) != rec.length - 9L) {
                throw BagProblems.corrupt(source, ref.offset(), "the chunk index points to a record that is not a chunk of "
                        + ref.length() + " bytes");
            }
            chunk(new ByteCursor(rec, 9, rec.length, source, ref.offset(), where), want, sink);
        }
    }

    private static boolean holdsWanted(ChunkRef ref, boolean[] want) {
        if (ref.channels().length == 0) {
            return true;
        }
        for (int id : ref.channels()) {
            if (want[id]) {
                return true;
            }
        }
        return false;
    }

    /** Decompresses one chunk record's content, checks its CRC and hands out its messages. */
    private void chunk(ByteCursor r, boolean[] want, MessageSink sink) {
        String where = "chunk at byte " + (r.base + r.pos - 9);
        r.u64("chunk message start time");
        r.u64("chunk message end time");
        long size = r.u64("chunk uncompressed size");
        long crc = r.u32("chunk uncompressed CRC");
        String compression = r.string("chunk compression");
        int len = r.length(8, "chunk records length");
        if (size < 0 || size > file.limits().maxRecordBytes()) {
            throw BagProblems.corrupt(source, r.offset(), where + " claims " + Long.toUnsignedString(size)
                    + " uncompressed bytes, more than the limit of " + file.limits().maxRecordBytes());
        }
        byte[] records;
        int from;
        if ((compression.isEmpty() || compression.equalsIgnoreCase("none")) && len == size) {
            records = r.buf; // uncompressed: the records are read where they lie, not copied
            from = r.pos;
        } else {
            records = ChunkCodec.decompress(source, where, compression, r.buf, r.pos, len, (int) size);
            from = 0;
        }
        if (crc != 0) {
            CRC32 c = new CRC32();
            c.update(records, from, (int) size);
            if (c.getValue() != crc) {
                throw BagProblems.corrupt(source, -1, where + ": CRC of the uncompressed records mismatch (computed "
                        + hex(c.getValue()) + ", chunk says " + hex(crc) + ")");
            }
        }
        // in place, the bytes are the file's: offsets in refusals stay file offsets
        records(new ByteCursor(records, from, from + (int) size, source, records == r.buf ? r.base : -1, where), want,
                sink, false);
    }

    /**
     * Walks records: schemas and channels are registered, messages of wanted channels handed out,
     * chunks opened (in a linear scan). Stops at the data end or the footer.
     */
    private boolean records(ByteCursor c, boolean[] want, MessageSink sink, boolean top) {
        byte[] b = c.buf;
        while (c.remaining() > 0) {
            long at = c.offset();
            int op = c.u8("record opcode");
            int len = c.length(8, "record length");
            int from = c.pos;
            c.pos += len;
            if (op == OP_MESSAGE) {
                // the hot path, one per message: read in place, no cursor, no text built
                if (len < MESSAGE_HEADER_BYTES) {
                    throw BagProblems.corrupt(source, c.base >= 0 ? at : -1, "a message record of " + len
                            + " bytes is shorter than its " + MESSAGE_HEADER_BYTES + "-byte header (" + c.where + ")");
                }
                int id = (b[from] & 0xff) | (b[from + 1] & 0xff) << 8;
                if (want != null && want[id]) {
                    BagChannel ch = byId[id];
                    if (ch == null) {
                        throw BagProblems.corrupt(source, c.base >= 0 ? at : -1, "a message names channel " + id
                                + ", which is not defined before it");
                    }
                    long logTime = ByteCursor.le64(b, from + 6);
                    sink.message(ch, logTime, b, from + MESSAGE_HEADER_BYTES, len - MESSAGE_HEADER_BYTES);
                }
                continue;
            }
            ByteCursor r = new ByteCursor(b, from, from + len, source, c.base, "record at "
                    + (c.base >= 0 ? "byte " : "chunk offset ") + at);
            switch (op) {
                case OP_SCHEMA -> schema(r);
                case OP_CHANNEL -> channel(r);
                case OP_CHUNK -> {
                    if (!top) {
                        throw BagProblems.corrupt(source, -1, "a chunk inside a chunk (" + r.where + ")");
                    }
                    chunk(r, want, sink);
                }
                case OP_DATA_END, OP_FOOTER -> {
                    return true;
                }
                default -> {
                    // header, message indexes, attachments, metadata, statistics: not needed here
                }
            }
        }
        return false;
    }

    /** Linear scan of the whole data section, one top-level record in memory at a time. */
    private void scan(Predicate<BagChannel> wanted, MessageSink sink) {
        long size = file.size();
        long at = MAGIC.length;
        boolean[] want = new boolean[1 << 16];
        for (BagChannel ch : channels.values()) {
            want[ch.id()] = wanted.test(ch);
        }
        scanWanted = wanted;
        scanWant = want;
        try {
            scanFrom(at, size, want, sink);
        } finally {
            scanWanted = null;
            scanWant = null;
        }
    }

    private void scanFrom(long at, long size, boolean[] want, MessageSink sink) {
        while (at < size) {
            if (size - at < 9) {
                throw BagProblems.corrupt(source, at, "the file ends inside a record header (truncated?)");
            }
            byte[] head = file.read(at, 9, "record header");
            int op = head[0] & 0xff;
            long len = ByteCursor.le64(head, 1);
            if (op == OP_FOOTER || op == OP_DATA_END) {
                return;
            }
            if (len < 0 || len > size - at - 9) {
                throw BagProblems.length(source, at, "record (opcode 0x" + Integer.toHexString(op) + ") length",
                        len, size - at - 9);
            }
            boolean needed = op == OP_SCHEMA || op == OP_CHANNEL || op == OP_CHUNK || op == OP_MESSAGE;
            if (needed) {
                byte[] rec = file.read(at, 9 + len, "record");
                records(new ByteCursor(rec, 0, rec.length, source, at, "record at byte " + at), want, sink, true);
            }
            at += 9 + len;
        }
        throw BagProblems.corrupt(source, size, "the file ends without a data end or footer record (truncated?)");
    }

    private static String hex(long v) {
        return String.format("0x%08x", v);
    }

    @Override
    public void close() {
        file.close();
    }
}
