package org.trajeval.core.io;

import java.io.IOException;
import java.io.InputStream;
import java.nio.ByteBuffer;
import java.util.Arrays;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.atomic.AtomicInteger;

/**
 * One file read in blocks by several threads ({@link ReadThreads}). The file is cut into blocks
 * just after a '\n'; unit k reads block k into a buffer of its own (each byte read from the file
 * once), hands the buffer to the file's SHA-256 in file order ({@link OrderedHash}: so the hash is
 * of exactly the bytes parsed, even if the file is rewritten while it is read), and parses it with
 * the format's own line reader ({@link NumericRows} and its batch loop, so the same values and
 * checks) into a segment of its own; segments are appended to the columns in file order, with the
 * timestamp-order check across each block edge. Only a clean file is read this way: on anything
 * else (a refusal, a quote, a header not in the first block, an order problem at an edge, too many
 * poses, a size that changed while it was read) {@link #read} returns null and the caller reads the
 * file as a whole, which then says what it says today (the first bad line in file order).
 */
final class BlockRead {
    /**
     * Blocks that may be read beyond the last one hashed (about 2 MiB each): bounds the bytes held (8 cost
     * up to 100 MB more peak RSS on a 10^4 + 10^7 pair than the whole read; README, session 11, h11).
     */
    static final int BLOCKS_AHEAD_OF_HASH = 2;

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
    private final OrderedHash hash;
    private byte[] firstBytes;
    private ByteLines firstLines;
    private NumericRows firstRows;

    private volatile boolean failed;
    private Throwable error;
    private int done;
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
        this.units = starts.length - 1; // unit k reads, hashes and parses block k: [starts[k], starts[k + 1])
        this.segments = new PoseBuffer[units];
        this.hash = new OrderedHash(units, BLOCKS_AHEAD_OF_HASH);
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
            if (!threads.inBlocks(size) || size > options.maxBytes()) {
                return null;
            }
            starts = cut(file, size, threads.blockBytes());
        } catch (IOException | RuntimeException e) {
            return null;
        }
        if (starts.length < 3) {
            return null;
        }
        for (int k = 1; k < starts.length; k++) {
            if (starts[k] - starts[k - 1] > ByteLines.MAX_LINE_BYTES) {
                return null; // a line the whole read may refuse as too long
            }
        }
        double perLine = size > ByteLines.SAMPLES * ByteLines.SAMPLE_BYTES
                ? ByteLines.sampleLineLength(file, size) : Double.NaN;
        long estimate = capacityFor(perLine > 0 ? (long) (size / perLine * 1.02) + 64 : 1024, options);
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

    /**
     * @param estimate poses expected in the file (from its size and sampled line length)
     * @return the poses to make room for at first: the estimate, but never more than the pose limit
     *     (a file of mostly blank lines would otherwise get room for a pose per line)
     */
    static long capacityFor(long estimate, ReadOptions options) {
        return Math.min(estimate, options.maxPoses());
    }

    private LoadedTrajectory run(ReadThreads threads) {
        try {
            firstBytes = readBlock(0);
            firstLines = ByteLines.inMemory(firstBytes, blockLength(0), source, true);
            firstRows = format.first(firstLines);
        } catch (IOException | RuntimeException e) {
            return null;
        }
        if (firstRows == null) {
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
            KeptInterrupt.await(this, () -> done >= units);
        }
        if (error instanceof Error e) {
            throw e;
        }
        String sha = hash.digest();
        if (failed || n == 0 || sha == null) {
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
            if (!failed && hash.awaitTurn(u)) {
                parse(u);
            } else {
                // this block is never handed to the hash: a reader waiting for the hash to pass it
                // (one that claimed a later block before the read failed) must not wait for ever
                hash.abandon();
            }
        } catch (Throwable t) {
            synchronized (this) {
                failed = true;
                if (error == null) {
                    error = t;
                }
            }
            hash.abandon();
        } finally {
            synchronized (this) {
                done++;
                notifyAll();
            }
        }
        return true;
    }

    /** Reads, hashes (in file order) and parses block {@code block}. */
    private void parse(int block) throws IOException {
        byte[] bytes = block == 0 ? firstBytes : readBlock(block);
        int length = blockLength(block);
        AtomicInteger users = new AtomicInteger(2); // the hash and the parse
        Runnable release = () -> {
            if (users.decrementAndGet() == 0) {
                spareBuffers.add(bytes);
            }
        };
        hash.offer(block, bytes, length, release);
        try {
            ByteLines lines = block == 0 ? firstLines : ByteLines.inMemory(bytes, length, source, false);
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
            append(block, poses);
        } finally {
            release.run();
        }
    }

    private int blockLength(int block) {
        return (int) (starts[block + 1] - starts[block]);
    }

    /**
     * @return the bytes of block {@code block} from the file, followed by {@link ByteLines#READ_AHEAD}
     *     bytes or more, in a spare buffer when one is big enough
     * @throws IOException also when the file ended before the block's end or goes on past the last
     *     block's (it changed size after it was cut)
     */
    private byte[] readBlock(int block) throws IOException {
        int length = blockLength(block);
        byte[] b = spareBuffers.poll();
        if (b == null || b.length < length + ByteLines.READ_AHEAD) {
            b = new byte[length + (length >> 4) + ByteLines.READ_AHEAD]; // room for a slightly longer next block
        }
        try (InputStream in = file.open(starts[block])) {
            for (int at = 0, m; at < length; at += m) {
                // reads of at most the whole read's size: the JDK's per-thread direct buffer for file reads
                // then fits every read, instead of being freed and allocated anew for each longer block
                m = in.read(b, at, Math.min(ByteLines.BLOCK_BYTES, length - at));
                if (m < 0) {
                    throw new IOException(source + " ended before byte " + starts[block + 1] + " (it shrank while read)");
                }
            }
            if (block == units - 1 && in.read() >= 0) {
                throw new IOException(source + " goes on past byte " + starts[units] + " (it grew while read)");
            }
        }
        return b;
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
                hash.abandon(); // wakes readers waiting for the hash (lock order: this, then the hash)
                return;
            }
            if (columns == null) {
                columns = new double[format.columns()][(int) Math.min(Math.max(estimate, m), Integer.MAX_VALUE - 8)];
            } else if (n + m > columns[0].length) {
                long wanted = capacityFor(Math.max((long) n + m, n + (n >> 3) + 64L), options);
                int grown = (int) Math.min(wanted, Integer.MAX_VALUE - 8);
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
}
