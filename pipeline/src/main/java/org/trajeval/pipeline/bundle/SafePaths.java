package org.trajeval.pipeline.bundle;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;

/** Resolves a path written inside a bundle so that it cannot leave the bundle. */
final class SafePaths {
    private SafePaths() {
    }

    /**
     * Resolves {@code relative} (as written in {@code field} of {@code source}) under {@code root}.
     *
     * @throws InputException PATH_ESCAPES for absolute paths, {@code ..}, and symbolic links on
     *     the way; UNREADABLE when the file is missing; TOO_LARGE over {@code maxBytes}
     */
    static Path resolveFile(Path root, String relative, String source, String field, long maxBytes) {
        if (relative == null || relative.isBlank()) {
            throw new InputException(source, 0, field, InputProblem.INVALID_CONFIGURATION,
                    field + " must name a file inside the bundle", relative);
        }
        String r = relative.replace('\\', '/');
        if (r.startsWith("/") || r.matches("^[A-Za-z]:.*") || Path.of(relative).isAbsolute()) {
            throw new InputException(source, 0, field, InputProblem.PATH_ESCAPES,
                    field + " must be a path relative to the bundle, not an absolute path", relative);
        }
        for (String part : r.split("/")) {
            if (part.equals("..")) {
                throw new InputException(source, 0, field, InputProblem.PATH_ESCAPES,
                        field + " must stay inside the bundle ('..' is not allowed)", relative);
            }
        }
        Path file = root.resolve(r).normalize();
        if (!file.startsWith(root)) {
            throw new InputException(source, 0, field, InputProblem.PATH_ESCAPES,
                    field + " must stay inside the bundle", relative);
        }
        for (Path p = file; p != null && p.startsWith(root) && !p.equals(root); p = p.getParent()) {
            if (Files.isSymbolicLink(p)) {
                throw new InputException(source, 0, field, InputProblem.PATH_ESCAPES,
                        field + " must not go through a symbolic link", relative);
            }
        }
        return requireRegularFile(file, source, field, relative, maxBytes);
    }

    /** @return {@code file} after checking it is a regular file (no link) of at most {@code maxBytes} */
    static Path requireRegularFile(Path file, String source, String field, String shown, long maxBytes) {
        if (Files.isSymbolicLink(file)) {
            throw new InputException(source, 0, field, InputProblem.PATH_ESCAPES,
                    field + " must not be a symbolic link", shown);
        }
        if (!Files.isRegularFile(file, LinkOption.NOFOLLOW_LINKS)) {
            throw new InputException(source, 0, field, InputProblem.UNREADABLE,
                    field + " must name an existing regular file in the bundle", shown);
        }
        long size;
        try {
            size = Files.size(file);
        } catch (IOException e) {
            throw new InputException(source, 0, field, InputProblem.UNREADABLE,
                    field + " could not be read: " + e.getMessage(), shown, e);
        }
        if (size > maxBytes) {
            throw new InputException(source, 0, field, InputProblem.TOO_LARGE,
                    field + " must be at most " + maxBytes + " bytes", size + " bytes");
        }
        return file;
    }
}
