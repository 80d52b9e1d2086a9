package org.trajeval.pipeline.ledger;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.ByteBuffer;
import java.nio.channels.FileChannel;
import java.nio.channels.FileLock;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.locks.ReentrantLock;
import java.util.function.Function;
import java.util.function.ToLongFunction;

/**
 * The persistent record of every reported run: an append-only text file, one line per report
 * ({@code R <tab> run id <tab> content hash <tab> version <tab> time ms <tab> source}), fsync'd
 * before a report counts as done. Keyed by run id and content hash: a run is reported once
 * across restarts, and a changed run gets the next version.
 *
 * <p>Several processes may share one ledger file: every {@link #locked} section holds an
 * exclusive file lock (and an in-process lock), first reads what other processes appended, and
 * only then decides. A line cut short by a crash is ignored (and cut off on the next open).
 *
 * <p>Memory: the ledger keeps, per reported version, only where its line lies in the file, its
 * version and its content hash's {@code hashCode}, in primitive arrays found by a 64-bit key of the run
 * id ({@link RunIndex}, about 40 B per run), not the parsed line (about 380 B) nor the run id: a service
 * that has reported 10^5 runs holds about 4 MB for them. A key or hash code that matches is confirmed by
 * reading that line back (lines before the read position are complete and never change) and comparing
 * the run id and the full hash.
 */
public final class Ledger implements AutoCloseable {
    private final Path file;
    private final FileChannel channel;
    private final ReentrantLock inProcess = new ReentrantLock();
    // written only under the in-process lock, after its line is in the file; read without it by the hints
    // (probablyReported, probableLatestVersion: a worker asks while another one commits)
    private final RunIndex byRun;
    private long readPosition;

    private Ledger(Path file, FileChannel channel, ToLongFunction<String> runKey) {
        this.file = file;
        this.channel = channel;
        this.byRun = new RunIndex(runKey, this::lineAt);
    }

    /** Opens (or creates) the ledger file and loads it. */
    public static Ledger open(Path file) {
        return open(file, RunIndex::key);
    }

    /** {@link #open(Path)} with another 64-bit key of the run id (tests: keys that collide). */
    static Ledger open(Path file, ToLongFunction<String> runKey) {
        try {
            Files.createDirectories(file.toAbsolutePath().getParent());
            FileChannel ch = FileChannel.open(file, StandardOpenOption.CREATE, StandardOpenOption.READ,
                    StandardOpenOption.WRITE);
            Ledger l = new Ledger(file, ch, runKey);
            l.locked(view -> {
                l.cutPartialTail();
                return null;
            });
            return l;
        } catch (IOException e) {
            throw new UncheckedIOException("could not open the ledger " + file + ": " + e.getMessage(), e);
        }
    }

    /** What a {@link #locked} section may do: look up and append, with the ledger up to date. */
    public interface View {
        /** @return the entry of this run id and content hash, if it was reported */
        Optional<LedgerEntry> find(String runId, String contentHash);

        /** @return the highest version reported for the run id, 0 when none */
        int latestVersion(String runId);

        /** Appends an entry and fsyncs the file. */
        default void append(LedgerEntry entry) {
            appendAll(List.of(entry));
        }

        /**
         * Appends entries in order with one write and one fsync (a group commit): when it returns, every
         * line is durable; when it throws, none counts in this process (a line cut short is cut off at the
         * next open; complete lines written before the failure are read back by the next {@link #locked}).
         */
        void appendAll(List<LedgerEntry> entries);
    }

    /**
     * Runs {@code action} holding the ledger's exclusive lock, after reading every line other
     * processes appended.
     */
    public <T> T locked(Function<View, T> action) {
        inProcess.lock();
        try (FileLock ignored = channel.lock()) {
            catchUp();
            return action.apply(view);
        } catch (IOException e) {
            throw new UncheckedIOException("ledger " + file + ": " + e.getMessage(), e);
        } finally {
            inProcess.unlock();
        }
    }

    /**
     * @return the highest version reported for the run id as far as this process has read, 0 when none
     *     (no lock: a guess before writing a report; {@link #locked} decides)
     */
    public int probableLatestVersion(String runId) {
        return view.latestVersion(runId);
    }

    /**
     * @return whether this run id and content were reported, as far as this process has read
     *     (no lock: a fast check before scoring; {@link #locked} decides)
     */
    public boolean probablyReported(String runId, String contentHash) {
        return byRun.find(runId, contentHash).isPresent();
    }

