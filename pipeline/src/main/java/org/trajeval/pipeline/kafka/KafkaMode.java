package org.trajeval.pipeline.kafka;

import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.IOException;
import java.io.PrintWriter;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Clock;
import java.time.Duration;
import java.time.Instant;
import java.util.List;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import org.apache.kafka.clients.consumer.ConsumerRecord;
import org.apache.kafka.clients.consumer.KafkaConsumer;
import org.apache.kafka.clients.producer.KafkaProducer;
import org.apache.kafka.clients.producer.ProducerRecord;
import org.apache.kafka.common.KafkaException;
import org.apache.kafka.common.TopicPartition;
import org.apache.kafka.common.errors.AuthenticationException;
import org.apache.kafka.common.errors.AuthorizationException;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import org.trajeval.pipeline.PipelineConfig;
import org.trajeval.pipeline.ReportStore;
import org.trajeval.pipeline.RunProcessor;
import org.trajeval.pipeline.RunScorer;
import org.trajeval.pipeline.StopSignals;
import org.trajeval.pipeline.dir.DirectoryLayout;
import org.trajeval.pipeline.ledger.Ledger;
import org.trajeval.pipeline.ledger.LedgerEntry;
import org.trajeval.pipeline.metrics.HealthStatus;
import org.trajeval.pipeline.metrics.HttpEndpoint;
import org.trajeval.pipeline.metrics.PipelineMetrics;

/** Wires and runs the Kafka mode from a configuration (the launcher's {@code kafka}, {@code send}, {@code tail}, {@code republish}). */
public final class KafkaMode {
    private static final Logger LOG = LoggerFactory.getLogger(KafkaMode.class);

    private KafkaMode() {
    }

    /**
     * Runs the Kafka mode until SIGTERM or SIGINT.
     *
     * @param c the configuration
     * @param scorer scores runs
     * @param clients builds the Kafka clients
     * @return the exit code (0)
     * @throws BrokerFailure when no broker answers within {@code kafka.startup_timeout_s}, or the
     *     broker refuses this client
     */
    public static int run(PipelineConfig c, RunScorer scorer, KafkaClients clients) throws InterruptedException {
        PipelineConfig.Kafka k = c.kafka();
        DirectoryLayout layout = new DirectoryLayout(c.rootPath()).create();
        try (Ledger ledger = Ledger.open(layout.ledger());
                InstanceIdentity identity = k.instanceId().isBlank()
                        ? InstanceIdentity.claim(layout.root().resolve("kafka-instances"))
                        : InstanceIdentity.fixed(k.instanceId())) {
            String instance = identity.id();
            Path base = k.bundleBase().isBlank() ? layout.incoming() : Path.of(k.bundleBase());
            KafkaSettings s = new KafkaSettings(k.groupId(), k.inputTopic(), k.outputTopic(), k.deadLetterTopic(),
                    k.partitions(), instance, base, layout.root().resolve("kafka-work").resolve(instance),
                    k.sessionTimeoutMs(), k.transactionTimeoutMs(), c.workers(), seconds(k.unhealthyAfterS()));
            LOG.info("Kafka mode: broker {}, group {}, transactional id {}, transaction timeout {} s",
                    clients.bootstrapServers(), s.groupId(), s.transactionalId(), s.transactionTimeoutMs() / 1000);
            PipelineMetrics metrics = PipelineMetrics.prometheus();
            // the results store recorder (a daemon; an unrecorded report is replayed from the ledger at the next start)
            ReportStore store = org.trajeval.pipeline.store.ResultsRecorder.attach(c,
                    new ReportStore(layout.reports(), ledger, Clock.systemUTC()), metrics.storeLag(), System.getenv())
                    .reports();
            RunProcessor processor = new RunProcessor(scorer, store);
            TopicKeeper keeper = new TopicKeeper(s, clients.bootstrapServers(), layout.root().resolve("kafka-state"));
            try (BrokerWatch watch = new BrokerWatch(clients, keeper, metrics, Clock.systemUTC(), s.unhealthyAfter(),
                    () -> metrics.runsHeld().get())) {
                KafkaService service = new KafkaService(s, clients, processor,
                        new Republisher(ledger, store, s.outputTopic()), c.bundleLimits(), metrics, watch,
                        Clock.systemUTC(), c.bagSettings());
                HttpEndpoint http = c.http().enabled() ? HttpEndpoint.startWithReason(c.http().host(), c.http().port(),
                        metrics::scrape, () -> service.isRunning() ? watch.health()
                                : HealthStatus.down("not consuming (waiting for the broker at " + clients.bootstrapServers()
                                        + ", or stopping)")) : null;
                if (http != null) {
                    LOG.info("serving /metrics and /health on http://{}:{}", c.http().host(), http.port());
                }
                try (StopSignals signals = StopSignals.install(() -> {
                    watch.stop();
                    service.stop();
                })) {
                    if (watch.awaitBroker(seconds(k.startupTimeoutS()))) {
                        watch.start();
                        service.run();
                    }
                } finally {
                    if (http != null) {
                        http.close();
                    }
                }
                LOG.info("stopped");
                return 0;
            }
        }
    }

