package org.trajeval.pipeline;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.nio.file.Path;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;
import org.trajeval.pipeline.dir.Completion;

class ConfigLoaderTest {
    @TempDir
    Path dir;

    @Test
    void fileThenEnvironmentThenCommandLineEachOverrideTheOneBefore() {
        Path f = dir.resolve("p.yaml");
        Fixtures.write(f, "root: /data\nworkers: 3\ncompletion: marker_or_quiet\nkafka:\n  group_id: from-file\n  input_topic: in\n");
        PipelineConfig c = ConfigLoader.load(f,
                Map.of("TRAJEVAL_PIPELINE_WORKERS", "5", "TRAJEVAL_PIPELINE_KAFKA_GROUP_ID", "from-env"),
                Map.of("kafka.group_id", "from-cli"));
        assertEquals("/data", c.root());
        assertEquals(5, c.workers());
        assertEquals("from-cli", c.kafka().groupId());
        assertEquals("in", c.kafka().inputTopic());
        assertEquals("127.0.0.1", c.http().host()); // default kept
        assertEquals(Completion.MARKER_OR_QUIET, c.directoryOptions().completion());
    }

    @Test
    void unknownKeyIsRefusedNamingIt() {
        Path f = dir.resolve("p.yaml");
        Fixtures.write(f, "workerz: 3\n");
        InputException e = assertThrows(InputException.class, () -> ConfigLoader.load(f, Map.of(), Map.of()));
        assertEquals("workerz", e.column());
        assertEquals(InputProblem.INVALID_CONFIGURATION, e.problem());
    }
}
