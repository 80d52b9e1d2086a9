package org.trajeval.pipeline.kafka;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.time.Clock;
import java.time.Duration;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Properties;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import org.apache.kafka.clients.consumer.ConsumerRecord;
import org.apache.kafka.clients.consumer.ConsumerRecords;
import org.apache.kafka.clients.consumer.KafkaConsumer;
import org.apache.kafka.clients.consumer.OffsetAndMetadata;
import org.apache.kafka.clients.producer.KafkaProducer;
import org.apache.kafka.clients.producer.ProducerRecord;
import org.apache.kafka.common.KafkaException;
import org.apache.kafka.common.TopicPartition;
import org.apache.kafka.common.errors.WakeupException;
import org.apache.kafka.common.serialization.StringDeserializer;
import org.apache.kafka.common.serialization.StringSerializer;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;
import org.trajeval.pipeline.Outcome;
import org.trajeval.pipeline.RunFailure;
import org.trajeval.pipeline.RunJob;
import org.trajeval.pipeline.RunProcessor;
import org.trajeval.pipeline.RunResult;
import org.trajeval.pipeline.Stage;
import org.trajeval.pipeline.StageException;
import org.trajeval.pipeline.bundle.BundleKind;
import org.trajeval.pipeline.bundle.BundleLimits;
import org.trajeval.pipeline.bundle.BundleOpener;
import org.trajeval.pipeline.metrics.PipelineMetrics;

/**
 * The Kafka mode: a consume-score-produce loop in Kafka transactions. Each poll's records are
 * scored (reports written and fsync'd, ledger appended), their report events (or dead-letter
 * records) are sent, and the input offsets are committed in the same transaction. A crash before
 * the commit aborts the transaction; the record is delivered again, the ledger recognises the
 * report as already written, and its report event is sent again in the new transaction: one
 * report file and one committed report event per run.
 */
public final class KafkaService {
    private static final Logger LOG = LoggerFactory.getLogger(KafkaService.class);
    private static final ObjectMapper JSON = new ObjectMapper();

    private final KafkaSettings settings;
    private final RunProcessor processor;
    private final BundleOpener opener;
    private final BundleLimits limits;
    private final PipelineMetrics metrics;
    private final Clock clock;
    private volatile boolean stopping;
    private volatile boolean running;
    private volatile KafkaConsumer<String, String> consumer;

    /**
     * @param settings topics, group, folders
     * @param processor scores and files runs
     * @param limits bundle limits
     * @param metrics where to count
     * @param clock clock for dead-letter records
     */
    public KafkaService(KafkaSettings settings, RunProcessor processor, BundleLimits limits, PipelineMetrics metrics,
            Clock clock) {
        this.settings = settings;
        this.processor = processor;
        this.limits = limits;
        this.opener = new BundleOpener(limits);
        this.metrics = metrics;
        this.clock = clock;
    }

    /** Stops the loop after the current transaction. */
    public void stop() {
        stopping = true;
        KafkaConsumer<String, String> c = consumer;
        if (c != null) {
            c.wakeup();
        }
    }

    /** @return true while consuming */
    public boolean isRunning() {
        return running && !stopping;
    }

    /** Consumes until {@link #stop()}. */
    public void run() {
        Properties cp = new Properties();
        cp.put("bootstrap.servers", settings.bootstrapServers());
        cp.put("group.id", settings.groupId());
        cp.put("enable.auto.commit", "false");
        cp.put("isolation.level", "read_committed");
        cp.put("auto.offset.reset", "earliest");
        cp.put("max.poll.records", "20");
        cp.put("session.timeout.ms", String.valueOf(settings.sessionTimeoutMs()));
        cp.put("heartbeat.interval.ms", String.valueOf(Math.max(100, settings.sessionTimeoutMs() / 4)));
        cp.put("client.id", "trajeval-" + settings.instanceId());
        Properties pp = new Properties();
        pp.put("bootstrap.servers", settings.bootstrapServers());
        pp.put("transactional.id", settings.groupId() + "-" + settings.instanceId());
        pp.put("enable.idempotence", "true");
        pp.put("acks", "all");
        pp.put("transaction.timeout.ms", String.valueOf(settings.transactionTimeoutMs()));
        pp.put("client.id", "trajeval-" + settings.instanceId() + "-producer");
        ExecutorService pool = Executors.newFixedThreadPool(settings.workers(), r -> new Thread(r, "trajeval-kafka-worker"));
        try (KafkaConsumer<String, String> c = new KafkaConsumer<>(cp, new StringDeserializer(), new StringDeserializer());
                KafkaProducer<String, String> producer = new KafkaProducer<>(pp, new StringSerializer(), new StringSerializer())) {
            consumer = c;
            producer.initTransactions();
            c.subscribe(List.of(settings.inputTopic()));
            running = true;
            while (!stopping) {
                ConsumerRecords<String, String> records;
                try {
                    records = c.poll(Duration.ofMillis(500));
                } catch (WakeupException e) {
                    break;
                }
                updateLag(c);
                if (records.isEmpty()) {
                    continue;
                }
                processBatch(c, producer, pool, records);
            }
        } finally {
            running = false;
            consumer = null;
            pool.shutdown();
        }
    }

