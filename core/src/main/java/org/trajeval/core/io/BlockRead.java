package org.trajeval.core.io;

import java.io.IOException;
import java.io.InputStream;
import java.nio.ByteBuffer;
import java.security.MessageDigest;
import java.util.Arrays;
import java.util.HexFormat;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.atomic.AtomicInteger;

/**
 * One file read in blocks by several threads ({@link ReadThreads}). The file is cut into blocks
 * just after a '\n'; unit 0 hashes every byte in order (SHA-256), unit k parses block k-1 with the
 * format's own line reader ({@link NumericRows} and its batch loop, so the same values and checks)
 * into a segment of its own; segments are appended to the columns in file order, with the
 * timestamp-order check across each block edge. Only a clean file is read this way: on anything
 * else (a refusal, a quote, a header not in the first block, an order problem at an edge, too many
 * poses, a size that changed while it was read) {@link #read} returns null and the caller reads the file as a whole, which then says
 * what it says today (the first bad line in file order).
 */
final class BlockRead {
    /** How a format's blocks are read. */
    interface Format {
        /** @return number of columns, the time included */
        int columns();

        /** Reads what precedes the data in the first block (a header); @return its rows, or null to give up */
        NumericRows first(ByteLines lines);

        /** @return the rows of a later block */
        NumericRows later(ByteLines lines);

        /** @return an empty segment with the format's checks (position range, order within it) */
        PoseBuffer segment();

        /** The format's batch loop ({@code in}, {@code row}: scratch of 8 values): @return false at the block's end */
        boolean readBatch(NumericRows rows, PoseBuffer poses, double[] in, double[] row);

        /** @return the trajectory from the first {@code n} values of the columns */
        LoadedTrajectory result(int n, double[][] columns, String sha256);
    }

    private final ByteSource file;
    private final String source;
    private final ReadOptions options;
    private final Format format;
    private final long[] starts;
    private final AtomicInteger nextUnit = new AtomicInteger();
    private final int units;
    private ByteLines firstLines;
    private NumericRows firstRows;

    private volatile boolean failed;
    private Throwable error;
    private int done;
    private String sha;
    private final PoseBuffer[] segments;
    private int frontier;
    private double[][] columns;
    private int n;
    private double lastT;
    private final long estimate;
    /** Segment columns and block buffers already copied or read, for later blocks (fewer fresh pages and GCs). */
    private final ConcurrentLinkedQueue<double[][]> spareColumns = new ConcurrentLinkedQueue<>();
    private final ConcurrentLinkedQueue<byte[]> spareBuffers = new ConcurrentLinkedQueue<>();

    private BlockRead(ByteSource file, String source, ReadOptions options, Format format, long[] starts, long estimate) {
        this.file = file;
        this.source = source;
        this.options = options;
        this.format = format;
        this.starts = starts;
        this.units = starts.length; // unit 0 hashes; unit k parses [starts[k-1], starts[k])
        this.segments = new PoseBuffer[starts.length - 1];
        this.estimate = estimate;
    }

    /**
     * Reads a file in blocks.
     *
     * @return the trajectory, or null when the file must be read as a whole instead
     */
    static LoadedTrajectory read(ByteSource file, String source, ReadOptions options, Format format,
            ReadThreads threads) {
        long size;
        long[] starts;
        try {
            size = file.size();
            if (!threads.inBlocks(size)) {
                return null;
            }
            starts = cut(file, size, threads.blockBytes());
        } catch (IOException | RuntimeException e) {
            return null;
        }
        if (starts.length < 3) {
            return null;
        }
        double perLine = size > ByteLines.SAMPLES * ByteLines.SAMPLE_BYTES
                ? ByteLines.sampleLineLength(file, size) : Double.NaN;
        long estimate = perLine > 0 ? (long) (size / perLine * 1.02) + 64 : 1024;
        BlockRead r = new BlockRead(file, source, options, format, starts, estimate);
        return r.run(threads);
    }

    /** @return block starts: 0, each just after a '\n', then the size (at least two blocks or fewer starts) */
    static long[] cut(ByteSource file, long size, long blockBytes) throws IOException {
        long[] starts = new long[(int) Math.min(Integer.MAX_VALUE - 8, size / blockBytes + 2)];
        int k = 1;
        long at = blockBytes;
        ByteBuffer buf = ByteBuffer.allocate(1 << 16);
        while (at < size) {
            long nl = -1;
            long p = at;
            while (nl < 0 && p < size) {
                buf.clear();
                int m = file.readAt(p, buf);
                if (m <= 0) {
                    break;
                }
                int i = ByteLines.indexOfNewline(buf.array(), 0, m);
                nl = i >= 0 ? p + i : -1;
                p += m;
            }
            if (nl < 0 || nl + 1 >= size) {
                break;
            }
            starts[k++] = nl + 1;
            at = nl + 1 + blockBytes;
        }
        starts[k++] = size;
        return Arrays.copyOf(starts, k);
    }

