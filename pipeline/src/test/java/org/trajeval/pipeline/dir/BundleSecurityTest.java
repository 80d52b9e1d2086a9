package org.trajeval.pipeline.dir;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Set;
import java.util.TreeSet;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.trajeval.pipeline.Fixtures;
import org.trajeval.pipeline.StandInScorer;
import org.trajeval.pipeline.bundle.BundleLimits;

/** Hostile bundles are refused with the reason, and nothing is written outside the service's folders. */
class BundleSecurityTest {
    private static final ObjectMapper JSON = new ObjectMapper();
    /** Small limits so the test files stay small: 64 KiB per file, ratio 50. */
    private static final BundleLimits LIMITS = new BundleLimits(64 << 10, 1 << 20, 10, 50.0);

    @TempDir
    Path tmp;
    Path root;
    Path outside;

    @BeforeEach
    void setUp() {
        root = tmp.resolve("service");
        outside = tmp.resolve("outside");
        Fixtures.writeTrajectory(outside.resolve("secret.csv"), 50, 0.0, 9);
    }

    private JsonNode refuse(String bundle) throws IOException {
        Set<String> before = tree(tmp);
        DrainSummary s;
        try (ServiceHarness h = new ServiceHarness(root, new StandInScorer(),
                new DirectoryOptions(1, 1, Completion.MARKER, Duration.ofSeconds(60), Duration.ofMillis(50)), LIMITS)) {
            s = h.service.drain();
        }
        assertEquals(new DrainSummary(0, 0, 1), s);
        Set<String> outsideAfter = tree(tmp).stream().filter(p -> !p.startsWith("service")).collect(Collectors.toSet());
        Set<String> outsideBefore = before.stream().filter(p -> !p.startsWith("service")).collect(Collectors.toSet());
        assertEquals(outsideBefore, outsideAfter, "nothing may be written outside the service's folders");
        try (Stream<Path> r = Files.list(root.resolve("reports"))) {
            assertEquals(0, r.count());
        }
        return JSON.readTree(root.resolve("failed").resolve(bundle + ".error.json").toFile());
    }

    private static Set<String> tree(Path dir) throws IOException {
        try (Stream<Path> s = Files.walk(dir)) {
            return s.map(p -> dir.relativize(p).toString()).collect(Collectors.toCollection(TreeSet::new));
        }
    }

    private Path incoming() {
        return new DirectoryLayout(root).create().incoming();
    }

    private void manifestBundle(String name, String reference) {
        Path b = incoming().resolve(name);
        Fixtures.writeTrajectory(b.resolve("est.csv"), 50, 0.05, 2);
        Fixtures.write(b.resolve("run.yaml"), Fixtures.manifest("run-x", "bot", reference, "est.csv"));
        Fixtures.marker(incoming(), name);
    }

    @Test
    void referenceWithDotDotIsRefused() throws IOException {
        manifestBundle("b", "../../../outside/secret.csv");
        JsonNode err = refuse("b");
        assertEquals("path_escapes", err.get("kind").asText());
        assertEquals("unpack", err.get("stage").asText());
        assertTrue(err.get("message").asText().contains("'..' is not allowed"), err.toString());
    }

    @Test
    void absoluteReferenceIsRefused() throws IOException {
        manifestBundle("b", outside.resolve("secret.csv").toString());
        JsonNode err = refuse("b");
        assertEquals("path_escapes", err.get("kind").asText());
        assertTrue(err.get("message").asText().contains("not an absolute path"), err.toString());
    }

    @Test
    void referenceThroughASymbolicLinkIsRefused() throws IOException {
        manifestBundle("b", "gt.csv");
        Files.createSymbolicLink(incoming().resolve("b").resolve("gt.csv"), outside.resolve("secret.csv"));
        JsonNode err = refuse("b");
        assertEquals("path_escapes", err.get("kind").asText());
        assertTrue(err.get("message").asText().contains("symbolic link"), err.toString());
    }

