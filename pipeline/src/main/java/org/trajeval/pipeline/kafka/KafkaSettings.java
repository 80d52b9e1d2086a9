package org.trajeval.pipeline.kafka;

import java.nio.file.Path;

/**
 * Resolved settings of one Kafka-mode instance.
 *
 * @param bootstrapServers host:port list
 * @param groupId consumer group
 * @param inputTopic run events
 * @param outputTopic report events
 * @param deadLetterTopic refused events
 * @param instanceId unique per instance (the producer's transactional id is groupId + "-" + instanceId)
 * @param bundleBase folder bundle locations are relative to
 * @param scratch this instance's scratch folder
 * @param sessionTimeoutMs consumer session timeout (ms)
 * @param transactionTimeoutMs producer transaction timeout (ms)
 * @param workers records of one poll scored in parallel
 */
public record KafkaSettings(String bootstrapServers, String groupId, String inputTopic, String outputTopic,
        String deadLetterTopic, String instanceId, Path bundleBase, Path scratch, int sessionTimeoutMs,
        int transactionTimeoutMs, int workers) {
}