    private void processBatch(KafkaConsumer<String, String> c, KafkaProducer<String, String> producer, ExecutorService pool,
            ConsumerRecords<String, String> records) {
        List<ConsumerRecord<String, String>> list = new ArrayList<>();
        records.forEach(list::add);
        List<Future<List<ProducerRecord<String, String>>>> futures = new ArrayList<>();
        for (ConsumerRecord<String, String> r : list) {
            futures.add(pool.submit(() -> handle(r)));
        }
        producer.beginTransaction();
        try {
            for (Future<List<ProducerRecord<String, String>>> f : futures) {
                for (ProducerRecord<String, String> out : f.get()) {
                    producer.send(out);
                }
            }
            Map<TopicPartition, OffsetAndMetadata> offsets = new HashMap<>();
            for (TopicPartition tp : records.partitions()) {
                List<ConsumerRecord<String, String>> rs = records.records(tp);
                offsets.put(tp, new OffsetAndMetadata(rs.get(rs.size() - 1).offset() + 1));
            }
            producer.sendOffsetsToTransaction(offsets, c.groupMetadata());
            producer.commitTransaction();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            abortAndRewind(c, producer, records);
        } catch (ExecutionException | KafkaException e) {
            LOG.warn("transaction failed, the batch will be delivered again: {}", e.toString());
            abortAndRewind(c, producer, records);
            if (e instanceof org.apache.kafka.common.errors.ProducerFencedException) {
                throw (KafkaException) e;
            }
        }
    }

    private static void abortAndRewind(KafkaConsumer<String, String> c, KafkaProducer<String, String> producer,
            ConsumerRecords<String, String> records) {
        try {
            producer.abortTransaction();
        } catch (KafkaException ignored) {
            // fenced or closing: the broker aborts the transaction on timeout
        }
        for (TopicPartition tp : records.partitions()) {
            if (c.assignment().contains(tp)) {
                c.seek(tp, records.records(tp).get(0).offset());
            }
        }
    }

    /** Top-level handler of one record: @return the records to publish for it */
    private List<ProducerRecord<String, String>> handle(ConsumerRecord<String, String> r) {
        long start = System.nanoTime();
        String source = r.topic() + "-" + r.partition() + "@" + r.offset();
        Path scratch = settings.scratch().resolve(r.partition() + "-" + r.offset());
        RunResult result;
        RunEvent event = null;
        try {
            try {
                event = RunEvent.parse(r.value(), source);
            } catch (InputException e) {
                throw new StageException(RunFailure.of(Stage.MANIFEST, e), e);
            }
            RunJob job = toJob(event, scratch, source);
            result = processor.process(job);
        } catch (StageException e) {
            result = RunResult.failed(event == null ? null : event.metadata().runId(), e.failure());
        } catch (RuntimeException e) {
            LOG.error("internal error on {}", source, e);
            result = RunResult.failed(null, RunFailure.of(Stage.SCORE, e));
        } finally {
            deleteTree(scratch);
        }
        metrics.recordRun(result.outcome(), Duration.ofNanos(System.nanoTime() - start));
        String key = event != null && event.metadata().robotId() != null ? event.metadata().robotId() : r.key();
        return switch (result.outcome()) {
            case REPORTED -> {
                LOG.info("reported run_id={} version={} source={}", result.runId(), result.version(), source);
                yield List.of(reportEvent(key, result, source));
            }
            case DUPLICATE -> {
                if (source.equals(result.firstSource())) {
                    // delivered again after an aborted transaction: publish its report event again
                    LOG.info("re-delivered run_id={} source={}", result.runId(), source);
                    yield List.of(reportEvent(key, result, source));
                }
                LOG.info("duplicate run_id={} source={} first={}", result.runId(), source, result.firstSource());
                yield List.of();
            }
            case FAILED -> {
                LOG.warn("dead-letter {} stage={} kind={} message=\"{}\"", source, result.failure().stage(),
                        result.failure().kind(), result.failure().message());
                yield List.of(deadLetter(key, r, result.failure()));
            }
        };
    }

