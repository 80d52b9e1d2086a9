package org.trajeval.core.protocol;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.HexFormat;
import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;
import org.trajeval.core.io.LoadedTrajectory;
import org.trajeval.core.options.PathResolver;

/** The files a manifest names: resolved inside its folder, hashed, and named as the manifest wrote them. */
final class ManifestPaths {
    private ManifestPaths() {
    }

    /** Path settings of a manifest: relative to its folder, which they may not leave. */
    static PathResolver paths(Path base, String source) {
        return (text, where) -> inside(base, text.replace('\\', '/'), source, where);
    }

    /** Resolves a manifest-relative path and refuses one that leaves the folder, also through symbolic links. */
    static Path inside(Path base, String rel, String source, String key) {
        Path p = base.resolve(rel).normalize();
        boolean escapes = !p.startsWith(base);
        if (!escapes && Files.exists(p)) {
            try {
                escapes = !p.toRealPath().startsWith(base.toRealPath());
            } catch (IOException e) {
                throw new UncheckedIOException("could not resolve " + rel, e);
            }
        }
        if (escapes) {
            throw new InputException(source, 0, key, InputProblem.PATH_ESCAPES,
                    "'" + key + "': path leaves the manifest's folder", rel);
        }
        return p;
    }

    /** @return the trajectory named {@code source} (the path as the manifest wrote it) */
    static LoadedTrajectory renamed(LoadedTrajectory t, String source) {
        return new LoadedTrajectory(source, t.format(), t.formatReason(), t.trajectory(), t.sha256(),
                t.indexTimestamps());
    }

    /** @return SHA-256 of the file's bytes, lower-case hex */
    static String sha256(Path file) {
        try (InputStream in = Files.newInputStream(file)) {
            MessageDigest md = MessageDigest.getInstance("SHA-256");
            byte[] buf = new byte[1 << 16];
            int n;
            while ((n = in.read(buf)) > 0) {
                md.update(buf, 0, n);
            }
            return HexFormat.of().formatHex(md.digest());
        } catch (IOException e) {
            throw new UncheckedIOException("could not read " + file, e);
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException("SHA-256 is not available", e);
        }
    }
}
