package org.trajeval.core.io.bag;

import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.function.Predicate;

/**
 * ROS 1 bags, format 2.0 (wiki.ros.org/Bags/Format/2.0): {@code #ROSBAG V2.0}, then records of
 * {@code uint32 header length, header fields (uint32 length, name=value), uint32 data length,
 * data}. The bag header points to the index section (connections and chunk infos); only the
 * chunks whose infos name a wanted connection are read and decompressed (none, bz2 or lz4).
 * A bag without an index (recording interrupted) is scanned from the start.
 */
final class Ros1BagReader implements BagContainer {
    static final int OP_MESSAGE = 0x02;
    static final int OP_BAG_HEADER = 0x03;
    static final int OP_CHUNK = 0x05;
    static final int OP_CONNECTION = 0x07;
    static final int OP_CHUNK_INFO = 0x06;

    /** A chunk info: where the chunk is and which connections it holds. */
    private record ChunkRef(long position, int[] connections) {
    }

    /** One record: header fields, the length of its data and the file offset just past it. */
    private record Record(Map<String, byte[]> fields, int dataLength, long end) {
        int op(String source, long at) {
            byte[] op = fields.get("op");
            if (op == null || op.length != 1) {
                throw BagProblems.corrupt(source, at, "a record header has no one-byte 'op' field");
            }
            return op[0] & 0xff;
        }
    }

    private final FileWindow file;
    private final String source;
    private final Map<Integer, BagChannel> channels = new TreeMap<>();
    private final List<ChunkRef> chunks = new ArrayList<>();
    private final long dataStart;
    private boolean indexed;
    private Predicate<BagChannel> scanWanted;
    private boolean[] scanWant;

    Ros1BagReader(Path path, String source, BagLimits limits) {
        this.file = new FileWindow(path, source, limits);
        this.source = source;
        try {
            byte[] magic = file.read(0, Bags.ROS1_MAGIC.length, "magic");
            if (!java.util.Arrays.equals(magic, Bags.ROS1_MAGIC)) {
                throw BagProblems.corrupt(source, 0, "not a ROS 1 bag (expected '#ROSBAG V2.0')");
            }
            long at = Bags.ROS1_MAGIC.length;
            Record header = record(at, "bag header");
            if (header.op(source, at) != OP_BAG_HEADER) {
                throw BagProblems.corrupt(source, at, "the first record is not the bag header");
            }
            long indexPos = u64(header, "index_pos", at);
            dataStart = header.end();
            if (indexPos >= dataStart && indexPos < file.size()) {
                readIndex(indexPos);
                indexed = true;
            } else {
                scan(c -> false, (c, t, d, o, l) -> {
                });
            }
        } catch (RuntimeException e) {
            file.close();
            throw e;
        }
    }

    @Override
    public String kind() {
        return "ROS 1";
    }

    /** Reads the record at a file offset: its header in full, its data too unless it is larger than needed. */
    private Record record(long at, String what) {
        long size = file.size();
        if (size - at < 4) {
            throw BagProblems.corrupt(source, at, "the file ends inside " + what + " (truncated?)");
        }
        long hlen = ByteCursor.le32(file.read(at, 4, what + " header length"), 0) & 0xffffffffL;
        byte[] head = file.read(at + 4, hlen, what + " header");
        long dlenAt = at + 4 + hlen;
        long dlen = ByteCursor.le32(file.read(dlenAt, 4, what + " data length"), 0) & 0xffffffffL;
        if (dlen > size - dlenAt - 4) {
            throw BagProblems.length(source, dlenAt, what + " data length", dlen, size - dlenAt - 4);
        }
        Map<String, byte[]> fields = fields(head, 0, head.length, at + 4);
        return new Record(fields, (int) Math.min(dlen, Integer.MAX_VALUE), dlenAt + 4 + dlen);
    }

    private byte[] data(long dataAt, Record r, String what) {
        return file.read(dataAt, r.dataLength(), what);
    }

    private Map<String, byte[]> fields(byte[] b, int from, int to, long base) {
        Map<String, byte[]> out = new HashMap<>();
        ByteCursor c = new ByteCursor(b, from, to, source, base, "a record header");
        while (c.remaining() > 0) {
            int len = c.length(4, "header field length");
            int eq = -1;
            for (int i = c.pos; i < c.pos + len; i++) {
                if (b[i] == '=') {
                    eq = i;
                    break;
                }
            }
            if (eq < 0) {
                throw BagProblems.corrupt(source, c.offset(), "a record header field has no '='");
            }
            String name = new String(b, c.pos, eq - c.pos, StandardCharsets.UTF_8);
            out.put(name, java.util.Arrays.copyOfRange(b, eq + 1, c.pos + len));
            c.pos += len;
        }
        return out;
    }

    private long u64(Record r, String name, long at) {
        byte[] v = r.fields().get(name);
        if (v == null || v.length != 8) {
            throw BagProblems.corrupt(source, at, "record field '" + name + "' must be 8 bytes");
        }
        return ByteCursor.le64(v, 0);
    }

    private long u32(Map<String, byte[]> f, String name, long at) {
        byte[] v = f.get(name);
        if (v == null || v.length != 4) {
            throw BagProblems.corrupt(source, at, "record field '" + name + "' must be 4 bytes");
        }
        return ByteCursor.le32(v, 0) & 0xffffffffL;
    }

    private String text(Map<String, byte[]> f, String name) {
        byte[] v = f.get(name);
        return v == null ? "" : new String(v, StandardCharsets.UTF_8);
    }