    private RunJob toJob(RunEvent event, Path scratch, String source) {
        try {
            Files.createDirectories(scratch);
            if (event.bundle() != null) {
                Path p;
                try {
                    p = BundleOpener.locate(settings.bundleBase(), event.bundle(), source);
                } catch (InputException e) {
                    throw new StageException(RunFailure.of(Stage.UNPACK, e), e);
                }
                String file = p.getFileName().toString();
                boolean zip = file.endsWith(".zip") && Files.isRegularFile(p, LinkOption.NOFOLLOW_LINKS);
                RunJob job = opener.open(zip ? BundleKind.ZIP : BundleKind.FOLDER, p,
                        zip ? file.substring(0, file.length() - 4) : file, scratch.resolve("unpacked"));
                if (!job.metadata().runId().equals(event.metadata().runId())) {
                    InputException e = new InputException(source, 0, "run_id", InputProblem.INVALID_CONFIGURATION,
                            "run_id of the event must match the bundle's run.yaml (" + job.metadata().runId() + ")",
                            event.metadata().runId());
                    throw new StageException(RunFailure.of(Stage.MANIFEST, e), e);
                }
                return new RunJob(job.metadata(), job.reference(), job.estimate(), job.settings(), source, job.folder());
            }
            Path ref = writeInline(scratch.resolve("reference"), event.reference(), source, "reference");
            Path est = writeInline(scratch.resolve("estimate"), event.estimate(), source, "estimate");
            return new RunJob(event.metadata(), ref, est, event.settings(), source);
        } catch (IOException e) {
            throw new UncheckedIOException("could not write to " + scratch + ": " + e.getMessage(), e);
        }
    }

    private Path writeInline(Path dir, RunEvent.Inline inline, String source, String field) throws IOException {
        byte[] bytes = inline.data().getBytes(StandardCharsets.UTF_8);
        if (bytes.length > limits.maxFileBytes()) {
            InputException e = new InputException(source, 0, field, InputProblem.TOO_LARGE,
                    field + " must be at most " + limits.maxFileBytes() + " bytes", bytes.length + " bytes");
            throw new StageException(RunFailure.of(Stage.UNPACK, e), e);
        }
        Files.createDirectories(dir);
        Path p = dir.resolve(inline.fileName());
        Files.write(p, bytes);
        return p;
    }

    private ProducerRecord<String, String> reportEvent(String key, RunResult result, String source) {
        ObjectNode ev = JSON.createObjectNode();
        ev.put("run_id", result.runId());
        ev.put("run_version", result.version());
        ev.put("report_path", result.report().toString());
        ev.put("source", source);
        try {
            ev.set("report", JSON.readTree(Files.readString(result.report())));
        } catch (IOException e) {
            throw new UncheckedIOException("could not read back " + result.report() + ": " + e.getMessage(), e);
        }
        return new ProducerRecord<>(settings.outputTopic(), key, ev.toString());
    }

    private ProducerRecord<String, String> deadLetter(String key, ConsumerRecord<String, String> r, RunFailure f) {
        ObjectNode ev = JSON.createObjectNode();
        ev.put("stage", f.stage().name().toLowerCase(Locale.ROOT));
        ev.put("kind", f.kind());
        ev.put("message", f.message());
        ev.put("topic", r.topic());
        ev.put("partition", r.partition());
        ev.put("offset", r.offset());
        ev.put("time", clock.instant().toString());
        ev.put("original", r.value());
        ProducerRecord<String, String> out = new ProducerRecord<>(settings.deadLetterTopic(), key, ev.toString());
        out.headers().add("trajeval.reason", f.message().getBytes(StandardCharsets.UTF_8));
        return out;
    }

    private void updateLag(KafkaConsumer<String, String> c) {
        long lag = 0;
        for (TopicPartition tp : c.assignment()) {
            lag += c.currentLag(tp).orElse(0);
        }
        metrics.consumerLag().set(lag);
    }

    private static void deleteTree(Path root) {
        if (!Files.exists(root, LinkOption.NOFOLLOW_LINKS)) {
            return;
        }
        try (var s = Files.walk(root)) {
            for (Path p : (Iterable<Path>) s.sorted(java.util.Comparator.reverseOrder())::iterator) {
                Files.deleteIfExists(p);
            }
        } catch (IOException e) {
            LOG.warn("could not delete {}: {}", root, e.toString());
        }
    }
}
