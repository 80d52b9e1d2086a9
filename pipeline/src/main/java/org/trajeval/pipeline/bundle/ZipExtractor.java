package org.trajeval.pipeline.bundle;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import org.trajeval.pipeline.EnvironmentException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.Enumeration;
import java.util.zip.ZipEntry;
import java.util.zip.ZipException;
import java.util.zip.ZipFile;
import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;

/**
 * Extracts a bundle zip into a scratch folder, refusing path traversal entries ({@code ..},
 * absolute names), too many entries, files over the size limit and zip bombs. Sizes are counted
 * on the bytes actually inflated, never trusted from the archive's headers.
 */
final class ZipExtractor {
    private ZipExtractor() {
    }

    /** Extracts {@code zip} into the empty folder {@code dest}. */
    static void extract(Path zip, Path dest, String source, BundleLimits limits) {
        long zipBytes;
        try {
            zipBytes = Math.max(1, Files.size(zip));
        } catch (IOException e) {
            throw new InputException(source, 0, null, InputProblem.UNREADABLE, "zip could not be read: " + e.getMessage(),
                    null, e);
        }
        createFolders(dest);
        long ratioCap = (long) Math.min(limits.maxUnzippedBytes(), zipBytes * limits.maxCompressionRatio());
        try (ZipFile zf = new ZipFile(zip.toFile())) {
            if (zf.size() > limits.maxZipEntries()) {
                throw new InputException(source, 0, null, InputProblem.TOO_LARGE,
                        "zip must hold at most " + limits.maxZipEntries() + " entries", zf.size() + " entries");
            }
            long total = 0;
            byte[] buf = new byte[64 * 1024];
            for (Enumeration<? extends ZipEntry> en = zf.entries(); en.hasMoreElements(); ) {
                ZipEntry e = en.nextElement();
                Path target = entryTarget(dest, e.getName(), source);
                if (e.isDirectory()) {
                    createFolders(target);
                    continue;
                }
                createFolders(target.getParent());
                long fileBytes = 0;
                try (InputStream in = zf.getInputStream(e);
                        OutputStream out = new EnvironmentOutput(target)) {
                    for (int n; (n = in.read(buf)) > 0; ) {
                        fileBytes += n;
                        total += n;
                        if (fileBytes > limits.maxFileBytes()) {
                            throw new InputException(source, 0, e.getName(), InputProblem.TOO_LARGE,
                                    "zip entry '" + e.getName() + "' must be at most " + limits.maxFileBytes()
                                            + " bytes when extracted", "more than " + limits.maxFileBytes() + " bytes");
                        }
                        if (total > ratioCap) {
                            throw new InputException(source, 0, e.getName(), InputProblem.TOO_LARGE,
                                    "zip must extract to at most " + ratioCap + " bytes (" + limits.maxCompressionRatio()
                                            + " x its size, at most " + limits.maxUnzippedBytes()
                                            + " bytes); looks like a zip bomb",
                                    "more than " + ratioCap + " bytes");
                        }
                        out.write(buf, 0, n);
                    }
                }
            }
        } catch (ZipException e) {
            throw new InputException(source, 0, null, InputProblem.UNREADABLE, "not a valid zip file: " + e.getMessage(),
                    null, e);
        } catch (IOException e) {
            throw new InputException(source, 0, null, InputProblem.UNREADABLE, "zip could not be extracted: " + e,
                    null, e);
        }
    }

    private static void createFolders(Path dir) {
        try {
            Files.createDirectories(dir);
        } catch (IOException e) {
            throw new EnvironmentException("create", dir, e);
        }
    }

    /**
     * The extracted file: a failure to create or write it (a full disk) is the service's environment
     * failing, not the zip, so it is an {@link EnvironmentException} and the bundle is retried.
     */
    private static final class EnvironmentOutput extends OutputStream {
        private final Path target;
        private final OutputStream out;

        EnvironmentOutput(Path target) {
            this.target = target;
            try {
                this.out = Files.newOutputStream(target, StandardOpenOption.CREATE_NEW);
            } catch (IOException e) {
                throw new EnvironmentException("create", target, e);
            }
        }

        @Override
        public void write(int b) {
            write(new byte[] {(byte) b}, 0, 1);
        }

        @Override
        public void write(byte[] b, int off, int len) {
            try {
                out.write(b, off, len);
            } catch (IOException e) {
                throw new EnvironmentException("write", target, e);
            }
        }

        @Override
        public void close() {
            try {
                out.close();
            } catch (IOException e) {
                throw new EnvironmentException("write", target, e);
            }
        }
    }

    private static Path entryTarget(Path dest, String name, String source) {
        String n = name.replace('\\', '/');
        boolean escapes = n.startsWith("/") || n.matches("^[A-Za-z]:.*") || n.indexOf('\0') >= 0;
        for (String part : n.split("/")) {
            escapes |= part.equals("..");
        }
        Path target = dest.resolve(n).normalize();
        if (escapes || !target.startsWith(dest) || target.equals(dest)) {
            throw new InputException(source, 0, name, InputProblem.PATH_ESCAPES,
                    "zip entries must stay inside the bundle (no '..', no absolute names)", name);
        }
        return target;
    }
}
