package org.trajeval.core.io;

import java.io.IOException;
import java.io.InputStream;
import java.nio.ByteBuffer;
import java.nio.file.Path;

/**
 * A {@link ByteSource} over a real file that behaves as {@link ByteSource#of(Path)} in every method:
 * the block-read tests extend it and override the one method where they change the file or fail.
 */
class FileSourceDouble implements ByteSource {
    final Path f;
    private final ByteSource file;

    FileSourceDouble(Path f) {
        this.f = f;
        this.file = ByteSource.of(f);
    }

    @Override
    public InputStream open() throws IOException {
        return file.open();
    }

    @Override
    public InputStream open(long from) throws IOException {
        return file.open(from);
    }

    @Override
    public long size() throws IOException {
        return file.size();
    }

    @Override
    public String fileName() {
        return file.fileName();
    }

    @Override
    public int readAt(long position, ByteBuffer dst) throws IOException {
        return file.readAt(position, dst);
    }
}
