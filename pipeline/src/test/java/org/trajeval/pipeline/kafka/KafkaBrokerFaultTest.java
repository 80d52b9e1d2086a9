package org.trajeval.pipeline.kafka;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Properties;
import java.util.Set;
import java.util.TreeSet;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Collectors;
import java.util.stream.IntStream;
import java.util.stream.Stream;
import org.apache.kafka.clients.admin.Admin;
import org.apache.kafka.clients.consumer.ConsumerRecord;
import org.apache.kafka.clients.consumer.KafkaConsumer;
import org.apache.kafka.clients.producer.KafkaProducer;
import org.apache.kafka.clients.producer.ProducerRecord;
import org.apache.kafka.common.TopicPartition;
import org.apache.kafka.common.header.Header;
import org.apache.kafka.common.serialization.StringDeserializer;
import org.apache.kafka.common.serialization.StringSerializer;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.trajeval.pipeline.Fixtures;
import org.trajeval.pipeline.PipelineCommand;

/**
 * The service against a real broker in its own JVM that is killed with SIGKILL: one outage longer
 * than the transaction timeout, then the loss of the broker's whole state. The service (a child
 * JVM, production logging) never exits; every run ends with one report file and at least one
 * committed report event; /health says DOWN with the reason during the outage; the log has one
 * line per change of state and no stack trace; SIGTERM exits 0. The other faults of issue 19's
 * table are in the reliability script (README, "Reliability").
 */
class KafkaBrokerFaultTest {
    private static final ObjectMapper JSON = new ObjectMapper();
    private static final int RUNS = 40;
    private static final int LATE_RUNS = 10;
    private static final int TRANSACTION_TIMEOUT_MS = 8000;
    private static final Duration OUTAGE = Duration.ofSeconds(14); // > the transaction timeout
    private static final List<String> TOPICS = List.of("trajeval.runs", "trajeval.reports", "trajeval.runs.dlq");

    @TempDir
    Path tmp;

    @Test
    void serviceRidesOutALongOutageAndRepublishesAfterTheBrokerLostItsState() throws Exception {
        Path svcLog = tmp.resolve("service.log");
        try (BrokerProcess broker = BrokerProcess.start(tmp.resolve("broker-data"), tmp.resolve("broker.log"), null)) {
            String bs = broker.bootstrapServers();
            BrokerMain.createTopics(bs, TOPICS);
            Process svc = service(bs, svcLog);
            try {
                // 1. a broker outage longer than the transaction timeout, in the middle of the work
                send(bs, 0, RUNS);
                Path reports = tmp.resolve("svc").resolve("reports");
                awaitCount(() -> count(reports), RUNS / 4, Duration.ofSeconds(120), "reports before the outage");
                broker.kill();
                int health = httpPort(svcLog);
                boolean sawDown = false;
                long back = System.nanoTime() + OUTAGE.toNanos();
                while (System.nanoTime() < back) {
                    String h = get(health);
                    sawDown |= h.startsWith("503") && h.contains("unreachable since");
                    Thread.sleep(500);
                }
                assertTrue(svc.isAlive(), "the service must survive the outage\n" + Files.readString(svcLog));
                broker.restart();
                Set<String> all = ids(0, RUNS);
                Map<String, Integer> events = awaitEvents(bs, all, Duration.ofSeconds(150));
                assertEquals(all, events.keySet(), "every run has a committed report event\n" + Files.readString(svcLog));
                assertEquals(files(all), names(reports), "one report file per run");
                assertTrue(sawDown, "/health must answer 503 with the reason during the outage");
                System.out.printf("outage of %d s: %d runs, %d report events (%d runs with more than one)%n",
                        OUTAGE.toSeconds(), RUNS, events.values().stream().mapToInt(Integer::intValue).sum(),
                        events.values().stream().filter(n -> n > 1).count());

                // 2. the broker loses its whole state: new cluster, no topics, no group offsets
                broker.kill();
                broker.wipe();
                broker.restart();
                Map<String, Integer> republished = awaitEvents(bs, all, Duration.ofSeconds(150));
                assertEquals(all, republished.keySet(), "every run re-published after the state loss\n"
                        + Files.readString(svcLog));
                assertTrue(svc.isAlive(), "the service must survive the state loss");
                send(bs, RUNS, LATE_RUNS); // the service re-created the input topic: new runs flow again
                Set<String> everything = ids(0, RUNS + LATE_RUNS);
                assertEquals(everything, awaitEvents(bs, everything, Duration.ofSeconds(120)).keySet());
                assertEquals(files(everything), names(reports), "still one report file per run");
            } finally {
                svc.destroy(); // SIGTERM
                assertTrue(svc.waitFor(60, TimeUnit.SECONDS), "the service must stop on SIGTERM");
            }
            assertEquals(0, svc.exitValue(), "SIGTERM ends the current transaction and exits 0\n" + Files.readString(svcLog));
            String log = Files.readString(svcLog);
            assertTrue(log.contains("unreachable since") && log.contains("back after"), log);
            assertTrue(log.contains("every report in the ledger will be published again"), log);
            assertFalse(log.contains("\tat "), "no stack trace in the log:\n" + log);
        }
    }

