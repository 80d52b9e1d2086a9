package org.trajeval.core.io.bag;

import io.airlift.compress.lz4.Lz4Compressor;
import io.airlift.compress.zstd.ZstdCompressor;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.io.UncheckedIOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.zip.CRC32;
import org.apache.commons.compress.compressors.bzip2.BZip2CompressorOutputStream;

/**
 * Writers of small bags with known content, for tests and benchmarks: MCAP (chunks uncompressed,
 * lz4 or zstd, with or without a summary) and ROS 1 bags (chunks none, bz2 or lz4), messages
 * serialised as CDR or ROS 1 by hand, following the formats' specifications (mcap.dev/spec,
 * wiki.ros.org/Bags/Format/2.0) independently of the readers under test.
 */
public final class BagWriters {
    /** ros2msg definition of geometry_msgs/msg/PoseStamped with its dependencies, as rosbag2 stores it. */
    public static final String POSE_STAMPED_ROS2 = String.join("\n",
            "std_msgs/Header header", "Pose pose", sep("std_msgs/Header"), "builtin_interfaces/Time stamp",
            "string frame_id", sep("builtin_interfaces/Time"), "int32 sec", "uint32 nanosec",
            sep("geometry_msgs/Pose"), "Point position", "Quaternion orientation", sep("geometry_msgs/Point"),
            "float64 x", "float64 y", "float64 z", sep("geometry_msgs/Quaternion"), "float64 x 0", "float64 y 0",
            "float64 z 0", "float64 w 1", "");
    /** ros1msg definition of geometry_msgs/PoseStamped. */
    public static final String POSE_STAMPED_ROS1 = String.join("\n",
            "Header header", "Pose pose", sep("std_msgs/Header"), "uint32 seq", "time stamp", "string frame_id",
            sep("geometry_msgs/Pose"), "Point position", "Quaternion orientation", sep("geometry_msgs/Point"),
            "float64 x", "float64 y", "float64 z", sep("geometry_msgs/Quaternion"), "float64 x", "float64 y",
            "float64 z", "float64 w", "");
    /** ros2msg definition of tf2_msgs/msg/TFMessage. */
    public static final String TF_MESSAGE_ROS2 = String.join("\n",
            "geometry_msgs/TransformStamped[] transforms", sep("geometry_msgs/TransformStamped"),
            "std_msgs/Header header", "string child_frame_id", "Transform transform", sep("std_msgs/Header"),
            "builtin_interfaces/Time stamp", "string frame_id", sep("builtin_interfaces/Time"), "int32 sec",
            "uint32 nanosec", sep("geometry_msgs/Transform"), "Vector3 translation", "Quaternion rotation",
            sep("geometry_msgs/Vector3"), "float64 x", "float64 y", "float64 z", sep("geometry_msgs/Quaternion"),
            "float64 x", "float64 y", "float64 z", "float64 w", "");

    private BagWriters() {
    }

    private static String sep(String type) {
        return "================================================================================\nMSG: " + type;
    }

    /** One pose: stamp (ns), position (m), quaternion (x, y, z, w), frame ids. */
    public record Pose(long stampNs, double x, double y, double z, double qx, double qy, double qz, double qw,
            String frame, String child) {
        /** @return a pose in frame "map" with no child frame */
        public static Pose of(long stampNs, double x, double y, double z, double qx, double qy, double qz, double qw) {
            return new Pose(stampNs, x, y, z, qx, qy, qz, qw, "map", "");
        }
    }

    // ---------------------------------------------------------------- serialisation

    /** Little-endian byte sink with CDR alignment relative to {@code origin}. */
    static final class Out {
        ByteBuffer b = ByteBuffer.allocate(256).order(ByteOrder.LITTLE_ENDIAN);
        int origin;

        void ensure(int n) {
            if (b.remaining() < n) {
                ByteBuffer g = ByteBuffer.allocate(Math.max(b.capacity() * 2, b.position() + n)).order(ByteOrder.LITTLE_ENDIAN);
                b.flip();
                g.put(b);
                b = g;
            }
        }

