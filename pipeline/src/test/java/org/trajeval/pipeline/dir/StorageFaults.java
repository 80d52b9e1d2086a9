package org.trajeval.pipeline.dir;

import java.io.IOException;
import java.io.OutputStream;
import java.io.UncheckedIOException;
import java.nio.file.FileSystemException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;
import java.util.function.BiConsumer;

/**
 * Real storage faults where this machine allows them, else the same fault injected at the write
 * layer: a small tmpfs filled to the last byte (disk full) or a tmpfs remounted read-only. Mounting
 * needs root (and a kernel that lets the container mount); CI may have neither, so each test runs
 * either way and says which in its output.
 */
final class StorageFaults {
    private StorageFaults() {
    }

    /** @return whether {@code dir} now has a tmpfs of {@code bytes} mounted on it */
    static boolean mountTmpfs(Path dir, long bytes) {
        return run("mount", "-t", "tmpfs", "-o", "size=" + bytes, "tmpfs", dir.toString());
    }

    /** @return whether the tmpfs on {@code dir} is now read-only */
    static boolean remountReadOnly(Path dir) {
        return run("mount", "-o", "remount,ro", dir.toString());
    }

    static void unmount(Path dir) {
        run("umount", "-l", dir.toString());
    }

    /** Fills the file system of {@code dir} until a write fails with "No space left on device". */
    static void fill(Path dir) throws IOException {
        byte[] block = new byte[4096];
        try (OutputStream o = Files.newOutputStream(dir.resolve("filler"))) {
            for (int i = 0; i < 1 << 20; i++) {
                o.write(block);
                o.flush();
            }
        } catch (IOException full) {
            // the disk is full, as wanted
        }
        for (int i = 0; ; i++) {
            try {
                Files.write(dir.resolve("filler-" + i), new byte[1]);
            } catch (IOException full) {
                return; // not even one byte (one page) left
            }
        }
    }

    /** @return a report writer that fails as the operating system does with {@code reason} */
    static BiConsumer<Path, String> failingWriter(String reason) {
        return (file, text) -> {
            throw new UncheckedIOException("could not write " + file,
                    new FileSystemException(file.toString(), null, reason));
        };
    }

    private static boolean run(String... command) {
        try {
            Process p = new ProcessBuilder(command).redirectErrorStream(true).start();
            p.getInputStream().readAllBytes();
            return p.waitFor(30, TimeUnit.SECONDS) && p.exitValue() == 0;
        } catch (IOException e) {
            return false;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return false;
        }
    }
}
