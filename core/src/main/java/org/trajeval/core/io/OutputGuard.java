package org.trajeval.core.io;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Collection;
import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;

/**
 * Refuses an output path that is one of the inputs, so a report never overwrites the data it was
 * computed from. Two paths are the same file when {@link Files#isSameFile} says so (symbolic links
 * followed, hard links compared by inode); an output that does not exist yet is compared through
 * its real parent folder, so {@code ./dir/../keep.csv} and a link to the folder are caught too.
 */
public final class OutputGuard {
    private OutputGuard() {
    }

    /**
     * @param output the file about to be written
     * @param option how the user named it, e.g. {@code --out}
     * @param inputs the files read ({@code null} entries are skipped)
     * @throws InputException ({@link InputProblem#INVALID_OPTION}) naming the option and the input
     */
    public static void refuseInputs(Path output, String option, Collection<Path> inputs) {
        for (Path in : inputs) {
            if (in != null && same(output, in)) {
                throw new InputException(output.toString(), 0, option, InputProblem.INVALID_OPTION,
                        option + " would overwrite the input " + in + "; write the report to another file", null);
            }
        }
    }

    /**
     * Refuses an output folder that holds one of the inputs: the files written into it could
     * replace that input.
     *
     * @param dir the folder about to be written into
     * @param option how the user named it, e.g. {@code --plot}
     * @param inputs the files read ({@code null} entries are skipped)
     * @throws InputException ({@link InputProblem#INVALID_OPTION}) naming the option and the input
     */
    public static void refuseFolderOfInputs(Path dir, String option, Collection<Path> inputs) {
        for (Path in : inputs) {
            Path parent = in == null ? null : in.toAbsolutePath().normalize().getParent();
            if (parent != null && same(dir, parent)) {
                throw new InputException(dir.toString(), 0, option, InputProblem.INVALID_OPTION,
                        option + " is the folder of the input " + in + ", whose files it could replace; write into "
                        + "another folder", null);
            }
        }
    }

    static boolean same(Path a, Path b) {
        try {
            if (Files.exists(a) && Files.exists(b)) {
                return Files.isSameFile(a, b);
            }
            if (a.toAbsolutePath().normalize().equals(b.toAbsolutePath().normalize())) {
                return true;
            }
            if (!Files.exists(b)) {
                return false;
            }
            Path parent = a.toAbsolutePath().getParent();
            if (parent == null || !Files.isDirectory(parent) || a.getFileName() == null) {
                return false;
            }
            return parent.toRealPath().resolve(a.getFileName()).equals(b.toRealPath());
        } catch (IOException | SecurityException e) {
            return false; // cannot tell: the write itself then reports the problem
        }
    }
}
