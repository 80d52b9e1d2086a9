package org.trajeval.pipeline.kafka;

import java.util.LinkedHashMap;
import java.util.Map;
import java.util.Properties;
import org.apache.kafka.clients.admin.Admin;
import org.apache.kafka.clients.consumer.KafkaConsumer;
import org.apache.kafka.clients.producer.KafkaProducer;
import org.apache.kafka.common.serialization.StringDeserializer;
import org.apache.kafka.common.serialization.StringSerializer;
import org.trajeval.pipeline.PipelineConfig;

/**
 * Builds every Kafka client of the service and its subcommands (consumer, producers, admin) from
 * one place: the bootstrap address, the operator's client settings (security, timeouts), then
 * the service's own settings, which always win.
 */
public final class KafkaClients {
    /** Retry and blocking times short enough that an outage is noticed and SIGTERM is prompt (ms). */
    static final int MAX_BLOCK_MS = 10_000;
    static final int ADMIN_TIMEOUT_MS = 5_000;

    private final String bootstrapServers;
    private final ClientSettings client;
    private final Map<String, String> common;

    /**
     * @param bootstrapServers host:port list
     * @param client client settings applied to every client (security protocol, SASL, TLS ...)
     */
    public KafkaClients(String bootstrapServers, ClientSettings client) {
        this.bootstrapServers = bootstrapServers;
        this.client = client;
        this.common = client.settings();
    }

    /**
     * @return the clients of a configuration
     * @throws org.trajeval.core.InputException on bad client settings (see {@link ClientSettings#of})
     */
    public static KafkaClients of(PipelineConfig.Kafka k, Map<String, String> env) {
        return new KafkaClients(k.bootstrapServers(), ClientSettings.of(k, env));
    }

    /** @return {@code text} with every known secret masked */
    public String scrub(String text) {
        return client.scrub(text);
    }

    /** @return the bootstrap address (for messages) */
    public String bootstrapServers() {
        return bootstrapServers;
    }

    /** @return "security protocol, mechanism, user" as configured (never a secret), for messages */
    public String identity() {
        String protocol = common.getOrDefault("security.protocol", "PLAINTEXT");
        StringBuilder b = new StringBuilder("security protocol " + protocol);
        if (common.containsKey("sasl.mechanism")) {
            b.append(", mechanism ").append(common.get("sasl.mechanism"));
        }
        String user = SaslUser.of(common.get("sasl.jaas.config"));
        if (user != null) {
            b.append(", user '").append(user).append('\'');
        }
        return b.toString();
    }

    private Properties base() {
        Properties p = new Properties();
        p.putAll(common);
        p.put("bootstrap.servers", bootstrapServers);
        return p;
    }

    /** @return the service's consumer: read_committed, manual offsets inside transactions */
    public KafkaConsumer<String, String> serviceConsumer(KafkaSettings s) {
        Properties p = base();
        p.put("group.id", s.groupId());
        p.put("enable.auto.commit", "false");
        p.put("isolation.level", "read_committed");
        p.put("auto.offset.reset", "earliest");
        p.put("max.poll.records", "20");
        p.put("session.timeout.ms", String.valueOf(s.sessionTimeoutMs()));
        p.put("heartbeat.interval.ms", String.valueOf(Math.max(100, s.sessionTimeoutMs() / 4)));
        p.put("client.id", "trajeval-" + s.instanceId());
        return new KafkaConsumer<>(p, new StringDeserializer(), new StringDeserializer());
    }

    /**
     * @return the service's transactional producer: records wait for the broker as long as the
     *     transaction may stay open; blocking calls give up after {@link #MAX_BLOCK_MS}
     */
    public KafkaProducer<String, String> serviceProducer(KafkaSettings s) {
        Properties p = base();
        p.put("transactional.id", s.transactionalId());
        p.put("enable.idempotence", "true");
        p.put("acks", "all");
        p.put("transaction.timeout.ms", String.valueOf(s.transactionTimeoutMs()));
        p.put("delivery.timeout.ms", String.valueOf(Math.max(s.transactionTimeoutMs(), 40_000)));
        p.put("max.block.ms", String.valueOf(MAX_BLOCK_MS));
        p.put("client.id", "trajeval-" + s.instanceId() + "-producer");
        return new KafkaProducer<>(p, new StringSerializer(), new StringSerializer());
    }

    /** @return a plain idempotent producer (send, republish) */
    public KafkaProducer<String, String> plainProducer() {
        Properties p = base();
        p.put("acks", "all");
        p.put("enable.idempotence", "true");
        return new KafkaProducer<>(p, new StringSerializer(), new StringSerializer());
    }

    /** @return a read_committed consumer without a group (tail) */
    public KafkaConsumer<String, String> readerConsumer() {
        Properties p = base();
        p.put("isolation.level", "read_committed");
        p.put("enable.auto.commit", "false");
        return new KafkaConsumer<>(p, new StringDeserializer(), new StringDeserializer());
    }

    /** @return an admin client with short timeouts (health checks, topics) */
    public Admin admin() {
        Map<String, Object> p = new LinkedHashMap<>();
        base().forEach((k, v) -> p.put((String) k, v));
        p.put("request.timeout.ms", String.valueOf(ADMIN_TIMEOUT_MS));
        p.put("default.api.timeout.ms", String.valueOf(ADMIN_TIMEOUT_MS));
        p.put("client.id", "trajeval-admin");
        return Admin.create(p);
    }
}
