package org.trajeval.pipeline.kafka;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.Properties;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.trajeval.pipeline.PipelineCommand;
import org.trajeval.pipeline.StandInScorer;
import picocli.CommandLine;

/**
 * A transaction timeout above the broker's {@code transaction.max.timeout.ms}: the broker refuses
 * every transaction, so the Kafka mode stops at once with exit code 2 and one line naming the
 * value set and the broker's own limit (read from the broker), instead of retrying for ever or
 * printing an internal error.
 */
class TransactionTimeoutLimitTest {
    private static final int BROKER_LIMIT_MS = 60_000;
    private static final int CONFIGURED_MS = 120_000;

    @TempDir
    Path tmp;

    @Test
    void timeoutAboveTheBrokersLimitIsRefusedWithExitTwoAndOneLine() throws Exception {
        Properties extra = new Properties();
        extra.setProperty(TransactionTimeoutRefusal.BROKER_LIMIT, String.valueOf(BROKER_LIMIT_MS));
        try (EmbeddedBroker broker = EmbeddedBroker.start(null, EmbeddedBroker.freePort(), EmbeddedBroker.freePort(),
                EmbeddedBroker.freePort(), extra)) {
            BrokerMain.createTopics(broker.bootstrapServers(), RunEvents.TOPICS);
            StringWriter out = new StringWriter();
            StringWriter err = new StringWriter();
            CommandLine cl = PipelineCommand.newCommandLine(c -> new StandInScorer(), Map.of());
            cl.setOut(new PrintWriter(out));
            cl.setErr(new PrintWriter(err));
            long start = System.nanoTime();
            int code = cl.execute("kafka", "--root", tmp.resolve("svc").toString(), "--no-http",
                    "--bootstrap-servers", broker.bootstrapServers(), "--startup-timeout", "60",
                    "--set", "kafka.transaction_timeout_ms=" + CONFIGURED_MS);
            double seconds = (System.nanoTime() - start) / 1e9;

            assertEquals(2, code, "a fatal configuration error: exit 2\n" + err);
            List<String> lines = err.toString().lines().toList();
            assertEquals(1, lines.size(), "one line, no stack trace: " + err);
            String line = lines.get(0);
            assertTrue(line.startsWith("trajeval-pipeline: kafka.transaction_timeout_ms: must not exceed the limit of the broker "
                    + broker.bootstrapServers()), line);
            assertTrue(line.contains("transaction.max.timeout.ms = " + BROKER_LIMIT_MS + " ms"), "names the broker's limit: " + line);
            assertTrue(line.endsWith("found \"" + CONFIGURED_MS + " ms\""), "names the value set: " + line);
            assertTrue(seconds < 60, "refused at start-up, not after retrying: " + seconds + " s");
        }
    }
}
