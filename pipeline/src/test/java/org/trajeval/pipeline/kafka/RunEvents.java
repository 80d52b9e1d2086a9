package org.trajeval.pipeline.kafka;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Properties;
import java.util.Set;
import java.util.TreeSet;
import java.util.concurrent.TimeUnit;
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
import org.trajeval.pipeline.Fixtures;

/** Run events in, report events out: what the broker fault tests and the reliability script send and count. */
final class RunEvents {
    static final String INPUT = "trajeval.runs";
    static final String OUTPUT = "trajeval.reports";
    static final List<String> TOPICS = List.of(INPUT, OUTPUT, "trajeval.runs.dlq");
    private static final ObjectMapper JSON = new ObjectMapper();

    private RunEvents() {
    }

    /** @return run ids run-FROM .. run-(FROM+N-1), sorted */
    static Set<String> ids(int from, int n) {
        return IntStream.range(from, from + n).mapToObj(i -> "run-" + i).collect(Collectors.toCollection(TreeSet::new));
    }

    /** @return the value of run event i: inline trajectories of 60 poses, seeded by i */
    static String event(int i) {
        ObjectNode ev = JSON.createObjectNode();
        ev.put("run_id", "run-" + i);
        ev.put("robot_id", "bot-" + (i % 7));
        ev.putObject("reference").put("file_name", "gt.csv").put("data", trajectory(60, 0.0, 1));
        ev.putObject("estimate").put("file_name", "est.csv").put("data", trajectory(60, 0.05, i));
        return ev.toString();
    }

    /** Sends events {@code from .. from+n-1}, each acknowledged (waits up to 120 s each, riding out an outage). */
    static void send(Properties client, int from, int n, Duration pause) throws Exception {
        Properties pp = new Properties();
        pp.putAll(client);
        pp.put("acks", "all");
        pp.put("delivery.timeout.ms", "120000");
        pp.put("max.block.ms", "120000");
        try (KafkaProducer<String, String> p = new KafkaProducer<>(pp, new StringSerializer(), new StringSerializer())) {
            for (int i = from; i < from + n; i++) {
                p.send(new ProducerRecord<>(INPUT, "bot-" + (i % 7), event(i))).get(130, TimeUnit.SECONDS);
                if (!pause.isZero()) {
                    Thread.sleep(pause.toMillis());
                }
            }
        }
    }

    /** @return plain client properties for a bootstrap address */
    static Properties plain(String bootstrap) {
        Properties p = new Properties();
        p.put("bootstrap.servers", bootstrap);
        return p;
    }

    private static String trajectory(int poses, double noise, long seed) {
        try {
            Path f = Files.createTempFile("traj", ".csv");
            Fixtures.writeTrajectory(f, poses, noise, seed);
            String s = Files.readString(f);
            Files.delete(f);
            return s;
        } catch (IOException e) {
            throw new java.io.UncheckedIOException(e);
        }
    }

    /** @return the report file names in {@code dir} (hidden files left out) */
    static Set<String> reportFiles(Path dir) throws IOException {
        if (!Files.isDirectory(dir)) {
            return new TreeSet<>();
        }
        try (Stream<Path> s = Files.list(dir)) {
            return s.map(p -> p.getFileName().toString()).filter(n -> !n.startsWith("."))
                    .collect(Collectors.toCollection(TreeSet::new));
        }
    }

    /** @return the report file names of these run ids */
    static Set<String> files(Set<String> ids) {
        return ids.stream().map(id -> id + ".json").collect(Collectors.toCollection(TreeSet::new));
    }

    /**
     * Reads the committed report events until every run id in {@code want} was seen (plus 2 s to
     * catch repeats) or the timeout, waiting for the topic to exist: @return events per run id
     * (from the {@code trajeval.run_id} header, checked against the value's run_id)
     */
    static Map<String, Integer> awaitEvents(Properties client, Set<String> want, Duration timeout) throws Exception {
        long deadline = System.nanoTime() + timeout.toNanos();
        Map<String, Object> ac = new HashMap<>();
        client.forEach((k, v) -> ac.put((String) k, v));
        try (Admin admin = Admin.create(ac)) {
            while (!admin.listTopics().names().get(30, TimeUnit.SECONDS).contains(OUTPUT)) {
                if (System.nanoTime() > deadline) {
                    throw new AssertionError(OUTPUT + " does not exist");
                }
                Thread.sleep(200);
            }
        }
        Properties cp = new Properties();
        cp.putAll(client);
        cp.put("isolation.level", "read_committed");
        Map<String, Integer> seen = new HashMap<>();
        try (KafkaConsumer<String, String> c = new KafkaConsumer<>(cp, new StringDeserializer(), new StringDeserializer())) {
            List<TopicPartition> tps = c.partitionsFor(OUTPUT).stream()
                    .map(p -> new TopicPartition(OUTPUT, p.partition())).toList();
            c.assign(tps);
            c.seekToBeginning(tps);
            long extra = Long.MAX_VALUE;
            while (System.nanoTime() < Math.min(deadline, extra)) {
                for (ConsumerRecord<String, String> r : c.poll(Duration.ofMillis(200))) {
                    Header h = r.headers().lastHeader(ReportEvents.RUN_ID);
                    String runId = new String(h.value(), StandardCharsets.UTF_8);
                    if (!JSON.readTree(r.value()).get("run_id").asText().equals(runId)) {
                        throw new AssertionError("header and value disagree: " + r.value());
                    }
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