        Out align(int n) {
            while ((b.position() - origin) % n != 0) {
                u8(0);
            }
            return this;
        }

        Out u8(int v) {
            ensure(1);
            b.put((byte) v);
            return this;
        }

        Out u16(int v) {
            ensure(2);
            b.putShort((short) v);
            return this;
        }

        Out u32(long v) {
            ensure(4);
            b.putInt((int) v);
            return this;
        }

        Out u64(long v) {
            ensure(8);
            b.putLong(v);
            return this;
        }

        Out f64(double v) {
            ensure(8);
            b.putDouble(v);
            return this;
        }

        Out bytes(byte[] v) {
            ensure(v.length);
            b.put(v);
            return this;
        }

        /** A uint32-length-prefixed UTF-8 string (MCAP, ROS 1). */
        Out str(String s) {
            byte[] v = s.getBytes(StandardCharsets.UTF_8);
            return u32(v.length).bytes(v);
        }

        byte[] toArray() {
            return Arrays.copyOf(b.array(), b.position());
        }
    }

    /** CDR (little-endian) of geometry_msgs/msg/PoseStamped. */
    public static byte[] cdrPoseStamped(Pose p) {
        Out o = new Out();
        o.u8(0).u8(1).u8(0).u8(0);
        o.origin = 4;
        cdrHeader(o, p);
        o.align(8).f64(p.x()).f64(p.y()).f64(p.z()).f64(p.qx()).f64(p.qy()).f64(p.qz()).f64(p.qw());
        return o.toArray();
    }

    private static void cdrHeader(Out o, Pose p) {
        o.align(4).u32(Math.floorDiv(p.stampNs(), 1_000_000_000L)).u32(Math.floorMod(p.stampNs(), 1_000_000_000L));
        cdrString(o, p.frame());
    }

    private static void cdrString(Out o, String s) {
        byte[] v = s.getBytes(StandardCharsets.UTF_8);
        o.align(4).u32(v.length + 1).bytes(v).u8(0);
    }

    /** CDR of tf2_msgs/msg/TFMessage holding the given transforms (frame -> child). */
    public static byte[] cdrTfMessage(List<Pose> transforms) {
        Out o = new Out();
        o.u8(0).u8(1).u8(0).u8(0);
        o.origin = 4;
        o.align(4).u32(transforms.size());
        for (Pose p : transforms) {
            cdrHeader(o, p);
            cdrString(o, p.child());
            o.align(8).f64(p.x()).f64(p.y()).f64(p.z()).f64(p.qx()).f64(p.qy()).f64(p.qz()).f64(p.qw());
        }
        return o.toArray();
    }

    /** ROS 1 serialisation of geometry_msgs/PoseStamped. */
    public static byte[] ros1PoseStamped(Pose p, int seq) {
        Out o = new Out();
        o.u32(seq).u32(p.stampNs() / 1_000_000_000L).u32(p.stampNs() % 1_000_000_000L).str(p.frame());
        o.f64(p.x()).f64(p.y()).f64(p.z()).f64(p.qx()).f64(p.qy()).f64(p.qz()).f64(p.qw());
        return o.toArray();
    }

    // ---------------------------------------------------------------- compression

    /** LZ4 frame (independent blocks of at most 64 KiB, no checksums) around raw LZ4 blocks. */
    public static byte[] lz4Frame(byte[] data) {
        Out o = new Out();
        o.u32(0x184D2204L).u8(0x60).u8(0x40).u8(0x82); // FLG: version 1, independent blocks; BD: 64 KiB; HC
        Lz4Compressor c = new Lz4Compressor();
        for (int off = 0; off < data.length; off += 65536) {
            int n = Math.min(65536, data.length - off);
            byte[] block = new byte[c.maxCompressedLength(n)];
            int m = c.compress(data, off, n, block, 0, block.length);
            o.u32(m).bytes(Arrays.copyOf(block, m));
        }
        o.u32(0);
        return o.toArray();
    }

