package org.trajeval.pipeline;

import java.nio.file.Path;
import java.time.Duration;
import java.util.Locale;
import org.trajeval.pipeline.bundle.BundleLimits;
import org.trajeval.pipeline.dir.Completion;
import org.trajeval.pipeline.dir.DirectoryOptions;

/**
 * The service's settings, read from a YAML file (keys as below, snake_case), then environment
 * variables {@code TRAJEVAL_PIPELINE_<KEY>} (nested keys joined by '_', e.g.
 * {@code TRAJEVAL_PIPELINE_KAFKA_BOOTSTRAP_SERVERS}), then command-line options. See
 * {@link ConfigLoader}.
 *
 * @param root the service's root folder (incoming/, processing/, done/, failed/, reports/, ledger/)
 * @param workers threads scoring runs in parallel
 * @param queueCapacity bundles claimed ahead of the workers
 * @param completion marker or marker_or_quiet
 * @param quietTimeS quiet time before a bundle without marker counts as complete (s)
 * @param scanIntervalS pause between scans of an idle incoming/ (s)
 * @param logFormat text or json
 * @param limits bundle size limits
 * @param http metrics and health endpoint
 * @param kafka Kafka mode settings
 * @param store the results store every committed report is also recorded in
 * @param bags how bare bags (a bag file dropped alone, or named by a run event) are scored
 */
