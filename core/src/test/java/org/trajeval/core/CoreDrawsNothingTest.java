package org.trajeval.core;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/**
 * Core holds the report model and no drawing: figures and HTML live in the {@code figures} module,
 * so users of core do not get a charting library. The check reads core's own sources.
 */
class CoreDrawsNothingTest {
    private static final Pattern DRAWING = Pattern.compile(
            "^import\\s+(static\\s+)?(org\\.knowm\\.|java\\.awt\\.|javax\\.imageio\\.|javax\\.swing\\.|org\\.trajeval\\.figures\\."
                    + "|org\\.trajeval\\.cli\\.|org\\.trajeval\\.pipeline\\.)", Pattern.MULTILINE);

    @Test
    void noCoreSourceImportsADrawingLibraryOrAFrontEnd() throws IOException {
        Path main = Path.of(System.getProperty("trajeval.projectDir", ".")).resolve("src/main/java");
        assertTrue(Files.isDirectory(main), main.toString());
        List<String> offenders;
        try (Stream<Path> files = Files.walk(main)) {
            offenders = files.filter(f -> f.toString().endsWith(".java")).filter(f -> {
                try {
                    return DRAWING.matcher(Files.readString(f)).find();
                } catch (IOException e) {
                    throw new java.io.UncheckedIOException(e);
                }
            }).map(Path::toString).toList();
        }
        assertEquals(List.of(), offenders);
    }
}
