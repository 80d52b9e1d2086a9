package org.trajeval.core.io;

import java.security.MessageDigest;
import java.util.HexFormat;

/**
 * The SHA-256 of a file read in blocks ({@link BlockRead}), fed with the very buffers the blocks are
 * parsed from, in file order: a block's bytes are offered once read; whichever thread offers the next
 * block in order hashes it, then every block after it already offered. So the hash is of exactly the
 * bytes parsed, each byte read from the file once. At most {@code window} blocks are read ahead of
 * the hash: a reader of a later block waits ({@link #awaitTurn}) rather than holding more memory.
 */
final class OrderedHash {
    private final MessageDigest sha = ByteLines.sha256();
    private final Held[] offered;
    private final int window;
    /** Blocks hashed: the next one in file order to hash. */
    private int hashed;
    private boolean hashing;
    private boolean abandoned;

    /** A block's bytes until they are hashed. */
    private record Held(byte[] bytes, int length, Runnable whenHashed) {
    }

    /**
     * @param blocks blocks in the file
     * @param window blocks that may be read beyond the last one hashed (at least 1)
     */
    OrderedHash(int blocks, int window) {
        this.offered = new Held[blocks];
        this.window = Math.max(1, window);
    }

    /**
     * Waits until block {@code block} may be read: fewer than {@code window} blocks before it are
     * unhashed. The next block to hash never waits, so the hash always progresses. An interrupt is kept.
     *
     * @return false if the hash was abandoned (the read failed elsewhere)
     */
    synchronized boolean awaitTurn(int block) {
        KeptInterrupt.await(this, () -> block < hashed + window || abandoned);
        return !abandoned;
    }

    /**
     * Hands over block {@code block}'s bytes {@code bytes[0, length)}; if it is the next in order and no
     * other thread is hashing, hashes it here, then every block after it offered meanwhile. The caller
     * must not change the bytes until {@code whenHashed} has run (on whichever thread hashed them).
     */
    void offer(int block, byte[] bytes, int length, Runnable whenHashed) {
        synchronized (this) {
            offered[block] = new Held(bytes, length, whenHashed);
            if (hashing || block != hashed || abandoned) {
                return; // the thread hashing now, or the one offering the next block, takes it
            }
            hashing = true;
        }
        while (true) {
            Held h;
            synchronized (this) {
                h = hashed < offered.length ? offered[hashed] : null;
                if (h == null || abandoned) {
                    hashing = false;
                    return;
                }
                offered[hashed] = null;
            }
            sha.update(h.bytes(), 0, h.length());
            h.whenHashed().run();
            synchronized (this) {
                hashed++;
                notifyAll();
            }
        }
    }

    /** Stops hashing and wakes every waiting reader (a block failed: the file is read as a whole). */
    synchronized void abandon() {
        abandoned = true;
        notifyAll();
    }

    /** @return the SHA-256 of every block in order, lower-case hex, or null if not every block was hashed */
    synchronized String digest() {
        return hashed == offered.length && !abandoned ? HexFormat.of().formatHex(sha.digest()) : null;
    }
}
