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
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.locks.ReentrantLock;
import java.util.function.Function;

/**
 * The persistent record of every reported run: an append-only text file, one line per report
 * ({@code R <tab> run id <tab> content hash <tab> version <tab> time ms <tab> source}), fsync'd
 * before a report counts as done. Keyed by run id and content hash: a run is reported once
 * across restarts, and a changed run gets the next version.
 *
 * <p>Several processes may share one ledger file: every {@link #locked} section holds an
 * exclusive file lock (and an in-process lock), first reads what other processes appended, and
 * only then decides. A line cut short by a crash is ignored (and cut off on the next open).
 */
public final class Ledger implements AutoCloseable {
    private final Path file;
    private final FileChannel channel;
    private final ReentrantLock inProcess = new ReentrantLock();
    private final Map<String, List<LedgerEntry>> byRun = new HashMap<>();
    private long readPosition;

    private Ledger(Path file, FileChannel channel) {
        this.file = file;
        this.channel = channel;
    }

    /** Opens (or creates) the ledger file and loads it. */
    public static Ledger open(Path file) {
        try {
            Files.createDirectories(file.toAbsolutePath().getParent());
            FileChannel ch = FileChannel.open(file, StandardOpenOption.CREATE, StandardOpenOption.READ,
                    StandardOpenOption.WRITE);
            Ledger l = new Ledger(file, ch);
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
        void append(LedgerEntry entry);
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
     * @return whether this run id and content were reported, as far as this process has read
     *     (no lock: a fast check before scoring; {@link #locked} decides)
     */
    public boolean probablyReported(String runId, String contentHash) {
        inProcess.lock();
        try {
            return lookup(runId, contentHash).isPresent();
        } finally {
            inProcess.unlock();
        }
    }

    /** @return every entry read so far (a copy), in file order per run */
    public List<LedgerEntry> entries() {
        inProcess.lock();
        try {
            List<LedgerEntry> all = new ArrayList<>();
            byRun.values().forEach(all::addAll);
            return all;
        } finally {
            inProcess.unlock();
        }
    }

    private final View view = new View() {
        @Override
        public Optional<LedgerEntry> find(String runId, String contentHash) {
            return lookup(runId, contentHash);
        }

        @Override
        public int latestVersion(String runId) {
            return byRun.getOrDefault(runId, List.of()).stream().mapToInt(LedgerEntry::version).max().orElse(0);
        }

        @Override
        public void append(LedgerEntry entry) {
            try {
                ByteBuffer b = ByteBuffer.wrap(entry.toLine().getBytes(StandardCharsets.UTF_8));
                long pos = channel.size();
                while (b.hasRemaining()) {
                    pos += channel.write(b, pos);
                }
                channel.force(false);
                readPosition = pos;
                byRun.computeIfAbsent(entry.runId(), k -> new ArrayList<>()).add(entry);
            } catch (IOException e) {
                throw new UncheckedIOException("could not append to the ledger " + file + ": " + e.getMessage(), e);
            }
        }
    };

    private Optional<LedgerEntry> lookup(String runId, String contentHash) {
        for (LedgerEntry e : byRun.getOrDefault(runId, List.of())) {
            if (e.contentHash().equals(contentHash)) {
                return Optional.of(e);
            }
        }
        return Optional.empty();
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
                    byRun.computeIfAbsent(e.runId(), k -> new ArrayList<>()).add(e);
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