public record PipelineConfig(String root, int workers, int queueCapacity, String completion, double quietTimeS,
        double scanIntervalS, String logFormat, Limits limits, Http http, Kafka kafka, Store store, Bags bags) {

    /**
     * @param metrics the settings of bare bags: any key of the core settings table, as under a
     *     run.yaml's {@code metrics}; {@code ref_topic} and {@code est_topic} (a topic, or a TF
     *     trajectory {@code /tf:PARENT.CHILD}) are needed before a bare bag can be scored
     */
    public record Bags(java.util.Map<String, Object> metrics) {
        /** Key path of the free-form settings mapping in the configuration. */
        public static final String METRICS_KEY = "bags.metrics";
    }

    /**
     * @return the checked settings of bare bags ({@code SettingValues.DEFAULTS} when none are given)
     * @throws org.trajeval.core.InputException naming the key on an unknown setting or a bad value
     */
    public org.trajeval.core.options.SettingValues bagSettings() {
        if (bags == null || bags.metrics() == null || bags.metrics().isEmpty()) {
            return org.trajeval.core.options.SettingValues.DEFAULTS;
        }
        return org.trajeval.core.options.SettingValues.of(org.trajeval.core.options.SettingsTree.flatten(
                bags.metrics(), Bags.METRICS_KEY, "configuration"), "configuration");
    }

    /**
     * @param db SQLite file or JDBC URL ({@code jdbc:sqlite:}, {@code jdbc:postgresql:}); empty:
     *     ROOT/trajeval.db; {@code none}: no store. Credentials from TRAJEVAL_DB_USER and
     *     TRAJEVAL_DB_PASSWORD or TRAJEVAL_DB_PASSWORD_FILE, never here
     * @param retryIntervalS pause between attempts to replay the backlog while the store is down (s)
     */
    public record Store(String db, double retryIntervalS) {
    }

    /**
     * @param maxFileBytes largest trajectory or manifest file (bytes)
     * @param maxUnzippedBytes largest total extracted from one zip (bytes)
     * @param maxZipEntries most entries in one zip
     * @param maxCompressionRatio largest extracted/zip size ratio
     */
    public record Limits(long maxFileBytes, long maxUnzippedBytes, int maxZipEntries, double maxCompressionRatio) {
    }

    /**
     * @param enabled serve /metrics and /health
     * @param host address to bind
     * @param port port (0: a free one)
     */
    public record Http(boolean enabled, String host, int port) {
    }

    /**
     * @param bootstrapServers host:port list of the cluster
     * @param groupId consumer group shared by every instance
     * @param inputTopic topic of run events
     * @param outputTopic topic of report events
     * @param deadLetterTopic topic of refused events with their reason
     * @param partitions partitions of the topics when the service creates (or re-creates) them
     * @param bundleBase folder that bundle locations in events are relative to (and must stay in)
     * @param sessionTimeoutMs consumer session timeout (ms): how soon a dead instance's partitions move
     * @param transactionTimeoutMs producer transaction timeout (ms): the longest broker outage a
     *     transaction rides out; capped by the broker's {@code transaction.max.timeout.ms} (15 min by default)
     * @param instanceId this instance's id (transactional id suffix); empty: the id persisted in
     *     ROOT/kafka-instances/ (one slot per running instance sharing the root)
     * @param unhealthyAfterS how long the broker may be unreachable, or commits fail, before
     *     /health answers 503 (s)
     * @param startupTimeoutS how long start-up waits for the broker before exiting with code 5 (s); 0: forever
     * @param clientProperties a Kafka client properties file applied to every Kafka client (what
     *     Kafka's tools take with --command-config; config providers work); empty: none
     * @param security typed shortcuts for the common secured connections
     */
    public record Kafka(String bootstrapServers, String groupId, String inputTopic, String outputTopic,
            String deadLetterTopic, int partitions, String bundleBase, int sessionTimeoutMs, int transactionTimeoutMs,
            String instanceId, double unhealthyAfterS, double startupTimeoutS, String clientProperties,
            Security security) {
    }

    /**
     * Shortcuts for TLS and SASL; each secret is a reference, {@code env:VARIABLE} or
     * {@code file:PATH} (the whole file, trailing newline dropped), never the secret itself.
     *
     * @param protocol security.protocol: PLAINTEXT, SSL, SASL_PLAINTEXT or SASL_SSL; empty: as the properties file says
     * @param saslMechanism PLAIN, SCRAM-SHA-256 or SCRAM-SHA-512; empty: none
     * @param saslUsername SASL user name
     * @param saslPassword reference to the SASL password
     * @param truststore truststore file (PKCS12, JKS or PEM, by extension): the CA that signed the broker's certificate
     * @param truststorePassword reference to the truststore's password (empty for PEM)
     * @param keystore keystore file for mutual TLS: this client's certificate and key
     * @param keystorePassword reference to the keystore's (and its key's) password
     */
    public record Security(String protocol, String saslMechanism, String saslUsername, String saslPassword,
            String truststore, String truststorePassword, String keystore, String keystorePassword) {
    }

    /** @return the defaults */
    public static PipelineConfig defaults() {
        return new PipelineConfig("pipeline-data", 2, 2, "marker", 60, 1, "text",
                new Limits(BundleLimits.DEFAULTS.maxFileBytes(), BundleLimits.DEFAULTS.maxUnzippedBytes(),
                        BundleLimits.DEFAULTS.maxZipEntries(), BundleLimits.DEFAULTS.maxCompressionRatio()),
                new Http(true, "127.0.0.1", 9464),
                new Kafka("127.0.0.1:9092", "trajeval-pipeline", "trajeval.runs", "trajeval.reports",
                        "trajeval.runs.dlq", 3, "", 10_000, 300_000, "", 60, 0, "",
                        new Security("", "", "", "", "", "", "", "")),
                new Store("", 10), new Bags(java.util.Map.of()));
    }

    /** @return the root folder */
    public Path rootPath() {
        return Path.of(root);
    }

    /** @return the bundle limits */
    public BundleLimits bundleLimits() {
        return new BundleLimits(limits.maxFileBytes(), limits.maxUnzippedBytes(), limits.maxZipEntries(),
                limits.maxCompressionRatio());
    }

    /** @return the directory mode options */
    public DirectoryOptions directoryOptions() {
        Completion c;
        try {
            c = Completion.valueOf(completion.trim().toUpperCase(Locale.ROOT));
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException("completion must be marker or marker_or_quiet, found \"" + completion + "\"");
        }
        return new DirectoryOptions(workers, queueCapacity, c, Duration.ofMillis(Math.round(quietTimeS * 1000)),
                Duration.ofMillis(Math.max(1, Math.round(scanIntervalS * 1000))));
    }
}