    private static Duration seconds(double s) {
        if (!(s >= 0) || Double.isInfinite(s)) {
            throw new IllegalArgumentException("a duration in seconds must be finite and >= 0, found " + s);
        }
        return Duration.ofMillis(Math.round(s * 1000));
    }

    /**
     * Publishes run events (one JSON object per file, or per line of a .jsonl file), keyed by robot id.
     *
     * @return the number of events sent
     */
    public static int send(KafkaClients clients, String topic, List<Path> files) {
        ObjectMapper json = new ObjectMapper();
        int n = 0;
        try (KafkaProducer<String, String> p = clients.plainProducer()) {
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
                    get(clients, p.send(new ProducerRecord<>(topic, key, v)));
                    n++;
                }
            }
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        return n;
    }

    /**
     * Publishes the report events of every ledger entry since {@code since} again (duplicates
     * are harmless: consumers drop repeats by run id and content hash).
     *
     * @return the number of events sent
     */
    public static int republish(PipelineConfig c, KafkaClients clients, Instant since) {
        DirectoryLayout layout = new DirectoryLayout(c.rootPath());
        if (!Files.isRegularFile(layout.ledger())) {
            throw new IllegalArgumentException(layout.ledger() + ": no ledger here; --root must be the service's root");
        }
        try (Ledger ledger = Ledger.open(layout.ledger());
                KafkaProducer<String, String> p = clients.plainProducer()) {
            Republisher r = new Republisher(ledger, new ReportStore(layout.reports(), ledger, Clock.systemUTC()),
                    c.kafka().outputTopic());
            int n = 0;
            for (LedgerEntry e : r.entriesSince(since)) {
                ProducerRecord<String, String> event = r.event(e);
                if (event != null) {
                    p.send(event);
                    n++;
                }
            }
            p.flush();
            return n;
        }
    }

    private static void get(KafkaClients clients, java.util.concurrent.Future<?> f) {
        try {
            f.get(60, TimeUnit.SECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IllegalStateException("interrupted", e);
        } catch (ExecutionException e) {
            if (e.getCause() instanceof AuthenticationException || e.getCause() instanceof AuthorizationException) {
                throw new BrokerFailure(BrokerFailure.Kind.REFUSED, clients.bootstrapServers(),
                        BrokerMessages.refused(clients, e.getCause()));
            }
            throw new BrokerFailure(BrokerFailure.Kind.UNREACHABLE, clients.bootstrapServers(),
                    "could not send to " + clients.bootstrapServers() + ": " + BrokerMessages.shortReason(e.getCause()));
        } catch (java.util.concurrent.TimeoutException e) {
            throw new BrokerFailure(BrokerFailure.Kind.UNREACHABLE, clients.bootstrapServers(),
                    "no Kafka broker answered at " + clients.bootstrapServers() + " within 60 s");
        }
    }

    /** Prints the committed records of a topic from its beginning, one value per line, for {@code seconds}. */
    public static int tail(KafkaClients clients, String topic, int seconds, PrintWriter out) {
        int n = 0;
        try (KafkaConsumer<String, String> c = clients.readerConsumer()) {
            List<TopicPartition> tps = c.partitionsFor(topic, Duration.ofSeconds(30)).stream()
                    .map(pi -> new TopicPartition(topic, pi.partition())).toList();
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
        } catch (AuthenticationException | AuthorizationException e) {
            throw new BrokerFailure(BrokerFailure.Kind.REFUSED, clients.bootstrapServers(),
                    BrokerMessages.refused(clients, e));
        } catch (org.apache.kafka.common.errors.TimeoutException e) {
            throw new BrokerFailure(BrokerFailure.Kind.UNREACHABLE, clients.bootstrapServers(),
                    "no Kafka broker answered at " + clients.bootstrapServers() + " within 30 s");
        } catch (KafkaException e) {
            throw new BrokerFailure(BrokerFailure.Kind.UNREACHABLE, clients.bootstrapServers(),
                    "could not read " + topic + " from " + clients.bootstrapServers() + ": " + BrokerMessages.shortReason(e));
        }
        return n;
    }
}