    static byte[] zstd(byte[] data) {
        ZstdCompressor c = new ZstdCompressor();
        byte[] out = new byte[c.maxCompressedLength(data.length)];
        int n = c.compress(data, 0, data.length, out, 0, out.length);
        return Arrays.copyOf(out, n);
    }

    static byte[] bz2(byte[] data) {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        try (OutputStream s = new BZip2CompressorOutputStream(bytes)) {
            s.write(data);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        return bytes.toByteArray();
    }

    static byte[] compress(String compression, byte[] data) {
        return switch (compression) {
            case "", "none" -> data;
            case "lz4" -> lz4Frame(data);
            case "zstd" -> zstd(data);
            case "bz2" -> bz2(data);
            default -> data; // a name no reader knows, for refusal tests: the bytes stay as they are
        };
    }

    // ---------------------------------------------------------------- MCAP

    /** One channel of a bag to write: topic, type, definition, encoding, and its serialised messages with log times. */
    public record Topic(String topic, String type, String definition, List<long[]> logTimes, List<byte[]> messages) {
        public Topic(String topic, String type, String definition) {
            this(topic, type, definition, new ArrayList<>(), new ArrayList<>());
        }

        /** Adds one message with its log time (ns). */
        public Topic add(long logTimeNs, byte[] message) {
            logTimes.add(new long[] {logTimeNs});
            messages.add(message);
            return this;
        }
    }

    /**
     * An MCAP file: header, schemas and channels, then the messages in chunks of at most
     * {@code perChunk} messages (round robin over the topics), data end, and (when {@code summary})
     * a summary with schemas, channels and chunk indexes, a footer with the summary CRC.
     */
    public static byte[] mcap(List<Topic> topics, String compression, int perChunk, boolean summary) {
        Out f = new Out();
        f.bytes(McapReader.MAGIC);
        record(f, 0x01, new Out().str("ros2").str("trajeval-test"));
        List<byte[]> defs = new ArrayList<>();
        for (int i = 0; i < topics.size(); i++) {
            Topic t = topics.get(i);
            byte[] schema = recordBytes(0x03, new Out().u16(i + 1).str(t.type()).str("ros2msg")
                    .u32(t.definition().getBytes(StandardCharsets.UTF_8).length)
                    .bytes(t.definition().getBytes(StandardCharsets.UTF_8)));
            byte[] channel = recordBytes(0x04, new Out().u16(i).u16(i + 1).str(t.topic()).str("cdr").u32(0));
            f.bytes(schema).bytes(channel);
            defs.add(schema);
            defs.add(channel);
        }
        // interleave messages by log time
        List<long[]> order = new ArrayList<>(); // {logTime, topic, index}
        for (int i = 0; i < topics.size(); i++) {
            for (int k = 0; k < topics.get(i).messages().size(); k++) {
                order.add(new long[] {topics.get(i).logTimes().get(k)[0], i, k});
            }
        }
        order.sort((a, b) -> Long.compare(a[0], b[0]));
        List<byte[]> chunkIndexes = new ArrayList<>();
        for (int from = 0; from < order.size(); from += perChunk) {
            List<long[]> part = order.subList(from, Math.min(order.size(), from + perChunk));
            Out recs = new Out();
            Map<Integer, Boolean> chans = new LinkedHashMap<>();
            for (long[] m : part) {
                Topic t = topics.get((int) m[1]);
                byte[] data = t.messages().get((int) m[2]);
                record(recs, 0x05, new Out().u16((int) m[1]).u32(0).u64(m[0]).u64(m[0]).bytes(data));
                chans.put((int) m[1], true);
            }
            byte[] raw = recs.toArray();
            byte[] packed = compress(compression, raw);
            CRC32 crc = new CRC32();
            crc.update(raw);
            long start = part.get(0)[0];
            long end = part.get(part.size() - 1)[0];
            long offset = f.b.position();
            byte[] chunk = recordBytes(0x06, new Out().u64(start).u64(end).u64(raw.length).u32(crc.getValue())
                    .str(compression).u64(packed.length).bytes(packed));
            f.bytes(chunk);
            Out idx = new Out().u64(start).u64(end).u64(offset).u64(chunk.length).u32(chans.size() * 10L);
            for (int c : chans.keySet()) {
                idx.u16(c).u64(0);
            }
            idx.u64(0).str(compression).u64(packed.length).u64(raw.length);
            chunkIndexes.add(recordBytes(0x08, idx));
        }
        CRC32 dataCrc = new CRC32(); // the data section CRC: every byte before the Data End, magic included
        dataCrc.update(f.b.array(), 0, f.b.position());
        record(f, 0x0F, new Out().u32(dataCrc.getValue()));
        long summaryStart = 0;
        if (summary) {
            summaryStart = f.b.position();
            for (byte[] d : defs) {
                f.bytes(d);
            }
            for (byte[] c : chunkIndexes) {
                f.bytes(c);
            }
        }
        f.u8(0x02).u64(20).u64(summaryStart).u64(0);
        long crc = 0;
        if (summary) {
            CRC32 c = new CRC32();
            byte[] all = f.toArray();
            c.update(all, (int) summaryStart, all.length - (int) summaryStart);
            crc = c.getValue();
        }
        f.u32(crc);
        f.bytes(McapReader.MAGIC);
        return f.toArray();
    }

    /**
     * Recomputes the data section CRC of an MCAP written by {@link #mcap} after a test changed
     * bytes of its data section, so that the test reaches the check it aims at (a chunk CRC, a
     * chunk size) instead of the data section CRC. Walks the records from the magic to the Data End.
     */
    public static byte[] resealDataCrc(byte[] mcap) {
        ByteBuffer b = ByteBuffer.wrap(mcap).order(ByteOrder.LITTLE_ENDIAN);
        int at = McapReader.MAGIC.length;
        while (mcap[at] != 0x0F) {
            at += 9 + (int) b.getLong(at + 1);
        }
        CRC32 crc = new CRC32();
        crc.update(mcap, 0, at);
        b.putInt(at + 9, (int) crc.getValue());
        return mcap;
    }

    private static void record(Out f, int op, Out content) {
        f.bytes(recordBytes(op, content));
    }

    private static byte[] recordBytes(int op, Out content) {
        byte[] c = content.toArray();
        return new Out().u8(op).u64(c.length).bytes(c).toArray();
    }

    // ---------------------------------------------------------------- ROS 1

    /** A ROS 1 bag record: header fields (name=value) and data. */
    private static byte[] ros1Record(Map<String, byte[]> fields, byte[] data) {
        Out h = new Out();
        for (Map.Entry<String, byte[]> e : fields.entrySet()) {
            byte[] name = (e.getKey() + "=").getBytes(StandardCharsets.UTF_8);
            h.u32(name.length + e.getValue().length).bytes(name).bytes(e.getValue());
        }
        byte[] head = h.toArray();
        return new Out().u32(head.length).bytes(head).u32(data.length).bytes(data).toArray();
    }

    private static Map<String, byte[]> fields(Object... kv) {
        Map<String, byte[]> m = new LinkedHashMap<>();
        for (int i = 0; i < kv.length; i += 2) {
            Object v = kv[i + 1];
            byte[] b;
            if (v instanceof byte[] bytes) {
                b = bytes;
            } else if (v instanceof String s) {
                b = s.getBytes(StandardCharsets.UTF_8);
            } else if (v instanceof Integer n) {
                b = new Out().u32(n).toArray();
            } else {
                b = new Out().u64((Long) v).toArray();
            }
            m.put((String) kv[i], b);
        }
        return m;
    }

    private static byte[] op(int op) {
        return new byte[] {(byte) op};
    }

    private static byte[] time(long ns) {
        return new Out().u32(ns / 1_000_000_000L).u32(ns % 1_000_000_000L).toArray();
    }

    /**
     * A ROS 1 bag (format 2.0) with ROS 1-serialised messages: bag header, chunks of at most
     * {@code perChunk} messages (compression none, bz2 or lz4), then the index section
     * (connections, chunk infos) that the bag header points to.
     */
    public static byte[] ros1Bag(List<Topic> topics, String compression, int perChunk) {
        Out f = new Out();
        f.bytes(Bags.ROS1_MAGIC);
        int headerAt = f.b.position();
        byte[] header = bagHeader(0, topics.size(), 0);
        f.bytes(header);
        List<byte[]> connections = new ArrayList<>();
        for (int i = 0; i < topics.size(); i++) {
            Topic t = topics.get(i);
            Out data = new Out();
            for (String[] kv : new String[][] {{"topic", t.topic()}, {"type", t.type()}, {"md5sum", "*"},
                {"message_definition", t.definition()}}) {
                byte[] v = (kv[0] + "=" + kv[1]).getBytes(StandardCharsets.UTF_8);
                data.u32(v.length).bytes(v);
            }
            connections.add(ros1Record(fields("op", op(0x07), "conn", i, "topic", t.topic()), data.toArray()));
        }
        List<long[]> order = new ArrayList<>();
        for (int i = 0; i < topics.size(); i++) {
            for (int k = 0; k < topics.get(i).messages().size(); k++) {
                order.add(new long[] {topics.get(i).logTimes().get(k)[0], i, k});
            }
        }
        order.sort((a, b) -> Long.compare(a[0], b[0]));
        List<byte[]> infos = new ArrayList<>();
        for (int from = 0; from < order.size(); from += perChunk) {
            List<long[]> part = order.subList(from, Math.min(order.size(), from + perChunk));
            Out recs = new Out();
            Map<Integer, Integer> counts = new LinkedHashMap<>();
            for (long[] m : part) {
                int c = (int) m[1];
                if (!counts.containsKey(c)) {
                    recs.bytes(connections.get(c));
                }
                counts.merge(c, 1, Integer::sum);
                recs.bytes(ros1Record(fields("op", op(0x02), "conn", c, "time", time(m[0])),
                        topics.get(c).messages().get((int) m[2])));
            }
            byte[] raw = recs.toArray();
            long pos = f.b.position();
            f.bytes(ros1Record(fields("op", op(0x05), "compression", compression, "size", raw.length),
                    compress(compression, raw)));
            Out counted = new Out();
            for (Map.Entry<Integer, Integer> e : counts.entrySet()) {
                counted.u32(e.getKey()).u32(e.getValue());
            }
            infos.add(ros1Record(fields("op", op(0x06), "ver", 1, "chunk_pos", pos, "start_time",
                    time(part.get(0)[0]), "end_time", time(part.get(part.size() - 1)[0]), "count", counts.size()),
                    counted.toArray()));
        }
        long indexPos = f.b.position();
        connections.forEach(f::bytes);
        infos.forEach(f::bytes);
        byte[] all = f.toArray();
        byte[] real = bagHeader(indexPos, topics.size(), infos.size());
        System.arraycopy(real, 0, all, headerAt, real.length);
        return all;
    }

    private static byte[] bagHeader(long indexPos, int conns, int chunks) {
        byte[] head = ros1Record(fields("op", op(0x03), "index_pos", indexPos, "conn_count", conns, "chunk_count",
                chunks), new byte[0]);
        // pad the data to 4096 bytes, as rosbag does, so the real header can overwrite the placeholder
        int pad = 4096 - head.length;
        byte[] data = new byte[pad];
        Arrays.fill(data, (byte) ' ');
        return ros1Record(fields("op", op(0x03), "index_pos", indexPos, "conn_count", conns, "chunk_count", chunks),
                data);
    }
}
