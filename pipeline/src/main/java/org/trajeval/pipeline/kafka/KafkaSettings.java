package org.trajeval.pipeline.kafka;

import java.nio.file.Path;
import java.time.Duration;
import java.util.List;

/**
 * Resolved settings of one Kafka-mode instance.
 *
 * @param groupId consumer group
 * @param inputTopic run events
 * @param outputTopic report events
 * @param deadLetterTopic refused events
 * @param partitions partitions of a topic the service creates or re-creates
 * @param instanceId stable per instance (the producer's transactional id is groupId + "-" + instanceId)
 * @param bundleBase folder bundle locations are relative to
 * @param scratch this instance's scratch folder
 * @param sessionTimeoutMs consumer session timeout (ms)
 * @param transactionTimeoutMs producer transaction timeout (ms)
 * @param workers records of one poll scored in parallel
 * @param unhealthyAfter how long the broker may be unreachable (or commits fail) before /health says DOWN
 */
public record KafkaSettings(String groupId, String inputTopic, String outputTopic, String deadLetterTopic,
        int partitions, String instanceId, Path bundleBase, Path scratch, int sessionTimeoutMs,
        int transactionTimeoutMs, int workers, Duration unhealthyAfter) {

    /** @return the producer's transactional id: stable across restarts of this instance */
    public String transactionalId() {
        return groupId + "-" + instanceId;
    }

    /** @return the three topics the service reads and writes */
    public List<String> topics() {
        return List.of(inputTopic, outputTopic, deadLetterTopic);
    }
}
