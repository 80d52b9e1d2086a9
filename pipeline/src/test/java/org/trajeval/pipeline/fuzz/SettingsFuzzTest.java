package org.trajeval.pipeline.fuzz;

import com.code_intelligence.jazzer.api.FuzzedDataProvider;
import com.code_intelligence.jazzer.junit.FuzzTest;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Map;
import org.trajeval.core.InputException;
import org.trajeval.pipeline.ConfigLoader;
import org.trajeval.pipeline.bundle.RunManifest;
import org.trajeval.pipeline.kafka.RunEvent;

/**
 * Coverage-guided fuzzing of the run-settings parsers every intake goes through: a bundle's
 * {@code run.yaml} (YAML), a Kafka run event (JSON) and the service configuration (YAML). Any
 * bytes give a result or an {@link InputException}, the documented refusal; any other exception
 * or error is a bug. Corpus (replayed by every {@code gradle test}):
 * {@code src/test/resources/org/trajeval/pipeline/fuzz/SettingsFuzzTestInputs/<method>/}.
 */
class SettingsFuzzTest {
    private static final Path DIR = scratch();

    private static Path scratch() {
        try {
            Path shm = Path.of("/dev/shm");
            Path dir = Files.isDirectory(shm) && Files.isWritable(shm)
                    ? Files.createTempDirectory(shm, "trajeval-fuzz") : Files.createTempDirectory("trajeval-fuzz");
            dir.toFile().deleteOnExit();
            return dir;
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    private static Path file(String name, byte[] bytes) {
        try {
            Path p = DIR.resolve(name);
            Files.write(p, bytes);
            p.toFile().deleteOnExit();
            return p;
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    @FuzzTest(maxDuration = "5m")
    void runYaml(FuzzedDataProvider data) {
        Path f = file("run.yaml", data.consumeRemainingAsBytes());
        try {
            RunManifest.read(f, "fuzz/run.yaml", 1 << 20);
        } catch (InputException expected) {
            // the documented refusal of a bad run.yaml
        }
    }

    @FuzzTest(maxDuration = "5m")
    void runEvent(FuzzedDataProvider data) {
        try {
            RunEvent.parse(data.consumeRemainingAsString(), "trajeval.runs-0@0");
        } catch (InputException expected) {
            // the documented refusal of a bad event (a dead letter)
        }
    }

    @FuzzTest(maxDuration = "5m")
    void config(FuzzedDataProvider data) {
        Path f = file("config.yaml", data.consumeRemainingAsBytes());
        try {
            ConfigLoader.load(f, Map.of(), Map.of());
        } catch (InputException expected) {
            // the documented refusal of a bad configuration
        }
    }
}