    private Process service(String bootstrap, Path log) throws IOException {
        List<String> cmd = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-Xmx256m", "-XX:TieredStopAtLevel=1",
                "-Dlogback.configurationFile=" + Path.of(System.getProperty("trajeval.projectDir", "."))
                        .resolve("src/main/resources/logback.xml"),
                "-cp", System.getProperty("trajeval.testClasspath", System.getProperty("java.class.path")),
                PipelineCommand.class.getName(), "kafka", "--root", tmp.resolve("svc").toString(), "--http-port", "0",
                "--bootstrap-servers", bootstrap, "--workers", "2", "--set", "kafka.group_id=fault-test",
                "--set", "kafka.session_timeout_ms=6000",
                "--set", "kafka.transaction_timeout_ms=" + TRANSACTION_TIMEOUT_MS, "--set", "kafka.unhealthy_after_s=2"));
        return new ProcessBuilder(cmd).redirectErrorStream(true)
                .redirectOutput(ProcessBuilder.Redirect.appendTo(log.toFile())).start();
    }

    /** Sends runs {@code from .. from+n-1} (inline, 60 poses), waiting up to 60 s for the input topic. */
    private static void send(String bs, int from, int n) throws Exception {
        String gt = trajectory(60, 0.0, 1);
        Properties pp = new Properties();
        pp.put("bootstrap.servers", bs);
        pp.put("acks", "all");
        try (KafkaProducer<String, String> p = new KafkaProducer<>(pp, new StringSerializer(), new StringSerializer())) {
            for (int i = from; i < from + n; i++) {
                ObjectNode ev = JSON.createObjectNode();
                ev.put("run_id", "run-" + i);
                ev.put("robot_id", "bot-" + (i % 7));
                ev.putObject("reference").put("file_name", "gt.csv").put("data", gt);
                ev.putObject("estimate").put("file_name", "est.csv").put("data", trajectory(60, 0.05, i));
                p.send(new ProducerRecord<>("trajeval.runs", "bot-" + (i % 7), ev.toString())).get(60, TimeUnit.SECONDS);
            }
        }
    }

    private static String trajectory(int poses, double noise, long seed) throws IOException {
        Path f = Files.createTempFile("traj", ".csv");
        Fixtures.writeTrajectory(f, poses, noise, seed);
        String s = Files.readString(f);
        Files.delete(f);
        return s;
    }

    private static Set<String> ids(int from, int n) {
        return IntStream.range(from, from + n).mapToObj(i -> "run-" + i).collect(Collectors.toCollection(TreeSet::new));
    }

    private static Set<String> files(Set<String> ids) {
        return ids.stream().map(id -> id + ".json").collect(Collectors.toCollection(TreeSet::new));
    }

    private static Set<String> names(Path dir) throws IOException {
        try (Stream<Path> s = Files.list(dir)) {
            return s.map(p -> p.getFileName().toString()).filter(n -> !n.startsWith("."))
                    .collect(Collectors.toCollection(TreeSet::new));
        }
    }

    private static int count(Path dir) {
        try {
            return Files.isDirectory(dir) ? names(dir).size() : 0;
        } catch (IOException e) {
            return 0;
        }
    }

    private static void awaitCount(java.util.function.IntSupplier n, int atLeast, Duration timeout, String what)
            throws InterruptedException {
        long deadline = System.nanoTime() + timeout.toNanos();
        while (n.getAsInt() < atLeast) {
            if (System.nanoTime() > deadline) {
                throw new AssertionError(what + ": " + n.getAsInt() + " < " + atLeast);
            }
            Thread.sleep(50);
        }
    }

    /** @return the port the service logged for /health */
    private static int httpPort(Path log) throws IOException {
        Matcher m = Pattern.compile("/health on http://127\\.0\\.0\\.1:(\\d+)").matcher(Files.readString(log));
        assertTrue(m.find(), "the service logs its HTTP port");
        return Integer.parseInt(m.group(1));
    }

    private static String get(int port) {
        try {
            HttpResponse<String> r = HttpClient.newHttpClient().send(HttpRequest.newBuilder(
                    URI.create("http://127.0.0.1:" + port + "/health")).timeout(Duration.ofSeconds(2)).build(),
                    HttpResponse.BodyHandlers.ofString());
            return r.statusCode() + " " + r.body();
        } catch (IOException e) {
            return "no answer " + e;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return "interrupted";
        }
    }

    /**
     * Reads the committed report events until every run id in {@code want} was seen (plus 2 s to
     * catch repeats), waiting for the topic to exist: @return events per run id (from the
     * {@code trajeval.run_id} header, which must match the value's run_id)
     */
    static Map<String, Integer> awaitEvents(String bs, Set<String> want, Duration timeout) throws Exception {
        long deadline = System.nanoTime() + timeout.toNanos();
        try (Admin admin = Admin.create(Map.of("bootstrap.servers", bs))) {
            while (!admin.listTopics().names().get(30, TimeUnit.SECONDS).contains("trajeval.reports")) {
                if (System.nanoTime() > deadline) {
                    throw new AssertionError("trajeval.reports was not re-created");
                }
                Thread.sleep(200);
            }
        }
        Properties cp = new Properties();
        cp.put("bootstrap.servers", bs);
        cp.put("isolation.level", "read_committed");
        Map<String, Integer> seen = new HashMap<>();
        try (KafkaConsumer<String, String> c = new KafkaConsumer<>(cp, new StringDeserializer(), new StringDeserializer())) {
            List<TopicPartition> tps = c.partitionsFor("trajeval.reports").stream()
                    .map(p -> new TopicPartition("trajeval.reports", p.partition())).toList();
            c.assign(tps);
            c.seekToBeginning(tps);
            long extra = Long.MAX_VALUE;
            while (System.nanoTime() < Math.min(deadline, extra)) {
                for (ConsumerRecord<String, String> r : c.poll(Duration.ofMillis(200))) {
                    Header h = r.headers().lastHeader(ReportEvents.RUN_ID);
                    String runId = new String(h.value(), StandardCharsets.UTF_8);
                    assertEquals(JSON.readTree(r.value()).get("run_id").asText(), runId);
                    seen.merge(runId, 1, Integer::sum);
                }
                if (extra == Long.MAX_VALUE && seen.keySet().containsAll(want)) {
                    extra = System.nanoTime() + Duration.ofSeconds(2).toNanos();
                }
            }
        }
        return seen;
    }
}
