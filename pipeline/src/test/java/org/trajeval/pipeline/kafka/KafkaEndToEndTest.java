package org.trajeval.pipeline.kafka;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Properties;
import java.util.Set;
import java.util.concurrent.TimeUnit;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import org.apache.kafka.clients.admin.Admin;
import org.apache.kafka.clients.consumer.ConsumerRecord;
import org.apache.kafka.clients.consumer.KafkaConsumer;
import org.apache.kafka.clients.producer.KafkaProducer;
import org.apache.kafka.clients.producer.ProducerRecord;
import org.apache.kafka.common.TopicPartition;
import org.apache.kafka.common.serialization.StringDeserializer;
import org.apache.kafka.common.serialization.StringSerializer;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.trajeval.pipeline.Fixtures;
import org.trajeval.pipeline.PipelineCommand;

/**
 * Embedded broker, 3 partitions, two service instances (child JVMs) in one consumer group, 500
 * run events; one instance is killed with SIGKILL mid-way. Every good run is reported exactly once
 * (one report file, one committed report event); every malformed event is in the dead-letter topic
 * exactly once, with its reason.
 */
class KafkaEndToEndTest {
    private static final ObjectMapper JSON = new ObjectMapper();
    private static final int EVENTS = 500;
    private static final String GROUP = "trajeval-test";

    @TempDir
    Path tmp;