    private void readIndex(long at) {
        long size = file.size();
        while (at < size) {
            Record r = record(at, "index record");
            int op = r.op(source, at);
            long dataAt = r.end() - r.dataLength();
            if (op == OP_CONNECTION) {
                connection(r.fields(), data(dataAt, r, "connection data"), at);
            } else if (op == OP_CHUNK_INFO) {
                long pos = u64(r, "chunk_pos", at);
                long count = u32(r.fields(), "count", at);
                if (count * 8 != r.dataLength()) {
                    throw BagProblems.corrupt(source, at, "a chunk info claims " + count + " connections but holds "
                            + r.dataLength() + " bytes of counts");
                }
                byte[] d = data(dataAt, r, "chunk info data");
                int[] ids = new int[(int) count];
                for (int i = 0; i < ids.length; i++) {
                    ids[i] = ByteCursor.le32(d, 8 * i);
                }
                chunks.add(new ChunkRef(pos, ids));
            }
            at = r.end();
        }
    }

    private void connection(Map<String, byte[]> header, byte[] data, long at) {
        int id = (int) u32(header, "conn", at);
        if (channels.containsKey(id)) {
            return;
        }
        Map<String, byte[]> f = fields(data, 0, data.length, -1);
        String topic = text(header, "topic");
        BagChannel ch = new BagChannel(id, topic, text(f, "type"), "ros1msg", text(f, "message_definition"), "ros1");
        channels.put(id, ch);
        if (scanWant != null && id >= 0 && id < scanWant.length) {
            scanWant[id] = scanWanted.test(ch);
        }
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
        Map<Integer, Boolean> want = new HashMap<>();
        for (BagChannel c : channels.values()) {
            want.put(c.id(), wanted.test(c));
        }
        for (ChunkRef ref : chunks) {
            boolean any = false;
            for (int id : ref.connections()) {
                any |= want.getOrDefault(id, false);
            }
            if (!any) {
                continue;
            }
            if (ref.position() < dataStart || ref.position() >= file.size()) {
                throw BagProblems.corrupt(source, -1, "a chunk info points to byte " + ref.position()
                        + ", outside the data (" + dataStart + ".." + file.size() + ")");
            }
            Record r = record(ref.position(), "chunk");
            if (r.op(source, ref.position()) != OP_CHUNK) {
                throw BagProblems.corrupt(source, ref.position(), "a chunk info points to a record that is not a chunk");
            }
            chunk(ref.position(), r, id -> want.getOrDefault(id, false), sink);
        }
    }

    private void chunk(long at, Record r, java.util.function.IntPredicate want, MessageSink sink) {
        String where = "chunk at byte " + at;
        long size = u32(r.fields(), "size", at);
        if (size > file.limits().maxRecordBytes()) {
            throw BagProblems.corrupt(source, at, where + " claims " + size + " uncompressed bytes, more than the limit of "
                    + file.limits().maxRecordBytes());
        }
        byte[] packed = data(r.end() - r.dataLength(), r, where);
        byte[] records = ChunkCodec.decompress(source, where, text(r.fields(), "compression"), packed, 0,
                packed.length, (int) size);
        ByteCursor c = new ByteCursor(records, 0, records.length, source, -1, where);
        while (c.remaining() > 0) {
            int hlen = c.length(4, "record header length");
            Map<String, byte[]> f = fields(records, c.pos, c.pos + hlen, -1);
            c.pos += hlen;
            int dlen = c.length(4, "record data length");
            int dataAt = c.pos;
            c.pos += dlen;
            byte[] op = f.get("op");
            int o = op != null && op.length == 1 ? op[0] & 0xff : -1;
            if (o == OP_CONNECTION) {
                connection(f, java.util.Arrays.copyOfRange(records, dataAt, dataAt + dlen), -1);
            } else if (o == OP_MESSAGE) {
                int id = (int) u32(f, "conn", -1);
                if (want.test(id)) {
                    BagChannel ch = channels.get(id);
                    if (ch == null) {
                        throw BagProblems.corrupt(source, -1, where + ": a message names connection " + id
                                + ", which is not defined");
                    }
                    byte[] t = f.get("time");
                    if (t == null || t.length != 8) {
                        throw BagProblems.corrupt(source, -1, where + ": a message has no 8-byte 'time' field");
                    }
                    long ns = (ByteCursor.le32(t, 0) & 0xffffffffL) * 1_000_000_000L + (ByteCursor.le32(t, 4) & 0xffffffffL);
                    sink.message(ch, ns, records, dataAt, dlen);
                }
            } else if (o < 0) {
                throw BagProblems.corrupt(source, -1, where + ": a record header has no one-byte 'op' field");
            }
        }
    }

    /** Linear scan from the first record after the bag header. */
    private void scan(Predicate<BagChannel> wanted, MessageSink sink) {
        boolean[] want = new boolean[1 << 16];
        scanWanted = wanted;
        scanWant = want;
        try {
            long at = dataStart;
            long size = file.size();
            while (at < size) {
                Record r = record(at, "record");
                int op = r.op(source, at);
                if (op == OP_CHUNK) {
                    chunk(at, r, id -> id >= 0 && id < want.length && want[id], sink);
                } else if (op == OP_CONNECTION) {
                    connection(r.fields(), data(r.end() - r.dataLength(), r, "connection data"), at);
                }
                at = r.end();
            }
        } finally {
            scanWanted = null;
            scanWant = null;
        }
    }

    @Override
    public void close() {
        file.close();
    }
}
