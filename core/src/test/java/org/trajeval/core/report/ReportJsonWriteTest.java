package org.trajeval.core.report;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The atomic report write: whole or absent, mode 0644, folders made when missing, writers kept apart. */
class ReportJsonWriteTest {
    /** The pipeline's pattern for its own leftover temporary files (StaleTempFiles.OURS). */
    private static final String TEMPORARY_NAME = "\\.r\\.json\\.[0-9]+\\.tmp";

    @TempDir
    Path dir;

    @Test
    void writesIntoAFolderThatDoesNotExistYetWithItsParents() throws IOException {
        Path target = dir.resolve("a/b/c/r.json");
        ReportJson.writeAtomically(target, "{}\n");
        assertEquals("{}\n", Files.readString(target));
        assertEquals(List.of(target), files(target.getParent()));
    }

    @Test
    void theTemporaryFileLiesBesideTheTargetUnderAHiddenNumberedNameWithMode0644() throws IOException {
        Path target = dir.resolve("r.json");
        Path tmp = ReportJson.writeBeside(target, out -> out.write("x".getBytes(StandardCharsets.UTF_8)));
        assertEquals(dir, tmp.getParent());
        assertTrue(tmp.getFileName().toString().matches(TEMPORARY_NAME), tmp.toString());
        assertEquals("x", Files.readString(tmp));
        if (dir.getFileSystem().supportedFileAttributeViews().contains("posix")) {
            assertEquals("rw-r--r--", PosixFilePermissions.toString(Files.getPosixFilePermissions(tmp)));
        }
        ReportJson.moveIntoPlace(tmp, target);
        assertEquals(List.of(target), files(dir));
    }

    @Test
    void aFolderThatIsAFileIsRefusedAsBeforeAndNothingIsLeft() throws IOException {
        Path notAFolder = Files.writeString(dir.resolve("file"), "data");
        UncheckedIOException e = assertThrows(UncheckedIOException.class,
                () -> ReportJson.writeAtomically(notAFolder.resolve("r.json"), "{}"));
        // Files.createDirectories' refusal, as the write gave when it made the folder first
        assertInstanceOf(FileAlreadyExistsException.class, e.getCause());
        assertEquals(List.of(notAFolder), files(dir));
    }

    @Test
    void contentThatFailsToWriteLeavesNoTemporaryFile() throws IOException {
        Path target = dir.resolve("r.json");
        assertThrows(UncheckedIOException.class, () -> ReportJson.writeAtomically(target, out -> {
            out.write('{');
            throw new IOException("disk full");
        }));
        assertEquals(List.of(), files(dir));
    }

    @Test
    void writersBesideEachOtherNeverShareATemporaryFileAndTheTargetIsAlwaysWhole() throws Exception {
        Path target = dir.resolve("r.json");
        int threads = 4;
        int writes = 200;
        ExecutorService pool = Executors.newFixedThreadPool(threads);
        try {
            List<Future<List<Path>>> staged = new ArrayList<>();
            for (int k = 0; k < threads; k++) {
                String text = String.valueOf((char) ('a' + k)).repeat(10_000);
                staged.add(pool.submit(() -> {
                    List<Path> mine = new ArrayList<>();
                    for (int i = 0; i < writes; i++) {
                        Path tmp = ReportJson.writeBeside(target, out -> out.write(text.getBytes(StandardCharsets.UTF_8)));
                        assertEquals(text, Files.readString(tmp)); // nobody else wrote into it
                        mine.add(tmp);
                        ReportJson.moveIntoPlace(tmp, target);
                        String seen = Files.readString(target);
                        assertTrue(seen.length() == 10_000 && seen.chars().distinct().count() == 1, "a torn report");
                    }
                    return mine;
                }));
            }
            Set<Path> names = new HashSet<>();
            for (Future<List<Path>> f : staged) {
                names.addAll(f.get());
            }
            assertEquals(threads * writes, names.size());
        } finally {
            pool.shutdownNow();
        }
        assertEquals(List.of(target), files(dir));
    }

    private static List<Path> files(Path folder) throws IOException {
        try (Stream<Path> s = Files.list(folder)) {
            return s.sorted().toList();
        }
    }
}