    private LoadedTrajectory run(ReadThreads threads) {
        try {
            firstLines = ByteLines.range(file, source, 0, starts[1], null);
            firstRows = format.first(firstLines);
        } catch (RuntimeException e) {
            close(firstLines);
            return null;
        }
        if (firstRows == null) {
            close(firstLines);
            return null;
        }
        threads.start(this);
        try {
            while (runOneUnit()) {
                // this file's units first
            }
        } finally {
            threads.finished(this);
        }
        threads.helpWhileWork(); // then any other file's, while this one's last blocks finish
        synchronized (this) {
            boolean interrupted = false;
            while (done < units) {
                try {
                    wait();
                } catch (InterruptedException e) {
                    interrupted = true;
                }
            }
            if (interrupted) {
                Thread.currentThread().interrupt();
            }
        }
        close(firstLines); // if its unit was skipped after a failure
        if (error instanceof Error e) {
            throw e;
        }
        if (failed || n == 0) {
            return null;
        }
        double[][] c = columns;
        if (c[0].length - n > n / 25) {
            for (int k = 0; k < c.length; k++) {
                c[k] = Arrays.copyOf(c[k], n);
            }
        }
        return format.result(n, c, sha);
    }

    /** Claims and runs the next unit of this file. @return false if every unit was claimed already */
    boolean runOneUnit() {
        int u = nextUnit.getAndIncrement();
        if (u >= units) {
            return false;
        }
        try {
            if (!failed) {
                if (u == 0) {
                    String h = hash();
                    synchronized (this) {
                        sha = h;
                    }
                } else {
                    parse(u - 1);
                }
            }
        } catch (Throwable t) {
            synchronized (this) {
                failed = true;
                if (error == null) {
                    error = t;
                }
            }
        } finally {
            synchronized (this) {
                done++;
                notifyAll();
            }
        }
        return true;
    }

    private String hash() throws IOException {
        MessageDigest md = ByteLines.sha256();
        byte[] b = new byte[ByteLines.BLOCK_BYTES];
        long total = 0;
        try (InputStream in = file.open()) {
            for (int m; (m = in.read(b)) >= 0; ) {
                md.update(b, 0, m);
                total += m;
                if (total > options.maxBytes()) {
                    throw FileProblems.tooManyBytes(source, total, options.maxBytes());
                }
            }
        }
        if (total != starts[starts.length - 1]) { // it grew or shrank: the blocks hold other bytes
            throw new IOException(source + " changed while it was read (" + total + " bytes, not "
                    + starts[starts.length - 1] + ")");
        }
        return HexFormat.of().formatHex(md.digest());
    }

    private void parse(int block) {
        ByteLines lines = block == 0 ? firstLines
                : ByteLines.range(file, source, starts[block], starts[block + 1], spareBuffers.poll());
        try {
            NumericRows rows = block == 0 ? firstRows : format.later(lines);
            PoseBuffer poses = format.segment();
            double[][] spare = spareColumns.poll();
            if (spare != null) {
                poses.reuse(spare);
            }
            poses.sizeFrom(lines);
            double[] in = new double[8];
            double[] row = new double[8];
            while (format.readBatch(rows, poses, in, row)) {
                // batches, as the whole-file readers
            }
            if (!lines.rangeRead()) { // the file shrank after it was cut (and perhaps hashed)
                throw new IllegalStateException(source + " ended before byte " + starts[block + 1]);
            }
            append(block, poses);
        } finally {
            lines.close();
        }
        spareBuffers.add(lines.buffer());
    }

    /** Keeps a parsed segment, and appends every segment whose predecessors are all appended. */
    private synchronized void append(int block, PoseBuffer segment) {
        segments[block] = segment;
        boolean keep = options.duplicates() == DuplicateTimestamps.KEEP;
        while (frontier < segments.length && segments[frontier] != null && !failed) {
            PoseBuffer s = segments[frontier];
            segments[frontier++] = null;
            int m = s.size();
            if (m == 0) {
                continue;
            }
            double t0 = s.get(0, 0);
            if (n > 0 && !(t0 > lastT) && !(keep && t0 == lastT) || n + (long) m > options.maxPoses()) {
                failed = true; // the whole-file read names the line
                return;
            }
            if (columns == null) {
                columns = new double[format.columns()][(int) Math.min(Math.max(estimate, m), Integer.MAX_VALUE - 8)];
            } else if (n + m > columns[0].length) {
                int grown = (int) Math.min(Math.max((long) n + m, n + (n >> 3) + 64L), Integer.MAX_VALUE - 8);
                for (int c = 0; c < columns.length; c++) {
                    columns[c] = Arrays.copyOf(columns[c], grown);
                }
            }
            for (int c = 0; c < columns.length; c++) {
                System.arraycopy(s.column(c), 0, columns[c], n, m);
            }
            n += m;
            lastT = s.get(0, m - 1);
            spareColumns.add(s.columns());
        }
    }

    private static void close(ByteLines lines) {
        if (lines != null) {
            lines.close();
        }
    }
}
