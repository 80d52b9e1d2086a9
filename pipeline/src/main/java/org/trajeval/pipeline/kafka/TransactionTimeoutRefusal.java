package org.trajeval.pipeline.kafka;

import java.util.Collection;
import java.util.List;
import java.util.OptionalLong;
import java.util.concurrent.TimeUnit;
import org.apache.kafka.clients.admin.Admin;
import org.apache.kafka.clients.admin.Config;
import org.apache.kafka.clients.admin.ConfigEntry;
import org.apache.kafka.common.KafkaException;
import org.apache.kafka.common.Node;
import org.apache.kafka.common.config.ConfigResource;
import org.apache.kafka.common.errors.InvalidTxnTimeoutException;
import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;

/**
 * {@code kafka.transaction_timeout_ms} above the broker's {@code transaction.max.timeout.ms}
 * (15 min by default): the broker refuses to start a transaction ({@code InitProducerId} answers
 * {@link InvalidTxnTimeoutException}), so the service cannot work at all. It is a fatal
 * configuration error, refused with one line (exit code 2) naming the value set and the broker's
 * limit, never clamped silently: a shorter timeout than the operator chose would change which
 * outages are ridden out with exactly one report event.
 */
final class TransactionTimeoutRefusal {
    /** The broker setting that caps the transaction timeout. */
    static final String BROKER_LIMIT = "transaction.max.timeout.ms";
    private static final long ADMIN_WAIT_S = 10;

    private TransactionTimeoutRefusal() {
    }

    /**
     * @return true when {@code e} or one of its causes says the transaction timeout is over the
     *     broker's limit. The Kafka 4 producer does not surface {@link InvalidTxnTimeoutException}
     *     from {@code initTransactions}: it wraps the broker's error in a plain
     *     {@code KafkaException("Unexpected error in InitProducerIdResponse; The transaction timeout
     *     is larger than the maximum value allowed by the broker (as configured by
     *     transaction.max.timeout.ms).")}, so the broker's text, which names the setting, is the
     *     only sign (checked by {@code TransactionTimeoutLimitTest} against a real broker).
     */
    static boolean isCause(Throwable e) {
        for (Throwable t = e; t != null; t = t.getCause()) {
            if (t instanceof InvalidTxnTimeoutException
                    || t.getMessage() != null && t.getMessage().contains(BROKER_LIMIT)) {
                return true;
            }
        }
        return false;
    }

    /**
     * @param timeoutMs the configured transaction timeout (ms)
     * @param clients the clients (to ask the broker for its limit, best effort)
     * @param cause the broker's refusal
     * @return the one-line refusal (bad configuration: exit code 2)
     */
    static InputException of(int timeoutMs, KafkaClients clients, Throwable cause) {
        OptionalLong limit = brokerLimitMs(clients);
        String allowed = limit.isPresent() ? BROKER_LIMIT + " = " + limit.getAsLong() + " ms"
                : BROKER_LIMIT + ", 900000 ms (15 min) by default";
        return new InputException("kafka.transaction_timeout_ms", 0, "kafka.transaction_timeout_ms",
                InputProblem.INVALID_CONFIGURATION, "must not exceed the limit of the broker "
                        + clients.bootstrapServers() + " (" + allowed + "); lower it or raise the broker's "
                        + BROKER_LIMIT, timeoutMs + " ms", cause);
    }

    /** @return the broker's {@code transaction.max.timeout.ms} (ms), or empty when it cannot be read */
    private static OptionalLong brokerLimitMs(KafkaClients clients) {
        try (Admin admin = clients.admin()) {
            Collection<Node> nodes = admin.describeCluster().nodes().get(ADMIN_WAIT_S, TimeUnit.SECONDS);
            if (nodes.isEmpty()) {
                return OptionalLong.empty();
            }
            ConfigResource broker = new ConfigResource(ConfigResource.Type.BROKER, nodes.iterator().next().idString());
            Config c = admin.describeConfigs(List.of(broker)).all().get(ADMIN_WAIT_S, TimeUnit.SECONDS).get(broker);
            ConfigEntry e = c == null ? null : c.get(BROKER_LIMIT);
            return e == null || e.value() == null ? OptionalLong.empty() : OptionalLong.of(Long.parseLong(e.value()));
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return OptionalLong.empty();
        } catch (java.util.concurrent.ExecutionException | java.util.concurrent.TimeoutException | KafkaException
                | NumberFormatException e) {
            return OptionalLong.empty(); // not allowed to describe the broker's configuration: the default is named
        }
    }
}