    @Test
    void bundleThatIsASymbolicLinkIsRefused() throws IOException {
        Fixtures.folderBundle(outside, "elsewhere", "run-x", 50, 1);
        Files.createSymbolicLink(incoming().resolve("b"), outside.resolve("elsewhere"));
        Fixtures.marker(incoming(), "b");
        JsonNode err = refuse("b");
        assertEquals("path_escapes", err.get("kind").asText());
    }

    @Test
    void zipWithPathTraversalEntryIsRefusedAndNothingIsExtractedOutside() throws IOException {
        Fixtures.zip(incoming().resolve("z.zip"),
                "run.yaml", Fixtures.manifest("run-x", "bot", "gt.csv", "est.csv").getBytes(StandardCharsets.UTF_8),
                "../../../outside/evil.txt", "pwned".getBytes(StandardCharsets.UTF_8));
        Fixtures.marker(incoming(), "z");
        JsonNode err = refuse("z.zip");
        assertEquals("path_escapes", err.get("kind").asText());
        assertEquals("unpack", err.get("stage").asText());
        assertFalse(Files.exists(outside.resolve("evil.txt")));
    }

    @Test
    void zipWithAbsoluteEntryIsRefused() throws IOException {
        Fixtures.zip(incoming().resolve("z.zip"), "/tmp/evil.txt", "pwned".getBytes(StandardCharsets.UTF_8));
        Fixtures.marker(incoming(), "z");
        assertEquals("path_escapes", refuse("z.zip").get("kind").asText());
    }

    @Test
    void zipBombIsRefusedBeforeItFillsTheDisk() throws IOException {
        // 4 MiB of zeros deflate to about 4 KiB: a ratio near 1000, far over the limit of 50
        Fixtures.zip(incoming().resolve("z.zip"),
                "run.yaml", Fixtures.manifest("run-x", "bot", "gt.csv", "est.csv").getBytes(StandardCharsets.UTF_8),
                "gt.csv", new byte[4 << 20]);
        Fixtures.marker(incoming(), "z");
        JsonNode err = refuse("z.zip");
        assertEquals("too_large", err.get("kind").asText());
        assertTrue(err.get("message").asText().contains("zip bomb") || err.get("message").asText().contains("at most"),
                err.toString());
        try (Stream<Path> s = Files.walk(root)) {
            long biggest = s.filter(Files::isRegularFile).mapToLong(p -> p.toFile().length()).max().orElse(0);
            assertTrue(biggest < 1 << 20, "no extracted file may stay behind: " + biggest);
        }
    }

    @Test
    void oversizedTrajectoryFileIsRefusedWithItsSize() throws IOException {
        manifestBundle("b", "gt.csv");
        Fixtures.writeTrajectory(incoming().resolve("b").resolve("gt.csv"), 3000, 0.0, 1); // about 100 KB > 64 KiB
        JsonNode err = refuse("b");
        assertEquals("too_large", err.get("kind").asText());
        assertTrue(err.get("message").asText().contains("must be at most 65536 bytes"), err.toString());
    }

    @Test
    void runIdThatCouldNameAPathIsRefused() throws IOException {
        Path b = incoming().resolve("b");
        Fixtures.writeTrajectory(b.resolve("gt.csv"), 50, 0.0, 1);
        Fixtures.writeTrajectory(b.resolve("est.csv"), 50, 0.0, 2);
        Fixtures.write(b.resolve("run.yaml"), Fixtures.manifest("../../outside/x", "bot", "gt.csv", "est.csv"));
        Fixtures.marker(incoming(), "b");
        JsonNode err = refuse("b");
        assertEquals("manifest", err.get("stage").asText());
        assertEquals("invalid_configuration", err.get("kind").asText());
        assertEquals(List.of(), List.of(outside.resolve("x.json")).stream().filter(Files::exists).toList());
    }
}
