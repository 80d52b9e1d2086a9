package org.trajeval.core.io;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.Executor;
import java.util.concurrent.RejectedExecutionException;

/**
 * The threads that read trajectory files. With more than one, a big CSV or TUM file is cut into
 * blocks at line boundaries ({@link BlockRead}), and every thread that is free (an idle pool
 * thread, or a reader whose own file has no unparsed block left) hashes or parses the next
 * unclaimed part of any file still being read. One object is shared by the files read at once
 * (the two files of a pair), so the thread of a small file helps with the big one.
 */
public final class ReadThreads {
    /** Bytes of one block (nominal; a block ends at the first line end at or after it). */
    static final long BLOCK_BYTES = 2L << 20;
    /** One thread: every file is read as a whole, on the calling thread. */
    public static final ReadThreads ONE = new ReadThreads(null, 1);

    private final Executor helpers;
    private final int threads;
    private final long blockBytes;
    private final boolean secondBigger;
    private final CopyOnWriteArrayList<BlockRead> active = new CopyOnWriteArrayList<>();

    /**
     * @param helpers runs the helping tasks (at most {@code threads - 1} per file read)
     * @param threads threads in all, the calling one included
     */
    public ReadThreads(Executor helpers, int threads) {
        this(helpers, threads, BLOCK_BYTES);
    }

    /**
     * The threads for reading a pair at once, one file per thread: blocks only where a thread would
     * otherwise idle, that is with more threads than files or one file at least twice the size of
     * the other (an equal 10^7 pair on two threads, planar or 3D, is no faster in blocks, even with
     * each byte read once since session 11: both threads are busy anyway, and blocks cost a copy of
     * each segment into the columns and more CPU; README, session 11, h11).
     *
     * @param threads threads in all, the calling one included
     * @return {@link #ONE} when blocks would not pay, or a file's size cannot be told
     */
    public static ReadThreads forPair(Executor helpers, int threads, Path a, Path b) {
        if (threads < 2) {
            return ONE;
        }
        long x;
        long y;
        try {
            x = Files.size(a);
            y = Files.size(b);
        } catch (IOException | RuntimeException e) {
            return threads > 2 ? new ReadThreads(helpers, threads) : ONE; // not a plain file (a bag topic, say)
        }
        if (threads == 2 && Math.max(x, y) < 2 * Math.min(x, y)) {
            return ONE;
        }
        return new ReadThreads(helpers, threads, BLOCK_BYTES, y > x);
    }

    /**
     * @return true if the second file of the pair ({@link #forPair}'s {@code b}) is the bigger one: the
     *     caller should read it on its own thread and hand the smaller one to the pool, whose thread then
     *     runs its queued turn at the bigger file's blocks once the smaller is read (the other way round,
     *     that turn waits behind the bigger file itself, and one thread hashes and then parses every block)
     */
    public boolean readSecondHere() {
        return secondBigger;
    }

    /** Threads that cut files into blocks of {@code blockBytes} (tests force small blocks). */
    ReadThreads(Executor helpers, int threads, long blockBytes) {
        this(helpers, threads, blockBytes, false);
    }

    private ReadThreads(Executor helpers, int threads, long blockBytes, boolean secondBigger) {
        if (threads > 1 && helpers == null) {
            throw new IllegalArgumentException("more than one thread needs an executor");
        }
        this.helpers = helpers;
        this.threads = Math.max(1, threads);
        this.blockBytes = blockBytes;
        this.secondBigger = secondBigger;
    }

    /** @return true if a file of {@code size} bytes is read in blocks (at least two blocks, two threads) */
    boolean inBlocks(long size) {
        return threads > 1 && size >= 2 * blockBytes;
    }

    long blockBytes() {
        return blockBytes;
    }

    /** Makes {@code read}'s units available to every thread, and asks the pool for helpers. */
    void start(BlockRead read) {
        active.add(read);
        for (int i = 1; i < threads; i++) {
            try {
                helpers.execute(this::helpWhileWork);
            } catch (RejectedExecutionException e) {
                return; // a pool shutting down: the reading threads do every unit themselves
            }
        }
    }

    /** Withdraws a read whose units are all claimed. */
    void finished(BlockRead read) {
        active.remove(read);
    }

    /** Runs unclaimed units of any file being read until none is left. */
    void helpWhileWork() {
        while (helpOnce()) {
            // one unit per pass: the list of files may change between units
        }
    }

    /** @return true if a unit of some file was run */
    private boolean helpOnce() {
        for (BlockRead r : active) {
            if (r.runOneUnit()) {
                return true;
            }
        }
        return false;
    }
}
