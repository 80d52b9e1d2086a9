package org.trajeval.pipeline.kafka;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Map;
import java.util.Properties;
import java.util.Set;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The service against a real broker in its own JVM that is killed with SIGKILL: one outage longer
 * than the transaction timeout, then the loss of the broker's whole state. The service (a child
 * JVM, production logging) never exits; every run ends with one report file and at least one
 * committed report event; /health says DOWN with the reason during the outage; the log has one
 * line per change of state and no stack trace; SIGTERM exits 0. The other faults of issue 19's
 * table are in the reliability script (README, "Reliability").
 */
class KafkaBrokerFaultTest {
    private static final int RUNS = 40;
    private static final int LATE_RUNS = 10;
    private static final int TRANSACTION_TIMEOUT_MS = 6000;
    private static final Duration OUTAGE = Duration.ofSeconds(10); // + the restart: > the transaction timeout

    @TempDir
    Path tmp;

    @Test
    void serviceRidesOutALongOutageAndRepublishesAfterTheBrokerLostItsState() throws Exception {
        try (BrokerProcess broker = BrokerProcess.start(tmp.resolve("broker-data"), tmp.resolve("broker.log"), null)) {
            String bs = broker.bootstrapServers();
            Properties client = RunEvents.plain(bs);
            BrokerMain.createTopics(bs, RunEvents.TOPICS);
            Path reports = tmp.resolve("svc").resolve("reports");
            int exit;
            String log;
            try (ServiceProcess svc = ServiceProcess.start(tmp.resolve("svc"), bs, tmp.resolve("service.log"),
                    List.of("--set", "kafka.group_id=fault-test", "--set", "kafka.session_timeout_ms=6000",
                            "--set", "kafka.transaction_timeout_ms=" + TRANSACTION_TIMEOUT_MS,
                            "--set", "kafka.unhealthy_after_s=2"))) {
                // 1. a broker outage longer than the transaction timeout, in the middle of the work
                RunEvents.send(client, 0, RUNS, Duration.ZERO);
                long deadline = System.nanoTime() + Duration.ofSeconds(120).toNanos();
                while (RunEvents.reportFiles(reports).size() < RUNS / 4 && System.nanoTime() < deadline) {
                    Thread.sleep(50);
                }
                broker.kill();
                boolean sawDown = false;
                long back = System.nanoTime() + OUTAGE.toNanos();
                while (System.nanoTime() < back) {
                    String h = svc.health();
                    sawDown |= h.startsWith("503") && h.contains("unreachable since");
                    Thread.sleep(500);
                }
                assertTrue(svc.isAlive(), "the service must survive the outage\n" + svc.log());
                broker.restart();
                Set<String> all = RunEvents.ids(0, RUNS);
                Map<String, Integer> events = RunEvents.awaitEvents(client, all, Duration.ofSeconds(150));
                assertEquals(all, events.keySet(), "every run has a committed report event\n" + svc.log());
                assertEquals(RunEvents.files(all), RunEvents.reportFiles(reports), "one report file per run");
                assertTrue(sawDown, "/health must answer 503 with the reason during the outage");

                // 2. the broker loses its whole state: new cluster, no topics, no group offsets
                broker.kill();
                broker.wipe();
                broker.restart();
                Map<String, Integer> republished = RunEvents.awaitEvents(client, all, Duration.ofSeconds(150));
                assertEquals(all, republished.keySet(), "every run re-published after the state loss\n" + svc.log());
                assertTrue(svc.isAlive(), "the service must survive the state loss");
                RunEvents.send(client, RUNS, LATE_RUNS, Duration.ZERO); // the service re-created the input topic
                Set<String> everything = RunEvents.ids(0, RUNS + LATE_RUNS);
                assertEquals(everything, RunEvents.awaitEvents(client, everything, Duration.ofSeconds(120)).keySet());
                assertEquals(RunEvents.files(everything), RunEvents.reportFiles(reports), "still one report file per run");
                exit = svc.terminate();
                log = svc.log();
            }
            assertEquals(0, exit, "SIGTERM ends the current transaction and exits 0\n" + log);
            assertTrue(log.contains("unreachable since") && log.contains("back after"), log);
            assertTrue(log.contains("every report in the ledger will be published again"), log);
            assertFalse(log.contains("\tat "), "no stack trace in the log:\n" + log);
        }
    }
}