    private Process instance(String bootstrap, String id) throws IOException {
        List<String> cmd = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-Xmx256m", "-XX:TieredStopAtLevel=1", "-cp",
                System.getProperty("trajeval.testClasspath", System.getProperty("java.class.path")),
                PipelineCommand.class.getName(), "kafka", "--root", tmp.resolve("svc").toString(), "--no-http",
                "--bootstrap-servers", bootstrap, "--workers", "2", "--set", "kafka.instance_id=" + id,
                "--set", "kafka.group_id=" + GROUP, "--set", "kafka.session_timeout_ms=6000",
                "--set", "kafka.transaction_timeout_ms=10000"));
        return new ProcessBuilder(cmd).redirectErrorStream(true)
                .redirectOutput(ProcessBuilder.Redirect.appendTo(tmp.resolve(id + ".log").toFile())).start();
    }

    private static String trajectory(int poses, double noise, long seed) throws IOException {
        Path f = Files.createTempFile("traj", ".csv");
        Fixtures.writeTrajectory(f, poses, noise, seed);
        String s = Files.readString(f);
        Files.delete(f);
        return s;
    }

    @Test
    void twoInstancesOneKilledEveryRunReportedExactlyOnceAndBadEventsDeadLettered() throws Exception {
        Set<String> good = new HashSet<>();
        Set<String> bad = new HashSet<>();
        try (EmbeddedBroker broker = EmbeddedBroker.start(null, 0)) {
            String bs = broker.bootstrapServers();
            BrokerMain.createTopics(bs, List.of("trajeval.runs", "trajeval.reports", "trajeval.runs.dlq"));
            Process a = instance(bs, "a");
            Process b = instance(bs, "b");
            try {
                awaitGroupMembers(bs, 2);
                String gt = trajectory(200, 0.0, 1);
                Properties pp = new Properties();
                pp.put("bootstrap.servers", bs);
                try (KafkaProducer<String, String> p = new KafkaProducer<>(pp, new StringSerializer(), new StringSerializer())) {
                    for (int i = 0; i < EVENTS; i++) {
                        String runId = "run-" + i;
                        String robot = "bot-" + (i % 10);
                        String value;
                        if (i % 25 == 5) {
                            value = "{not json";
                            bad.add("offset-less:" + i);
                        } else if (i % 25 == 10) {
                            value = "{\"run_id\":\"" + runId + "\",\"robot_id\":\"" + robot + "\"}";
                            bad.add(runId);
                        } else {
                            ObjectNode ev = JSON.createObjectNode();
                            ev.put("run_id", runId);
                            ev.put("robot_id", robot);
                            ev.putObject("reference").put("file_name", "gt.csv").put("data", gt);
                            String est = i % 25 == 15 ? "t,x,y,yaw\n0,0,0,0\n0.1,nan?,0,0\n" : trajectory(200, 0.05, i);
                            ev.putObject("estimate").put("file_name", "est.csv").put("data", est);
                            value = ev.toString();
                            (i % 25 == 15 ? bad : good).add(runId);
                        }
                        p.send(new ProducerRecord<>("trajeval.runs", robot, value));
                    }
                    p.flush();
                }
                Path reports = tmp.resolve("svc").resolve("reports");
                long deadline = System.nanoTime() + Duration.ofSeconds(120).toNanos();
                while (count(reports) < EVENTS / 4 && System.nanoTime() < deadline) {
                    Thread.sleep(50);
                }
                a.destroyForcibly(); // SIGKILL mid-way
                assertTrue(a.waitFor(30, TimeUnit.SECONDS));
                int killedAt = count(reports);
                assertTrue(killedAt < good.size(), "instance a must die before the work is done: " + killedAt);

                Map<String, Integer> events = readAll(bs, "trajeval.reports", good.size(), Duration.ofSeconds(150));
                Map<String, Integer> dead = readAll(bs, "trajeval.runs.dlq", bad.size(), Duration.ofSeconds(30));

                Set<String> files;
                try (Stream<Path> s = Files.list(reports)) {
                    files = s.map(x -> x.getFileName().toString()).filter(n -> !n.startsWith("."))
                            .collect(Collectors.toSet());
                }
                assertEquals(good.stream().map(id -> id + ".json").collect(Collectors.toSet()), files,
                        "one report file per good run");
                assertEquals(good, events.keySet(), "one report event per good run");
                assertTrue(events.values().stream().allMatch(n -> n == 1), "report events duplicated: " + events);
                assertEquals(bad.size(), dead.values().stream().mapToInt(Integer::intValue).sum(), dead.toString());
                assertTrue(dead.values().stream().allMatch(n -> n == 1), "dead letters duplicated: " + dead);
            } finally {
                a.destroyForcibly();
                b.destroy(); // SIGTERM: graceful stop
                if (!b.waitFor(30, TimeUnit.SECONDS)) {
                    b.destroyForcibly();
                }
            }
        }
    }

    private static int count(Path dir) throws IOException {
        if (!Files.isDirectory(dir)) {
            return 0;
        }
        try (Stream<Path> s = Files.list(dir)) {
            return (int) s.filter(p -> !p.getFileName().toString().startsWith(".")).count();
        }
    }

    private static void awaitGroupMembers(String bs, int n) throws Exception {
        try (Admin admin = Admin.create(Map.of("bootstrap.servers", bs))) {
            long deadline = System.nanoTime() + Duration.ofSeconds(60).toNanos();
            while (System.nanoTime() < deadline) {
                try {
                    var d = admin.describeConsumerGroups(List.of(GROUP)).all().get(10, TimeUnit.SECONDS).get(GROUP);
                    if (d.members().size() >= n) {
                        return;
                    }
                } catch (java.util.concurrent.ExecutionException e) {
                    // the group does not exist yet
                }
                Thread.sleep(200);
            }
            throw new AssertionError("the two instances did not join the group within 60 s");
        }
    }

    /**
     * Reads committed records of a topic until {@code expected} arrived (plus 2 s to catch
     * duplicates) or the timeout: @return count per key (run id for reports; "partition@offset"
     * of the original event for dead letters)
     */
    private static Map<String, Integer> readAll(String bs, String topic, int expected, Duration timeout) throws IOException {
        Properties cp = new Properties();
        cp.put("bootstrap.servers", bs);
        cp.put("isolation.level", "read_committed");
        Map<String, Integer> seen = new HashMap<>();
        try (KafkaConsumer<String, String> c = new KafkaConsumer<>(cp, new StringDeserializer(), new StringDeserializer())) {
            List<TopicPartition> tps = c.partitionsFor(topic).stream()
                    .map(p -> new TopicPartition(topic, p.partition())).collect(Collectors.toList());
            c.assign(tps);
            c.seekToBeginning(tps);
            long deadline = System.nanoTime() + timeout.toNanos();
            long extra = Long.MAX_VALUE;
            int total = 0;
            while (System.nanoTime() < Math.min(deadline, extra)) {
                for (ConsumerRecord<String, String> r : c.poll(Duration.ofMillis(200))) {
                    JsonNode v = JSON.readTree(r.value());
                    String key = v.has("run_id") ? v.get("run_id").asText()
                            : v.get("partition").asText() + "@" + v.get("offset").asText();
                    if (!v.has("run_id")) {
                        assertTrue(!v.get("message").asText().isBlank() && v.has("stage") && v.has("original"), r.value());
                    }
                    seen.merge(key, 1, Integer::sum);
                    total++;
                }
                if (total >= expected && extra == Long.MAX_VALUE) {
                    extra = System.nanoTime() + Duration.ofSeconds(2).toNanos();
                }
            }
        }
        return seen;
    }
}
