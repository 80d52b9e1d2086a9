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
import java.time.Instant;
import java.util.Optional;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import org.apache.kafka.common.errors.AuthenticationException;
import org.apache.kafka.common.errors.AuthorizationException;
import org.apache.kafka.common.errors.InvalidPidMappingException;
import org.apache.kafka.common.errors.InvalidProducerEpochException;
import org.apache.kafka.common.errors.InvalidTxnStateException;
import org.apache.kafka.common.errors.OutOfOrderSequenceException;
import org.apache.kafka.common.errors.ProducerFencedException;
import org.apache.kafka.common.errors.TimeoutException;
import org.apache.kafka.common.errors.UnknownProducerIdException;
import org.apache.kafka.common.errors.UnsupportedVersionException;
import org.trajeval.pipeline.ledger.LedgerEntry;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;
import org.trajeval.pipeline.Outcome;
import org.trajeval.pipeline.EnvironmentException;
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
 *
 * <p>Broker faults never end the loop (the shape of Apache Kafka's
 * {@code ExactlyOnceMessageProcessor} example): a commit that times out is retried while the
 * transaction may stay open; an abortable error aborts the transaction and rewinds the consumer
 * to the batch's first offsets; a fatal producer error (fenced, invalid producer id mapping,
 * out-of-order sequence, a timed-out transaction) closes the producer and builds a new one with
 * the same transactional id, which fences the old one and aborts its transaction, then rewinds.
 * Only {@link #stop()} or a broker refusing this client ({@link BrokerFailure}) ends it. When the
 * broker has lost the output topic ({@link BrokerWatch#republishNeeded()}), every report in the
 * ledger is published again.
 */
public final class KafkaService {
    private static final Logger LOG = LoggerFactory.getLogger(KafkaService.class);
    private static final ObjectMapper JSON = new ObjectMapper();
    private static final int REPUBLISH_CHUNK = 200;
    private static final long MAX_PAUSE_S = 30;

    private final KafkaSettings settings;
    private final KafkaClients clients;
    private final RunProcessor processor;
    private final Republisher republisher;
    private final BundleOpener opener;
    private final BundleLimits limits;
    private final PipelineMetrics metrics;
    private final BrokerWatch watch;
    private final Clock clock;
    private final CountDownLatch stopSignal = new CountDownLatch(1);
    private volatile boolean stopping;
    private volatile boolean running;
    private volatile KafkaConsumer<String, String> consumer;
    private KafkaProducer<String, String> producer;

    /**
     * @param settings topics, group, folders
     * @param clients builds the Kafka clients
     * @param processor scores and files runs
     * @param republisher re-builds report events from the ledger
     * @param limits bundle limits
     * @param metrics where to count
     * @param watch broker health, commit state and lost topics
     * @param clock clock for dead-letter records
     */
    public KafkaService(KafkaSettings settings, KafkaClients clients, RunProcessor processor, Republisher republisher,
            BundleLimits limits, PipelineMetrics metrics, BrokerWatch watch, Clock clock) {
        this(settings, clients, processor, republisher, limits, metrics, watch, clock,
                org.trajeval.core.options.SettingValues.DEFAULTS);
    }

    /**
     * As above, with the settings bare bags named by events are scored with (the configuration's
     * {@code bags.metrics}).
     */
    public KafkaService(KafkaSettings settings, KafkaClients clients, RunProcessor processor, Republisher republisher,
            BundleLimits limits, PipelineMetrics metrics, BrokerWatch watch, Clock clock,
            org.trajeval.core.options.SettingValues bagSettings) {
        this.settings = settings;
        this.clients = clients;
        this.processor = processor;
        this.republisher = republisher;
        this.limits = limits;
        this.opener = new BundleOpener(limits, bagSettings);
        this.metrics = metrics;
        this.watch = watch;
        this.clock = clock;
    }

    /** Stops the loop after the current transaction. */
    public void stop() {
        stopping = true;
        stopSignal.countDown();
        KafkaConsumer<String, String> c = consumer;
        if (c != null) {
            c.wakeup();
        }
    }

    /** @return true while consuming */
    public boolean isRunning() {
        return running && !stopping;
    }

    /**
     * Consumes until {@link #stop()}.
     *
     * @throws BrokerFailure when the broker refuses this client (credentials, TLS, ACLs)
     * @throws InputException when {@code kafka.transaction_timeout_ms} is over the broker's
     *     {@code transaction.max.timeout.ms} (a fatal configuration error: exit code 2)
     */
    public void run() {
        ExecutorService pool = Executors.newFixedThreadPool(settings.workers(), r -> new Thread(r, "trajeval-kafka-worker"));
        try (KafkaConsumer<String, String> c = clients.serviceConsumer(settings)) {
            consumer = c;
            if (stopping) {
                return;
            }
            c.subscribe(List.of(settings.inputTopic()));
            running = true;
            while (!stopping) {
                if (producer == null && !buildProducer()) {
                    break;
                }
                Optional<String> lostTopic = watch.republishNeeded();
                if (lostTopic.isPresent()) {
                    republishAll(lostTopic.get());
                    continue;
                }
                ConsumerRecords<String, String> records;
                try {
                    records = c.poll(Duration.ofMillis(500));
                } catch (WakeupException e) {
                    continue;
                } catch (AuthenticationException | AuthorizationException e) {
                    throw refused(e);
                } catch (KafkaException e) {
                    LOG.warn("poll failed ({}); retrying in 1 s", BrokerMessages.shortReason(e));
                    pause(1);
                    continue;
                }
                updateLag(c);
                if (!records.isEmpty()) {
                    processBatch(c, pool, records);
                }
            }
        } finally {
            running = false;
            consumer = null;
            closeProducer();
            pool.shutdown();
        }
    }

    /** Builds the transactional producer, waiting with back-off while the broker is away. @return false when stopped */
    private boolean buildProducer() {
        for (int attempt = 0; !stopping; attempt++) {
            KafkaProducer<String, String> p = null;
            try {
                p = clients.serviceProducer(settings);
                p.initTransactions();
                producer = p;
                if (attempt > 0) {
                    LOG.info("producer {} ready again", settings.transactionalId());
                }
                return true;
            } catch (AuthenticationException | AuthorizationException e) {
                close(p);
                throw refused(e);
            } catch (KafkaException | IllegalStateException e) {
                close(p);
                if (TransactionTimeoutRefusal.isCause(e)) {
                    throw TransactionTimeoutRefusal.of(settings.transactionTimeoutMs(), clients, e);
                }
                if (attempt == 0) {
                    LOG.warn("producer {} cannot start a transaction yet ({}); retrying", settings.transactionalId(),
                            BrokerMessages.shortReason(e));
                }
                pause(Math.min(MAX_PAUSE_S, 1L << Math.min(attempt, 5)));
            }
        }
        return false;
    }

    private void processBatch(KafkaConsumer<String, String> c, ExecutorService pool,
            ConsumerRecords<String, String> records) {
        List<ProducerRecord<String, String>> out;
        try {
            out = score(pool, records);
        } catch (ExecutionException e) {
            LOG.error("internal error while scoring a batch of {} records; it will be delivered again", records.count(),
                    e.getCause());
            rewind(c, records);
            pause(1);
            return;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            rewind(c, records);
            return;
        }
        metrics.runsHeld().set(records.count());
        try {
            producer.beginTransaction();
            for (ProducerRecord<String, String> r : out) {
                producer.send(r);
            }
            producer.sendOffsetsToTransaction(offsets(records), c.groupMetadata());
            commit();
            watch.commitSucceeded();
            metrics.runsHeld().set(0);
        } catch (AuthenticationException | AuthorizationException e) {
            closeProducer();
            rewind(c, records);
            throw refused(e);
        } catch (KafkaException | IllegalStateException e) {
            watch.commitFailed(BrokerMessages.shortReason(e));
            recover(e, records.count());
            rewind(c, records);
        }
    }

    /** Commits, retrying a commit that timed out (the transaction stays open on the broker) until stopped. */
    private void commit() {
        while (true) {
            try {
                producer.commitTransaction();
                return;
            } catch (TimeoutException e) {
                watch.commitFailed("commit timed out: " + BrokerMessages.shortReason(e));
                if (stopping) {
                    throw e;
                }
            }
        }
    }

    /** Aborts the transaction, or re-creates the producer when it cannot go on. */
    private void recover(RuntimeException e, int records) {
        if (isFatal(e)) {
            LOG.warn("producer {} cannot go on ({}): re-creating it; {} records will be delivered again",
                    settings.transactionalId(), BrokerMessages.shortReason(e), records);
            rebuildProducer();
            return;
        }
        try {
            producer.abortTransaction();
            LOG.warn("transaction aborted ({}); {} records will be delivered again", BrokerMessages.shortReason(e), records);
        } catch (KafkaException | IllegalStateException abortFailed) {
            LOG.warn("transaction failed ({}) and could not be aborted ({}): re-creating producer {}; {} records will "
                    + "be delivered again", BrokerMessages.shortReason(e), BrokerMessages.shortReason(abortFailed),
                    settings.transactionalId(), records);
            rebuildProducer();
        }
    }

    private static boolean isFatal(Throwable e) {
        for (Throwable t = e; t != null; t = t.getCause()) {
            if (t instanceof ProducerFencedException || t instanceof InvalidProducerEpochException
                    || t instanceof OutOfOrderSequenceException || t instanceof InvalidPidMappingException
                    || t instanceof UnknownProducerIdException || t instanceof UnsupportedVersionException
                    || t instanceof InvalidTxnStateException || t instanceof IllegalStateException) {
                return true;
            }
        }
        return false;
    }

    private void rebuildProducer() {
        closeProducer();
        metrics.producerRebuilds().increment();
    }

    private void closeProducer() {
        close(producer);
        producer = null;
    }

    private static void close(KafkaProducer<String, String> p) {
        if (p != null) {
            try {
                p.close(Duration.ZERO);
            } catch (KafkaException ignored) {
                // closing a broken producer: nothing left to save
            }
        }
    }

    private BrokerFailure refused(KafkaException e) {
        String message = BrokerMessages.refused(clients, e);
        watch.refused(message);
        return new BrokerFailure(BrokerFailure.Kind.REFUSED, clients.bootstrapServers(), message);
    }

    /** Publishes every report in the ledger again, in transactions of {@link #REPUBLISH_CHUNK}. */
    private void republishAll(String topicId) {
        // the broker that lost the topic may have lost this producer's id too: start afresh
        closeProducer();
        if (!buildProducer()) {
            return;
        }
        List<LedgerEntry> entries = republisher.entriesSince(Instant.EPOCH);
        LOG.warn("re-publishing {} report events from the ledger to {}", entries.size(), settings.outputTopic());
        int sent = 0;
        try {
            for (int i = 0; i < entries.size() && !stopping; i += REPUBLISH_CHUNK) {
                producer.beginTransaction();
                int n = 0;
                for (LedgerEntry e : entries.subList(i, Math.min(entries.size(), i + REPUBLISH_CHUNK))) {
                    ProducerRecord<String, String> r = republisher.event(e);
                    if (r != null) {
                        producer.send(r);
                        n++;
                    }
                }
                commit();
                watch.commitSucceeded();
                metrics.republished().increment(n);
                sent += n;
            }
        } catch (AuthenticationException | AuthorizationException e) {
            throw refused(e);
        } catch (KafkaException | IllegalStateException e) {
            watch.commitFailed(BrokerMessages.shortReason(e));
            recover(e, 0);
            pause(1);
            return;
        }
        if (!stopping) {
            watch.republished(topicId);
            LOG.info("re-published {} report events to {}", sent, settings.outputTopic());
        }
    }

    private List<ProducerRecord<String, String>> score(ExecutorService pool, ConsumerRecords<String, String> records)
            throws ExecutionException, InterruptedException {
        List<Future<List<ProducerRecord<String, String>>>> futures = new ArrayList<>();
        for (ConsumerRecord<String, String> r : records) {
            futures.add(pool.submit(() -> handle(r)));
        }
        List<ProducerRecord<String, String>> out = new ArrayList<>();
        for (Future<List<ProducerRecord<String, String>>> f : futures) {
            out.addAll(f.get());
        }
        return out;
    }

    private static Map<TopicPartition, OffsetAndMetadata> offsets(ConsumerRecords<String, String> records) {
        Map<TopicPartition, OffsetAndMetadata> offsets = new HashMap<>();
        for (TopicPartition tp : records.partitions()) {
            List<ConsumerRecord<String, String>> rs = records.records(tp);
            offsets.put(tp, new OffsetAndMetadata(rs.get(rs.size() - 1).offset() + 1));
        }
        return offsets;
    }

    /** Seeks back to the batch's first offsets: they follow the last committed ones. */
    private static void rewind(KafkaConsumer<String, String> c, ConsumerRecords<String, String> records) {
        for (TopicPartition tp : records.partitions()) {
            if (c.assignment().contains(tp)) {
                c.seek(tp, records.records(tp).get(0).offset());
            }
        }
    }

    private void pause(long seconds) {
        try {
            stopSignal.await(seconds, TimeUnit.SECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            stopping = true;
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
        } catch (EnvironmentException e) {
            throw e; // our disk or folders failed, not the event: the batch is aborted and delivered again
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
                yield List.of(ReportEvents.of(settings.outputTopic(), result.report(), source, false));
            }
            case DUPLICATE -> {
                if (source.equals(result.firstSource())) {
                    // delivered again after an aborted transaction: publish its report event again
                    LOG.info("re-delivered run_id={} source={}", result.runId(), source);
                    yield List.of(ReportEvents.of(settings.outputTopic(), result.report(), source, false));
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
                if (org.trajeval.pipeline.bundle.BareBag.stem(file) != null
                        && Files.isRegularFile(p, LinkOption.NOFOLLOW_LINKS)) {
                    // a bare bag: the event's identity, the configured bags.metrics
                    return opener.openBag(p, event.metadata(), source);
                }
                boolean zip = file.endsWith(".zip") && Files.isRegularFile(p, LinkOption.NOFOLLOW_LINKS);
                RunJob job = opener.open(zip ? BundleKind.ZIP : BundleKind.FOLDER, p,
                        zip ? file.substring(0, file.length() - 4) : file, scratch.resolve("unpacked"));
                if (!job.metadata().runId().equals(event.metadata().runId())) {
                    InputException e = new InputException(source, 0, "run_id", InputProblem.INVALID_CONFIGURATION,
                            "run_id of the event must match the bundle's run.yaml (" + job.metadata().runId() + ")",
                            event.metadata().runId());
                    throw new StageException(RunFailure.of(Stage.MANIFEST, e), e);
                }
                return new RunJob(job.metadata(), job.reference(), job.estimate(), job.settings(), source, job.folder(),
                        job.plot());
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
