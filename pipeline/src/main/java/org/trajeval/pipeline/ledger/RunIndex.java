package org.trajeval.pipeline.ledger;

import java.lang.invoke.MethodHandles;
import java.lang.invoke.VarHandle;
import java.util.Arrays;
import java.util.Optional;
import java.util.function.ToLongFunction;

/**
 * The ledger's in-memory index, in primitive arrays: per reported version, where its line lies in the
 * file, its version, its content hash's {@code hashCode} and the run's previous version; found through an
 * open-addressing table keyed by a 64-bit hash of the run id. Nothing but the line says which run id or
 * hash an entry is: every key match is confirmed by reading the line back and comparing the run id (and a
 * lookup compares the whole content hash), so two run ids with the same key stay two runs.
 *
 * <p>Memory: 32 B per version (four {@code long}s in pages of {@value #PAGE} entries) plus a table slot
 * ({@code int}, at most 3/4 full) per run: about 37-43 B per run, against about 127 B for a
 * {@code ConcurrentHashMap<String, record>} (node, record, the run id's {@code String} and bytes).
 *
 * <p>Threads: one writer at a time ({@link #add}, under the ledger's lock); readers ({@link #find},
 * {@link #latestVersion}) need no lock. An entry's words are written before its table slot is set with
 * release semantics, and slots are read with acquire semantics, so a reader that sees an entry sees its
 * words, its page and every earlier version it points to. A grown table is filled before it is published
 * through a volatile field; a reader still holding the old one sees the index as it was (a hint).
 */
final class RunIndex {
    /** Reads back the line at {@code offset} ({@code length} bytes, without its newline); null if it does not parse. */
    interface Lines {
        LedgerEntry at(long offset, int length);
    }

    private static final int PAGE_BITS = 10;
    private static final int PAGE = 1 << PAGE_BITS;
    // words of one entry: the run id's key, the line's offset, length << 32 | version, hash code << 32 | earlier + 1
    private static final int WORDS = 4;
    private static final VarHandle SLOT = MethodHandles.arrayElementVarHandle(int[].class);

    private final ToLongFunction<String> keyOf;
    private final Lines lines;
    // plain fields, written only by the writer before the release of a slot that makes them reachable
    private long[][] pages = new long[16][];
    private int entries;
    private int runs;
    // slot = 1 + the entry index of one run's latest version, 0 when free
    private volatile int[] table = new int[1024];

    RunIndex(ToLongFunction<String> keyOf, Lines lines) {
        this.keyOf = keyOf;
        this.lines = lines;
    }

    /**
     * The default key: FNV-1a over the run id's UTF-16 chars, then MurmurHash3's 64-bit finaliser so every
     * bit of the key depends on every char (the table uses its low bits).
     */
    static long key(String runId) {
        long h = 0xcbf29ce484222325L;
        for (int i = 0; i < runId.length(); i++) {
            h = (h ^ runId.charAt(i)) * 0x100000001b3L;
        }
        h ^= h >>> 33;
        h *= 0xff51afd7ed558ccdL;
        h ^= h >>> 33;
        h *= 0xc4ceb9fe1a85ec53L;
        return h ^ (h >>> 33);
    }

    /** Indexes a version whose complete line lies at {@code offset} ({@code length} bytes, no newline). Writer only. */
    void add(LedgerEntry e, long offset, int length) {
        long key = keyOf.applyAsLong(e.runId());
        int[] t = table;
        Chain chain = chainOf(t, key, e.runId());
        int slot = chain.slot();
        int earlier = chain.latest();
        if (earlier < 0 && 4L * (runs + 1) > 3L * t.length) {
            t = grow(t);
            slot = chainOf(t, key, e.runId()).slot();
        }
        int n = entries;
        if ((n >>> PAGE_BITS) == pages.length) {
            pages = Arrays.copyOf(pages, 2 * pages.length);
        }
        if ((n & (PAGE - 1)) == 0) {
            pages[n >>> PAGE_BITS] = new long[PAGE * WORDS];
        }
        long[] p = pages[n >>> PAGE_BITS];
        int w = (n & (PAGE - 1)) * WORDS;
        p[w] = key;
        p[w + 1] = offset;
        p[w + 2] = (long) length << 32 | (e.version() & 0xffffffffL);
        p[w + 3] = (long) e.contentHash().hashCode() << 32 | (earlier + 1);
        entries = n + 1;
        if (earlier < 0) {
            runs++;
        }
        SLOT.setRelease(t, slot, n + 1);
    }

    /** @return the highest version indexed for the run id, 0 when none */
    int latestVersion(String runId) {
        int v = 0;
        int[] t = table;
        for (int e = chainOf(t, keyOf.applyAsLong(runId), runId).latest(); e >= 0; e = earlier(e)) {
            v = Math.max(v, version(e));
        }
        return v;
    }

    /** @return the entry of this run id and content hash, read back from its line, if indexed */
    Optional<LedgerEntry> find(String runId, String contentHash) {
        int h = contentHash.hashCode();
        int[] t = table;
        Chain chain = chainOf(t, keyOf.applyAsLong(runId), runId);
        for (int e = chain.latest(); e >= 0; e = earlier(e)) {
            if (hashCode(e) == h) {
                // the latest version's line was read to confirm the run id: not read again
                LedgerEntry line = e == chain.latest() ? chain.latestLine() : lineOf(e);
                if (line != null && line.runId().equals(runId) && line.contentHash().equals(contentHash)) {
                    return Optional.of(line);
                }
            }
        }
        return Optional.empty();
    }

    /**
     * A run's chain as one probe of the table found it: its slot (or the free slot where it would go), the
     * entry index of its latest version (-1 when none) and that version's line, read to confirm the run id.
     */
    private record Chain(int slot, int latest, LedgerEntry latestLine) {
    }

    /** @return the run id's chain in table {@code t} (linear probing from the key) */
    private Chain chainOf(int[] t, long key, String runId) {
        int mask = t.length - 1;
        for (int i = (int) key & mask;; i = (i + 1) & mask) {
            int e = (int) SLOT.getAcquire(t, i) - 1;
            if (e < 0) {
                return new Chain(i, -1, null);
            }
            if (word(e, 0) == key) {
                LedgerEntry line = lineOf(e);
                if (line != null && line.runId().equals(runId)) {
                    return new Chain(i, e, line);
                }
            }
        }
    }

    /** Rehashes every chain head into a table twice the size and publishes it. Writer only. */
    private int[] grow(int[] old) {
        int[] t = new int[2 * old.length];
        int mask = t.length - 1;
        for (int s : old) {
            if (s != 0) {
                int i = (int) word(s - 1, 0) & mask;
                while (t[i] != 0) {
                    i = (i + 1) & mask;
                }
                t[i] = s;
            }
        }
        table = t;
        return t;
    }

    private LedgerEntry lineOf(int e) {
        return lines.at(word(e, 1), (int) (word(e, 2) >>> 32));
    }

    private int version(int e) {
        return (int) word(e, 2);
    }

    private int hashCode(int e) {
        return (int) (word(e, 3) >>> 32);
    }

    private int earlier(int e) {
        return (int) word(e, 3) - 1;
    }

    private long word(int e, int i) {
        return pages[e >>> PAGE_BITS][(e & (PAGE - 1)) * WORDS + i];
    }
}
