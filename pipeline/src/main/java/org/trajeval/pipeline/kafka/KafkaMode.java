package org.trajeval.pipeline.kafka;

import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.IOException;
import java.io.PrintWriter;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.time.Duration;
import java.util.Properties;
import org.apache.kafka.clients.consumer.ConsumerRecord;
import org.apache.kafka.clients.consumer.KafkaConsumer;
import org.apache.kafka.clients.producer.KafkaProducer;
import org.apache.kafka.clients.producer.ProducerRecord;
import org.apache.kafka.common.TopicPartition;
import org.apache.kafka.common.serialization.StringDeserializer;
import org.apache.kafka.common.serialization.StringSerializer;
import java.lang.management.ManagementFactory;
import java.net.InetAddress;
import java.net.UnknownHostException;
import java.nio.file.Path;
import java.time.Clock;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import org.apache.kafka.clients.admin.Admin;
import org.apache.kafka.clients.admin.NewTopic;
import org.apache.kafka.common.errors.TopicExistsException;
import org.trajeval.pipeline.PipelineConfig;
import org.trajeval.pipeline.ReportStore;
import org.trajeval.pipeline.RunProcessor;
import org.trajeval.pipeline.RunScorer;
import org.trajeval.pipeline.dir.DirectoryLayout;
import org.trajeval.pipeline.ledger.Ledger;
import org.trajeval.pipeline.metrics.HttpEndpoint;
import org.trajeval.pipeline.metrics.PipelineMetrics;

/** Wires and runs the Kafka mode from a configuration (the launcher's {@code kafka} and {@code broker}). */
public final class KafkaMode {
    private KafkaMode() {
    }

    /**
     * Runs the Kafka mode until SIGTERM.
     *
     * @return the exit code (0)
     */
    public static int run(PipelineConfig c, RunScorer scorer, boolean embeddedBroker) {
        PipelineConfig.Kafka k = c.kafka();
        DirectoryLayout layout = new DirectoryLayout(c.rootPath()).create();
        EmbeddedBroker broker = null;
        String bootstrap = k.bootstrapServers();
        if (embeddedBroker) {
            Path data = k.embeddedBrokerDir().isBlank() ? layout.root().resolve("kafka-data") : Path.of(k.embeddedBrokerDir());
            broker = EmbeddedBroker.start(data, k.embeddedBrokerPort());
            bootstrap = broker.bootstrapServers();
            org.slf4j.LoggerFactory.getLogger(KafkaMode.class).info("embedded broker on {}", bootstrap);
        }
        try (Ledger ledger = Ledger.open(layout.ledger())) {
            createTopics(bootstrap, List.of(k.inputTopic(), k.outputTopic(), k.deadLetterTopic()), k.partitions());
            String instance = k.instanceId().isBlank() ? defaultInstanceId() : k.instanceId();
            Path base = k.bundleBase().isBlank() ? layout.incoming() : Path.of(k.bundleBase());
            KafkaSettings s = new KafkaSettings(bootstrap, k.groupId(), k.inputTopic(), k.outputTopic(),
                    k.deadLetterTopic(), instance, base, layout.root().resolve("kafka-work").resolve(instance),
                    k.sessionTimeoutMs(), k.transactionTimeoutMs(), c.workers());
            PipelineMetrics metrics = PipelineMetrics.prometheus();
            // the results store recorder (a daemon; an unrecorded report is replayed from the ledger at the next start)
            RunProcessor processor = new RunProcessor(scorer, org.trajeval.pipeline.store.ResultsRecorder.attach(c,
                    new ReportStore(layout.reports(), ledger, Clock.systemUTC()), metrics.storeLag(), System.getenv())
                    .reports());
            KafkaService service = new KafkaService(s, processor, c.bundleLimits(), metrics, Clock.systemUTC());
            HttpEndpoint http = c.http().enabled()
                    ? HttpEndpoint.start(c.http().host(), c.http().port(), metrics::scrape, () -> true) : null;
            CountDownLatch finished = new CountDownLatch(1);
            Thread hook = new Thread(() -> {
                service.stop();
                try {
                    finished.await(60, TimeUnit.SECONDS);
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                }
            }, "trajeval-shutdown");
            Runtime.getRuntime().addShutdownHook(hook);
            try {
                service.run();
            } finally {
                if (http != null) {
                    http.close();
                }
                finished.countDown();
            }
            return 0;
        } finally {
            if (broker != null) {
                broker.close();
            }
        }
    }

