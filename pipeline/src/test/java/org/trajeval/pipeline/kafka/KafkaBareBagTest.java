package org.trajeval.pipeline.kafka;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.time.Duration;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Properties;
import java.util.concurrent.TimeUnit;
import org.apache.kafka.clients.consumer.ConsumerRecord;
import org.apache.kafka.clients.consumer.KafkaConsumer;
import org.apache.kafka.clients.producer.KafkaProducer;
import org.apache.kafka.clients.producer.ProducerRecord;
import org.apache.kafka.common.TopicPartition;
import org.apache.kafka.common.serialization.StringDeserializer;
import org.apache.kafka.common.serialization.StringSerializer;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.trajeval.pipeline.PipelineCommand;

/**
 * A run event that names a bare bag under the bundle base: the service (a child JVM, as the
 * launcher runs it, against a broker on a free port of 127.0.0.1) scores the bag with the topics
 * of its configuration ({@code bags.metrics}) and the event's identity; a bag cut short goes to the
 * dead-letter topic with its reason. The bags are copies of ../shared/refdata/ros recordings.
 */
class KafkaBareBagTest {
    private static final ObjectMapper JSON = new ObjectMapper();

    @TempDir
    Path tmp;

    @Test
    void eventNamingABagIsReportedWithTheConfiguredTopicsAndACutBagIsDeadLettered() throws Exception {
        Path ros = Paths.get(System.getProperty("trajeval.refdata", "../../shared/refdata")).resolve("ros");
        assertTrue(Files.isRegularFile(ros.resolve("evo_bag_reference.json")), "refdata missing at " + ros);
        Path incoming = Files.createDirectories(tmp.resolve("svc/incoming"));
        Files.copy(ros.resolve("nav2_turtlebot.mcap"), incoming.resolve("nav2-k1.mcap"));
        byte[] whole = Files.readAllBytes(ros.resolve("nav2_turtlebot.mcap"));
        Files.write(incoming.resolve("cut.mcap"), java.util.Arrays.copyOf(whole, whole.length / 2));
        try (EmbeddedBroker broker = EmbeddedBroker.start(null, 0)) {
            String bs = broker.bootstrapServers();
            BrokerMain.createTopics(bs, List.of("trajeval.runs", "trajeval.reports", "trajeval.runs.dlq"));
            List<String> cmd = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                    "-Xmx256m", "-XX:TieredStopAtLevel=1", "-cp",
                    System.getProperty("trajeval.testClasspath", System.getProperty("java.class.path")),
                    PipelineCommand.class.getName(), "kafka", "--root", tmp.resolve("svc").toString(), "--no-http",
                    "--bootstrap-servers", bs, "--set", "kafka.instance_id=bags", "--set",
                    "bags.metrics.ref_topic=/amcl_pose", "--set", "bags.metrics.est_topic=/odom", "--set",
                    "bags.metrics.alignment=se3"));
            Process svc = new ProcessBuilder(cmd).redirectErrorStream(true)
                    .redirectOutput(ProcessBuilder.Redirect.appendTo(tmp.resolve("svc.log").toFile())).start();
            try {
                Properties pp = new Properties();
                pp.put("bootstrap.servers", bs);
                try (KafkaProducer<String, String> p = new KafkaProducer<>(pp, new StringSerializer(),
                        new StringSerializer())) {
                    p.send(new ProducerRecord<>("trajeval.runs", "bot-1",
                            "{\"run_id\":\"nav2-k1\",\"robot_id\":\"bot-1\",\"bundle\":\"nav2-k1.mcap\"}"));
                    p.send(new ProducerRecord<>("trajeval.runs", "bot-1",
                            "{\"run_id\":\"cut-k2\",\"robot_id\":\"bot-1\",\"bundle\":\"cut.mcap\"}"));
                    p.flush();
                }
                Map<String, JsonNode> reports = read(bs, "trajeval.reports", Duration.ofSeconds(120));
                Map<String, JsonNode> dead = read(bs, "trajeval.runs.dlq", Duration.ofSeconds(30));
                assertEquals(List.of("nav2-k1"), new ArrayList<>(reports.keySet()), Files.readString(tmp.resolve("svc.log")));
                JsonNode report = reports.get("nav2-k1").get("report");
                assertEquals("bot-1", report.get("robot_id").asText());
                // evo_ape bag2 nav2_turtlebot.mcap /amcl_pose /odom -a: 0.5123009339164919 m (evo_bag_reference.json)
                double evoRmse = 0.5123009339164919;
                assertEquals(evoRmse, report.get("evaluation").get("ate").get("trans_m").get("rmse").asDouble(),
                        1e-9 * evoRmse);
                assertEquals(1, dead.size(), dead.toString());
                JsonNode letter = dead.values().iterator().next();
                assertEquals("corrupt_bag", letter.get("kind").asText(), letter.toString());
                assertTrue(letter.get("message").asText().contains("truncated"), letter.toString());
            } finally {
                svc.destroy(); // SIGTERM: finishes the transaction, exits
                if (!svc.waitFor(30, TimeUnit.SECONDS)) {
                    svc.destroyForcibly();
                }
            }
        }
    }

    /** @return the committed records of a topic by run id (reports) or by partition@offset (dead letters), after 1 arrived + 2 s */
    private static Map<String, JsonNode> read(String bs, String topic, Duration timeout) throws Exception {
        Properties cp = new Properties();
        cp.put("bootstrap.servers", bs);
        cp.put("isolation.level", "read_committed");
        Map<String, JsonNode> seen = new HashMap<>();
        try (KafkaConsumer<String, String> c = new KafkaConsumer<>(cp, new StringDeserializer(), new StringDeserializer())) {
            List<TopicPartition> tps = new ArrayList<>();
            c.partitionsFor(topic).forEach(p -> tps.add(new TopicPartition(topic, p.partition())));
            c.assign(tps);
            c.seekToBeginning(tps);
            long deadline = System.nanoTime() + timeout.toNanos();
            while (System.nanoTime() < deadline) {
                for (ConsumerRecord<String, String> r : c.poll(Duration.ofMillis(200))) {
                    JsonNode v = JSON.readTree(r.value());
                    seen.put(v.has("run_id") ? v.get("run_id").asText() : r.partition() + "@" + r.offset(), v);
                }
                if (!seen.isEmpty()) {
                    deadline = Math.min(deadline, System.nanoTime() + Duration.ofSeconds(2).toNanos());
                }
            }
        }
        return seen;
    }
}
