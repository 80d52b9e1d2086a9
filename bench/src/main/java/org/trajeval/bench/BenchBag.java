package org.trajeval.bench;

import java.io.BufferedOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Random;
import java.util.zip.CRC32;
import org.trajeval.core.io.bag.BagWriters;

/**
 * Writes the benchmark's MCAP bag straight to disk (never whole in memory, so it can be several
 * GB): {@code poses} geometry_msgs/PoseStamped messages on {@code /pose} at 200 Hz in chunks of
 * 1000, and every {@code heavyEvery} poses a 200 kB "image" ({@code /camera/image_raw}) and a
 * 100 kB "point cloud" ({@code /lidar/points}), each in chunks of their own, as a recorder that
 * chunks per channel writes them; then the data end with the data section CRC, a summary
 * (schemas, channels, chunk indexes) with its CRC, and the footer (mcap.dev/spec). Seeded: the
 * same arguments give the same bytes.
 */
final class BenchBag {
    private static final byte[] MAGIC = {(byte) 0x89, 'M', 'C', 'A', 'P', 0x30, '\r', '\n'};
    private static final int POSES_PER_CHUNK = 1000;

    private final OutputStream out;
    private final CRC32 dataCrc = new CRC32();
    private final String compression;
    private final List<byte[]> summary = new ArrayList<>();
    private long position;

    private BenchBag(OutputStream out, String compression) {
        this.out = out;
        this.compression = compression;
    }

    /**
     * @param compression "" (none) or "lz4"
     * @return the file (written only when missing)
     */
    static Path write(Path file, int poses, int heavyEvery, String compression) throws IOException {
        if (Files.isRegularFile(file)) {
            return file;
        }
        Path tmp = file.resolveSibling(file.getFileName() + ".part");
        try (OutputStream os = new BufferedOutputStream(Files.newOutputStream(tmp), 1 << 20)) {
            new BenchBag(os, compression).body(poses, heavyEvery);
        }
        Files.move(tmp, file, java.nio.file.StandardCopyOption.ATOMIC_MOVE);
        return file;
    }

    private void body(int poses, int heavyEvery) throws IOException {
        data(MAGIC); // the data section CRC starts at the leading magic
        data(record(0x01, new Rec().str("ros2").str("trajeval-bench")));
        String[][] topics = {
            {"/pose", "geometry_msgs/msg/PoseStamped", BagWriters.POSE_STAMPED_ROS2},
            {"/camera/image_raw", "sensor_msgs/msg/Image", "uint8[] data\n"},
            {"/lidar/points", "sensor_msgs/msg/PointCloud2", "uint8[] data\n"}};
        for (int i = 0; i < topics.length; i++) {
            byte[] def = topics[i][2].getBytes(StandardCharsets.UTF_8);
            byte[] schema = record(0x03, new Rec().u16(i + 1).str(topics[i][1]).str("ros2msg").u32(def.length).bytes(def));
            byte[] channel = record(0x04, new Rec().u16(i).u16(i + 1).str(topics[i][0]).str("cdr").u32(0));
            data(schema);
            data(channel);
            summary.add(schema);
            summary.add(channel);
        }
        Random r = new Random(7);
        byte[] pixels = new byte[200_000];
        byte[] points = new byte[100_000];
        Rec chunk = new Rec();
        long chunkStart = 0;
        int inChunk = 0;
        for (int i = 0; i < poses; i++) {
            long t = 1_700_000_000_000_000_000L + i * 5_000_000L;
            double yaw = 0.001 * i;
            byte[] msg = BagWriters.cdrPoseStamped(BagWriters.Pose.of(t, 0.01 * i, Math.sin(yaw), 0, 0, 0,
                    Math.sin(yaw / 2), Math.cos(yaw / 2)));
            if (inChunk == 0) {
                chunkStart = t;
            }
            chunk.bytes(record(0x05, new Rec().u16(0).u32(i).u64(t).u64(t).bytes(msg)));
            inChunk++;
            if (inChunk == POSES_PER_CHUNK || i == poses - 1) {
                chunk(0, chunkStart, t, chunk.toArray());
                chunk = new Rec();
                inChunk = 0;
            }
            if (heavyEvery > 0 && i % heavyEvery == heavyEvery / 2) {
                r.nextBytes(pixels);
                for (int k = 0; k < pixels.length; k += 2) {
                    pixels[k] = 0; // half the bytes constant: an image compresses a little
                }
                r.nextBytes(points);
                chunk(1, t + 1, t + 1, record(0x05, new Rec().u16(1).u32(i).u64(t + 1).u64(t + 1)
                        .u32(pixels.length).bytes(pixels)));
                chunk(2, t + 2, t + 2, record(0x05, new Rec().u16(2).u32(i).u64(t + 2).u64(t + 2)
                        .u32(points.length).bytes(points)));
            }
        }
        raw(record(0x0F, new Rec().u32(dataCrc.getValue())));
        long summaryStart = position;
        CRC32 summaryCrc = new CRC32();
        for (byte[] s : summary) {
            raw(s);
            summaryCrc.update(s);
        }
        byte[] footer = new Rec().u8(0x02).u64(20).u64(summaryStart).u64(0).toArray();
        summaryCrc.update(footer);
        raw(footer);
        raw(new Rec().u32(summaryCrc.getValue()).toArray());
        raw(MAGIC);
    }

    /** Writes one chunk of one channel and remembers its chunk index. */
    private void chunk(int channel, long start, long end, byte[] records) throws IOException {
        CRC32 crc = new CRC32();
        crc.update(records);
        byte[] packed = compression.equals("lz4") ? BagWriters.lz4Frame(records) : records;
        long offset = position;
        byte[] rec = record(0x06, new Rec().u64(start).u64(end).u64(records.length).u32(crc.getValue())
                .str(compression).u64(packed.length).bytes(packed));
        data(rec);
        summary.add(record(0x08, new Rec().u64(start).u64(end).u64(offset).u64(rec.length).u32(10).u16(channel).u64(0)
                .u64(0).str(compression).u64(packed.length).u64(records.length)));
    }

    private void data(byte[] b) throws IOException {
        dataCrc.update(b);
        raw(b);
    }

    private void raw(byte[] b) throws IOException {
        out.write(b);
        position += b.length;
    }

    private static byte[] record(int op, Rec content) {
        byte[] c = content.toArray();
        return new Rec().u8(op).u64(c.length).bytes(c).toArray();
    }

    /** A growing little-endian byte buffer. */
    private static final class Rec {
        private ByteBuffer b = ByteBuffer.allocate(64).order(ByteOrder.LITTLE_ENDIAN);

        private Rec need(int n) {
            if (b.remaining() < n) {
                ByteBuffer g = ByteBuffer.allocate(Math.max(2 * b.capacity(), b.position() + n))
                        .order(ByteOrder.LITTLE_ENDIAN);
                b.flip();
                g.put(b);
                b = g;
            }
            return this;
        }

        Rec u8(int v) {
            need(1).b.put((byte) v);
            return this;
        }

        Rec u16(int v) {
            need(2).b.putShort((short) v);
            return this;
        }

        Rec u32(long v) {
            need(4).b.putInt((int) v);
            return this;
        }

        Rec u64(long v) {
            need(8).b.putLong(v);
            return this;
        }

        Rec bytes(byte[] v) {
            need(v.length).b.put(v);
            return this;
        }

        Rec str(String s) {
            byte[] v = s.getBytes(StandardCharsets.UTF_8);
            return u32(v.length).bytes(v);
        }

        byte[] toArray() {
            return Arrays.copyOf(b.array(), b.position());
        }
    }
}