    /** @return every entry read so far, in file order (read back from the file) */
    public List<LedgerEntry> entries() {
        inProcess.lock();
        try {
            List<LedgerEntry> all = new ArrayList<>();
            byte[] bytes = readRange(0, readPosition);
            int lineStart = 0;
            for (int i = 0; i < bytes.length; i++) {
                if (bytes[i] == '\n') {
                    LedgerEntry e = LedgerEntry.parse(new String(bytes, lineStart, i - lineStart, StandardCharsets.UTF_8));
                    if (e != null) {
                        all.add(e);
                    }
                    lineStart = i + 1;
                }
            }
            return all;
        } catch (IOException e) {
            throw new UncheckedIOException("could not read the ledger " + file + ": " + e.getMessage(), e);
        } finally {
            inProcess.unlock();
        }
    }

    private final View view = new View() {
        @Override
        public Optional<LedgerEntry> find(String runId, String contentHash) {
            return byRun.find(runId, contentHash);
        }

        @Override
        public int latestVersion(String runId) {
            return byRun.latestVersion(runId);
        }

        @Override
        public void appendAll(List<LedgerEntry> entries) {
            if (entries.isEmpty()) {
                return;
            }
            try {
                byte[][] lines = new byte[entries.size()][];
                int total = 0;
                for (int i = 0; i < lines.length; i++) {
                    lines[i] = entries.get(i).toLine().getBytes(StandardCharsets.UTF_8);
                    total += lines[i].length;
                }
                ByteBuffer b = ByteBuffer.allocate(total);
                for (byte[] line : lines) {
                    b.put(line);
                }
                b.flip();
                long start = channel.size();
                long pos = start;
                while (b.hasRemaining()) {
                    pos += channel.write(b, pos);
                }
                channel.force(false);
                readPosition = pos;
                long offset = start;
                for (int i = 0; i < lines.length; i++) {
                    byRun.add(entries.get(i), offset, lines[i].length - 1);
                    offset += lines[i].length;
                }
            } catch (IOException e) {
                throw new UncheckedIOException("could not append to the ledger " + file + ": " + e.getMessage(), e);
            }
        }
    };

    /** @return the entry of the complete line at {@code offset}, {@code length} bytes without its newline */
    private LedgerEntry lineAt(long offset, int length) {
        try {
            return LedgerEntry.parse(new String(readRange(offset, offset + length), StandardCharsets.UTF_8));
        } catch (IOException e) {
            throw new UncheckedIOException("could not read the ledger " + file + ": " + e.getMessage(), e);
        }
    }

    private byte[] readRange(long from, long to) throws IOException {
        ByteBuffer buf = ByteBuffer.allocate(Math.toIntExact(to - from));
        long pos = from;
        while (buf.hasRemaining()) {
            int n = channel.read(buf, pos);
            if (n <= 0) {
                throw new IOException("the ledger is shorter than read before (" + pos + " of " + to + " bytes)");
            }
            pos += n;
        }
        return buf.array();
    }

    /** Reads complete lines appended since the last read (a line without its newline waits). */
    private void catchUp() throws IOException {
        long size = channel.size();
        if (size <= readPosition) {
            return;
        }
        ByteBuffer buf = ByteBuffer.allocate(Math.toIntExact(size - readPosition));
        long pos = readPosition;
        while (buf.hasRemaining()) {
            int n = channel.read(buf, pos);
            if (n <= 0) {
                break;
            }
            pos += n;
        }
        byte[] bytes = buf.array();
        int lineStart = 0;
        for (int i = 0; i < buf.position(); i++) {
            if (bytes[i] == '\n') {
                LedgerEntry e = LedgerEntry.parse(new String(bytes, lineStart, i - lineStart, StandardCharsets.UTF_8));
                if (e != null) {
                    byRun.add(e, readPosition + lineStart, i - lineStart);
                }
                lineStart = i + 1;
            }
        }
        readPosition += lineStart;
    }

    /** A crash during an append can leave a line without its newline: cut it, it never counted. */
    private void cutPartialTail() {
        try {
            if (channel.size() > readPosition) {
                channel.truncate(readPosition);
                channel.force(true);
            }
        } catch (IOException e) {
            throw new UncheckedIOException("could not repair the ledger " + file + ": " + e.getMessage(), e);
        }
    }

    @Override
    public void close() {
        try {
            channel.close();
        } catch (IOException ignored) {
            // closing a read/write channel after fsync: nothing left to lose
        }
    }
}
