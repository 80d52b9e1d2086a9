package org.trajeval.pipeline;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.FileSystemException;
import java.nio.file.Path;
import org.trajeval.core.InputText;

/**
 * The service's own environment failed while it worked on a run: a full disk, a read-only or
 * missing folder of its own, an I/O error on its own files. Never the input's fault: the bundle is
 * kept where it can be retried (processing/, or the Kafka record uncommitted), nothing is put in
 * failed/, and the message names the operation, the path and the operating system's reason, e.g.
 * {@code could not write /data/reports/r1.json: No space left on device}.
 */
public final class EnvironmentException extends RuntimeException {
    private static final long serialVersionUID = 1L;

    /**
     * @param operation what was being done, e.g. "write", "move", "create"
     * @param path the file or folder concerned
     * @param cause the I/O error
     */
    public EnvironmentException(String operation, Path path, IOException cause) {
        super("could not " + operation + " " + InputText.escape(String.valueOf(path)) + ": " + reason(cause), cause);
    }

    /** @return the same failure from an unchecked wrapper, whose message named the path already */
    public static EnvironmentException of(UncheckedIOException e) {
        return new EnvironmentException(e);
    }

    private EnvironmentException(UncheckedIOException e) {
        super(withReason(InputText.escape(e.getMessage()), reason(e.getCause())), e);
    }

    private static String withReason(String message, String reason) {
        return message == null ? reason : message.endsWith(reason) ? message : message + ": " + reason;
    }

    /** @return the operating system's reason, e.g. "No space left on device" or "Read-only file system" */
    public static String reason(IOException e) {
        if (e instanceof FileSystemException fs && fs.getReason() != null) {
            return fs.getReason();
        }
        if (e instanceof java.nio.file.AccessDeniedException) {
            return "Permission denied";
        }
        String m = e.getMessage();
        return InputText.escape(m == null ? e.getClass().getSimpleName() : m);
    }
}
