package org.trajeval.pipeline.dir;

import java.io.IOException;
import java.nio.channels.FileChannel;
import java.nio.channels.FileLock;
import java.nio.channels.OverlappingFileLockException;
import java.nio.file.AtomicMoveNotSupportedException;
import java.nio.file.DirectoryNotEmptyException;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.StandardOpenOption;
import org.trajeval.pipeline.EnvironmentException;

/**
 * A bundle's folder in processing/, {@code processing/SLOT/}, holding the bundle's payload and
 * marker and a {@code .lock} file this process keeps locked while it works on the bundle. The
 * slot appears by one atomic rename of a prepared folder (so it is never seen without its lock);
 * a process that dies releases the lock, and the next one to start resumes the slot.
 */
final class Slot implements AutoCloseable {
    static final String LOCK = ".lock";
    private static final String CLAIMING = ".claim-";

    private final Path dir;
    private final BundleUnit unit;
    private final FileChannel lockChannel;
    private final FileLock lock;

    private Slot(Path dir, BundleUnit unit, FileChannel lockChannel, FileLock lock) {
        this.dir = dir;
        this.unit = unit;
        this.lockChannel = lockChannel;
        this.lock = lock;
    }

    Path dir() {
        return dir;
    }

    BundleUnit unit() {
        return unit;
    }

    /**
     * Claims a bundle: prepares a locked folder, renames it to processing/SLOT (fails if the
     * slot exists: someone else has the bundle), then moves the payload and the marker in.
     *
     * @param names the names of the prepared folders ({@code .claim-NAME}), unique among processes
     *
     * @return the slot, or {@code null} when another worker got the bundle first
     */
    static Slot claim(Path incoming, Path processing, BundleUnit unit, ClaimNames names) throws IOException {
        Path tmp = processing.resolve(CLAIMING + names.next());
        Files.createDirectory(tmp);
        FileChannel ch = FileChannel.open(tmp.resolve(LOCK), StandardOpenOption.CREATE_NEW, StandardOpenOption.WRITE);
        FileLock lock = ch.lock();
        Path dir = processing.resolve(unit.slotName());
        try {
            Files.move(tmp, dir, StandardCopyOption.ATOMIC_MOVE);
        } catch (IOException e) {
            // rename(2) onto an existing slot fails with ENOTEMPTY, which the JDK reports as a plain
            // FileSystemException: any failure while the slot exists is a lost race, which is normal
            lock.release();
            ch.close();
            deleteTree(tmp);
            if (e instanceof FileAlreadyExistsException || e instanceof DirectoryNotEmptyException
                    || Files.exists(dir, LinkOption.NOFOLLOW_LINKS) || "Directory not empty".equals(
                            e instanceof java.nio.file.FileSystemException fs ? fs.getReason() : null)
                    || unit.payloadNames().stream().noneMatch(n -> Files.exists(incoming.resolve(n),
                            LinkOption.NOFOLLOW_LINKS))) {
                return null; // the other claimer may even have finished and moved the slot on already
            }
            throw e;
        }
        Slot slot = new Slot(dir, unit, ch, lock);
        if (!slot.collect(incoming)) {
            slot.abandon();
            return null;
        }
        return slot;
    }

    /**
     * Takes over a slot left by a process that died (its lock is free).
     *
     * @return the slot, or {@code null} when a live process holds it (or it is a claim in progress)
     */
    static Slot resume(Path incoming, Path dir) throws IOException {
        String name = dir.getFileName().toString();
        if (!Files.isDirectory(dir, LinkOption.NOFOLLOW_LINKS)) {
            return null;
        }
        if (name.startsWith(CLAIMING) && Files.getLastModifiedTime(dir).toMillis()
                > System.currentTimeMillis() - 60_000) {
            return null; // a claim another instance may be making right now (its lock may not be taken yet)
        }
        FileChannel ch;
        try {
            ch = FileChannel.open(dir.resolve(LOCK), StandardOpenOption.CREATE, StandardOpenOption.WRITE);
        } catch (NoSuchFileException e) {
            return null;
        }
        FileLock lock;
        try {
            lock = ch.tryLock();
        } catch (OverlappingFileLockException e) {
            lock = null;
        }
        if (lock == null) {
            ch.close();
            return null;
        }
        if (name.startsWith(CLAIMING)) {
            // a claim that died before its rename: nothing of a bundle is inside
            lock.release();
            ch.close();
            deleteTree(dir);
            return null;
        }
        Slot slot = new Slot(dir, BundleUnit.ofSlot(name), ch, lock);
        slot.collect(incoming);
        return slot;
    }

    /** Moves the bundle's remaining pieces from incoming/ into the slot; @return whether the payload is here */
    private boolean collect(Path incoming) throws IOException {
        for (String part : unit.allNames()) {
            Path from = incoming.resolve(part);
            Path to = dir.resolve(part);
            if (Files.exists(to, LinkOption.NOFOLLOW_LINKS)) {
                continue;
            }
            try {
                Files.move(from, to, StandardCopyOption.ATOMIC_MOVE);
            } catch (NoSuchFileException e) {
                // not there: another worker took it, or (a marker) it never existed
            } catch (AtomicMoveNotSupportedException e) {
                throw new IOException("incoming/ and processing/ must be on one file system: " + e.getMessage(), e);
            }
        }
        for (String part : unit.payloadNames()) {
            if (Files.exists(dir.resolve(part), LinkOption.NOFOLLOW_LINKS)) {
                return true;
            }
        }
        return false;
    }

    /** Releases an empty slot (the bundle was taken by someone else). */
    private void abandon() throws IOException {
        close();
        deleteTree(dir);
    }

    /**
     * Moves the whole slot to {@code target} (done/ or failed/) under the first free name
     * {@code SLOT}, {@code SLOT.2}, ...; the name must be chosen first with {@link #destination}.
     */
    void moveTo(Path target) {
        try {
            Files.move(dir, target, StandardCopyOption.ATOMIC_MOVE);
        } catch (IOException e) {
            throw new EnvironmentException("move", dir, e);
        } finally {
            close();
        }
        try {
            Files.deleteIfExists(target.resolve(LOCK));
        } catch (IOException e) {
            // an empty lock file left in done/ or failed/ harms nothing
        }
    }

    /** @return the first name {@code SLOT}, {@code SLOT.2}, ... free in {@code folder} (with its .error.json) */
    Path destination(Path folder) {
        String base = dir.getFileName().toString();
        Path p = folder.resolve(base);
        for (int k = 2; Files.exists(p, LinkOption.NOFOLLOW_LINKS)
                || Files.exists(folder.resolve(p.getFileName() + ".error.json"), LinkOption.NOFOLLOW_LINKS); k++) {
            p = folder.resolve(base + "." + k);
        }
        return p;
    }

    @Override
    public void close() {
        try {
            if (lock.isValid()) {
                lock.release();
            }
            lockChannel.close();
        } catch (IOException ignored) {
            // the lock goes with the channel
        }
    }

    static void deleteTree(Path root) throws IOException {
        if (!Files.exists(root, LinkOption.NOFOLLOW_LINKS)) {
            return;
        }
        try (var s = Files.walk(root)) {
            for (Path p : (Iterable<Path>) s.sorted(java.util.Comparator.reverseOrder())::iterator) {
                Files.deleteIfExists(p);
            }
        }
    }
}
