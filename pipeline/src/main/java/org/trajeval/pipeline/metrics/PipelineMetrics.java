package org.trajeval.pipeline.metrics;

import io.micrometer.core.instrument.Counter;
import io.micrometer.core.instrument.Gauge;
import io.micrometer.core.instrument.MeterRegistry;
import io.micrometer.core.instrument.Timer;
import io.micrometer.core.instrument.simple.SimpleMeterRegistry;
import io.micrometer.prometheusmetrics.PrometheusConfig;
import io.micrometer.prometheusmetrics.PrometheusMeterRegistry;
import java.time.Duration;
import java.util.EnumMap;
import java.util.Map;
import java.util.concurrent.atomic.AtomicLong;
import org.trajeval.pipeline.Outcome;

/**
 * The service's metrics (Micrometer; Prometheus names in brackets):
 * runs processed by outcome [{@code trajeval_pipeline_runs_total{outcome=reported|duplicate|failed}}],
 * processing time per run [{@code trajeval_pipeline_run_duration_seconds} histogram], complete
 * bundles waiting in incoming/ [{@code trajeval_pipeline_queue_depth}], bundles claimed and not
 * finished [{@code trajeval_pipeline_in_processing}], Kafka consumer lag in records
 * [{@code trajeval_pipeline_consumer_lag}]; Kafka mode: whether the broker answers
 * [{@code trajeval_pipeline_broker_reachable} 1 or 0], seconds since the last committed
 * transaction [{@code trajeval_pipeline_last_commit_age_seconds}, NaN before the first], runs
 * scored and waiting for their commit [{@code trajeval_pipeline_runs_held}], producers re-created
 * after a broker fault [{@code trajeval_pipeline_producer_rebuilds_total}], report events
 * re-published from the ledger [{@code trajeval_pipeline_republished_total}]; committed reports not
 * yet in the results store [{@code trajeval_pipeline_store_lag}].
 */
public final class PipelineMetrics {
    private final MeterRegistry registry;
    private final PrometheusMeterRegistry prometheus;
    private final Map<Outcome, Counter> runs = new EnumMap<>(Outcome.class);
    private final Timer duration;
    private final AtomicLong queueDepth = new AtomicLong();
    private final AtomicLong inProcessing = new AtomicLong();
    private final AtomicLong consumerLag = new AtomicLong();
    private final AtomicLong brokerReachable = new AtomicLong();
    private final AtomicLong lastCommitMillis = new AtomicLong();
    private final AtomicLong runsHeld = new AtomicLong();
    private final Counter producerRebuilds;
    private final Counter republished;
    private final AtomicLong storeLag = new AtomicLong();

    private PipelineMetrics(MeterRegistry registry, PrometheusMeterRegistry prometheus) {
        this.registry = registry;
        this.prometheus = prometheus;
        for (Outcome o : Outcome.values()) {
            runs.put(o, Counter.builder("trajeval.pipeline.runs").description("runs processed, by outcome")
                    .tag("outcome", o.label()).register(registry));
        }
        duration = Timer.builder("trajeval.pipeline.run.duration").description("time to process one run")
                .publishPercentileHistogram().minimumExpectedValue(Duration.ofMillis(1))
                .maximumExpectedValue(Duration.ofMinutes(5)).register(registry);
        Gauge.builder("trajeval.pipeline.queue.depth", queueDepth, AtomicLong::get)
                .description("complete bundles waiting in incoming/").register(registry);
        Gauge.builder("trajeval.pipeline.in.processing", inProcessing, AtomicLong::get)
                .description("bundles claimed and not finished").register(registry);
        Gauge.builder("trajeval.pipeline.consumer.lag", consumerLag, AtomicLong::get)
                .description("records behind the end of the input topic (Kafka mode)").register(registry);
        Gauge.builder("trajeval.pipeline.broker.reachable", brokerReachable, AtomicLong::get)
                .description("1 when the Kafka broker answered the last check, else 0").register(registry);
        Gauge.builder("trajeval.pipeline.last.commit.age", lastCommitMillis,
                        t -> t.get() == 0 ? Double.NaN : (System.currentTimeMillis() - t.get()) / 1000.0)
                .baseUnit("seconds").description("time since the last committed Kafka transaction").register(registry);
        Gauge.builder("trajeval.pipeline.runs.held", runsHeld, AtomicLong::get)
                .description("runs scored and waiting for their Kafka commit").register(registry);
        producerRebuilds = Counter.builder("trajeval.pipeline.producer.rebuilds")
                .description("transactional producers re-created after a broker fault").register(registry);
        republished = Counter.builder("trajeval.pipeline.republished")
                .description("report events re-published from the ledger").register(registry);
        Gauge.builder("trajeval.pipeline.store.lag", storeLag, AtomicLong::get)
                .description("committed reports not yet recorded in the results store").register(registry);
    }

    /** @return metrics exposed in the Prometheus text format */
    public static PipelineMetrics prometheus() {
        PrometheusMeterRegistry r = new PrometheusMeterRegistry(PrometheusConfig.DEFAULT);
        return new PipelineMetrics(r, r);
    }

    /** @return metrics kept in memory only (tests, and a service whose metrics no endpoint serves) */
    public static PipelineMetrics inMemory() {
        return new PipelineMetrics(new SimpleMeterRegistry(), null);
    }

    /** Counts one run and its processing time. */
    public void recordRun(Outcome outcome, Duration took) {
        runs.get(outcome).increment();
        duration.record(took);
    }

    /** @return runs counted with this outcome */
    public long runs(Outcome outcome) {
        return (long) runs.get(outcome).count();
    }

    /** @return the gauge of complete bundles waiting */
    public AtomicLong queueDepth() {
        return queueDepth;
    }

    /** @return the gauge of bundles in processing */
    public AtomicLong inProcessing() {
        return inProcessing;
    }

    /** @return the gauge of consumer lag (records) */
    public AtomicLong consumerLag() {
        return consumerLag;
    }

    /** @return the gauge of broker reachability (1 or 0) */
    public AtomicLong brokerReachable() {
        return brokerReachable;
    }

    /** @return the time of the last committed transaction (ms since the epoch; 0: none yet) */
    public AtomicLong lastCommitMillis() {
        return lastCommitMillis;
    }

    /** @return the gauge of runs waiting for their commit */
    public AtomicLong runsHeld() {
        return runsHeld;
    }

    /** @return the counter of re-created producers */
    public Counter producerRebuilds() {
        return producerRebuilds;
    }

    /** @return the counter of re-published report events */
    public Counter republished() {
        return republished;
    }

    /** @return the gauge of committed reports not yet in the results store */
    public AtomicLong storeLag() {
        return storeLag;
    }

    /** @return the Prometheus text exposition, or an empty string when not Prometheus-backed */
    public String scrape() {
        return prometheus == null ? "" : prometheus.scrape();
    }

    /** @return the underlying registry */
    public MeterRegistry registry() {
        return registry;
    }
}