    /** Runs a broker until SIGTERM, printing its bootstrap address. */
    public static int runBroker(Path data, int port, List<String> topics, PrintWriter out) throws InterruptedException {
        EmbeddedBroker broker = EmbeddedBroker.start(data, port);
        CountDownLatch stop = new CountDownLatch(1);
        Runtime.getRuntime().addShutdownHook(new Thread(() -> {
            broker.close();
            stop.countDown();
        }, "trajeval-broker-shutdown"));
        if (!topics.isEmpty()) {
            createTopics(broker.bootstrapServers(), topics, 3);
        }
        out.println("broker running on " + broker.bootstrapServers() + " (stop with Ctrl-C)");
        out.flush();
        stop.await();
        return 0;
    }

    /**
     * Publishes run events (one JSON object per file, or per line of a .jsonl file), keyed by robot id.
     *
     * @return the number of events sent
     */
    public static int send(String bootstrap, String topic, List<Path> files) {
        Properties pp = new Properties();
        pp.put("bootstrap.servers", bootstrap);
        pp.put("acks", "all");
        ObjectMapper json = new ObjectMapper();
        int n = 0;
        try (KafkaProducer<String, String> p = new KafkaProducer<>(pp, new StringSerializer(), new StringSerializer())) {
            for (Path f : files) {
                List<String> values = f.toString().endsWith(".jsonl")
                        ? Files.readAllLines(f).stream().filter(l -> !l.isBlank()).toList() : List.of(Files.readString(f));
                for (String v : values) {
                    String key = null;
                    try {
                        JsonNode node = json.readTree(v);
                        key = node != null && node.hasNonNull("robot_id") ? node.get("robot_id").asText() : null;
                    } catch (JsonProcessingException e) {
                        // sent as is: the service puts it in the dead-letter topic with the reason
                    }
                    p.send(new ProducerRecord<>(topic, key, v)).get(30, TimeUnit.SECONDS);
                    n++;
                }
            }
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IllegalStateException("interrupted", e);
        } catch (ExecutionException | java.util.concurrent.TimeoutException e) {
            throw new IllegalStateException("could not send to " + bootstrap + ": " + e, e);
        }
        return n;
    }

    /** Prints the committed records of a topic from its beginning, one value per line, for {@code seconds}. */
    public static int tail(String bootstrap, String topic, int seconds, PrintWriter out) {
        Properties cp = new Properties();
        cp.put("bootstrap.servers", bootstrap);
        cp.put("isolation.level", "read_committed");
        int n = 0;
        try (KafkaConsumer<String, String> c = new KafkaConsumer<>(cp, new StringDeserializer(), new StringDeserializer())) {
            List<TopicPartition> tps = c.partitionsFor(topic).stream().map(pi -> new TopicPartition(topic, pi.partition()))
                    .toList();
            c.assign(tps);
            c.seekToBeginning(tps);
            long end = System.nanoTime() + seconds * 1_000_000_000L;
            while (System.nanoTime() < end) {
                for (ConsumerRecord<String, String> r : c.poll(Duration.ofMillis(200))) {
                    out.println(r.value());
                    n++;
                }
                out.flush();
            }
        }
        return n;
    }

    /** Creates topics that do not exist yet. */
    public static void createTopics(String bootstrap, List<String> names, int partitions) {
        try (Admin admin = Admin.create(Map.of("bootstrap.servers", bootstrap))) {
            List<NewTopic> topics = new ArrayList<>();
            for (String n : names) {
                topics.add(new NewTopic(n, partitions, (short) 1));
            }
            var result = admin.createTopics(topics).values();
            for (var f : result.values()) {
                try {
                    f.get(60, TimeUnit.SECONDS);
                } catch (ExecutionException e) {
                    if (!(e.getCause() instanceof TopicExistsException)) {
                        throw new IllegalStateException("could not create topics on " + bootstrap + ": " + e.getCause(), e);
                    }
                }
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IllegalStateException("interrupted while creating topics", e);
        } catch (java.util.concurrent.TimeoutException e) {
            throw new IllegalStateException("Kafka at " + bootstrap + " did not answer within 60 s", e);
        }
    }

    private static String defaultInstanceId() {
        String host;
        try {
            host = InetAddress.getLocalHost().getHostName();
        } catch (UnknownHostException e) {
            host = "localhost";
        }
        return host + "-" + ManagementFactory.getRuntimeMXBean().getPid();
    }
}
