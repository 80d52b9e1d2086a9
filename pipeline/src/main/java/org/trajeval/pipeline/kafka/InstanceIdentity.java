package org.trajeval.pipeline.kafka;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.net.InetAddress;
import java.net.UnknownHostException;
import java.nio.channels.FileChannel;
import java.nio.channels.FileLock;
import java.nio.channels.OverlappingFileLockException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.StandardOpenOption;
import java.security.SecureRandom;
import java.util.HexFormat;
import java.util.Locale;

/**
 * The default instance id, stable across restarts: instances sharing a root each hold one slot
 * of {@code ROOT/kafka-instances/} ({@code slot-N.lock}, locked for the life of the process) and
 * take the id stored beside it ({@code slot-N.id}, host name + random suffix, written once). A
 * restarted instance takes the lowest free slot, so after a crash it gets its old id back; its
 * producer then fences the dead one and the broker aborts the dead one's open transaction at once.
 */
public final class InstanceIdentity implements AutoCloseable {
    /** Most instances that may share one root without an explicit {@code kafka.instance_id}. */
    static final int MAX_SLOTS = 64;

    private final String id;
    private final FileChannel channel;
    private final FileLock lock;

    private InstanceIdentity(String id, FileChannel channel, FileLock lock) {
        this.id = id;
        this.channel = channel;
        this.lock = lock;
    }

    /** @return an explicit id (nothing locked) */
    public static InstanceIdentity fixed(String id) {
        return new InstanceIdentity(id, null, null);
    }

    /**
     * Claims the lowest free slot of {@code dir}.
     *
     * @throws IllegalStateException when all {@link #MAX_SLOTS} slots are held
     */
    public static InstanceIdentity claim(Path dir) {
        try {
            Files.createDirectories(dir);
            for (int slot = 0; slot < MAX_SLOTS; slot++) {
                FileChannel ch = FileChannel.open(dir.resolve("slot-" + slot + ".lock"), StandardOpenOption.CREATE,
                        StandardOpenOption.WRITE);
                FileLock l;
                try {
                    l = ch.tryLock();
                } catch (OverlappingFileLockException e) {
                    l = null; // held by this JVM
                }
                if (l == null) {
                    ch.close();
                    continue;
                }
                return new InstanceIdentity(idOf(dir.resolve("slot-" + slot + ".id")), ch, l);
            }
        } catch (IOException e) {
            throw new UncheckedIOException("could not claim an instance id in " + dir + ": " + e.getMessage(), e);
        }
        throw new IllegalArgumentException("all " + MAX_SLOTS + " instance slots in " + dir
                + " are held by running instances; set kafka.instance_id explicitly");
    }

    private static String idOf(Path file) throws IOException {
        if (Files.exists(file)) {
            String s = Files.readString(file, StandardCharsets.UTF_8).trim();
            if (!s.isEmpty()) {
                return s;
            }
        }
        byte[] r = new byte[4];
        new SecureRandom().nextBytes(r);
        String id = host() + "-" + HexFormat.of().formatHex(r);
        Path tmp = file.resolveSibling(file.getFileName() + ".tmp");
        Files.writeString(tmp, id + "\n", StandardCharsets.UTF_8);
        try (FileChannel c = FileChannel.open(tmp, StandardOpenOption.WRITE)) {
            c.force(true);
        }
        Files.move(tmp, file, StandardCopyOption.ATOMIC_MOVE, StandardCopyOption.REPLACE_EXISTING);
        return id;
    }

    private static String host() {
        String h;
        try {
            h = InetAddress.getLocalHost().getHostName();
        } catch (UnknownHostException e) {
            h = "host";
        }
        String clean = h.toLowerCase(Locale.ROOT).replaceAll("[^a-z0-9.-]", "");
        return clean.isEmpty() ? "host" : clean;
    }

    /** @return the instance id */
    public String id() {
        return id;
    }

    /** Releases the slot. */
    @Override
    public void close() {
        try {
            if (lock != null) {
                lock.release();
            }
            if (channel != null) {
                channel.close();
            }
        } catch (IOException ignored) {
            // the lock goes with the process anyway
        }
    }
}
