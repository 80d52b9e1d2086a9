package org.trajeval.core.io;

import java.io.IOException;
import java.io.InputStream;
import java.nio.ByteBuffer;
import java.nio.channels.FileChannel;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Objects;

/** A trajectory file on a local file system, read in place (every read opens the file anew). */
record LocalFile(Path path) implements ByteSource {
    LocalFile {
        Objects.requireNonNull(path, "path");
    }

    @Override
    public InputStream open() throws IOException {
        return Files.newInputStream(path);
    }

    @Override
    public InputStream open(long from) throws IOException {
        FileChannel ch = FileChannel.open(path);
        try {
            return java.nio.channels.Channels.newInputStream(ch.position(from));
        } catch (IOException | RuntimeException e) {
            ch.close();
            throw e;
        }
    }

    @Override
    public long size() throws IOException {
        return Files.isRegularFile(path) ? Files.size(path) : 0;
    }

    @Override
    public String fileName() {
        return path.getFileName() == null ? "" : path.getFileName().toString();
    }

    @Override
    public int readAt(long position, ByteBuffer dst) throws IOException {
        try (FileChannel ch = FileChannel.open(path)) {
            return ch.read(dst, position);
        }
    }
}
