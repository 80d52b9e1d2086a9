package org.trajeval.pipeline.kafka;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.channels.FileChannel;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.StandardOpenOption;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import org.apache.kafka.clients.admin.Admin;
import org.apache.kafka.clients.admin.NewTopic;
import org.apache.kafka.clients.admin.TopicDescription;
import org.apache.kafka.common.KafkaFuture;
import org.apache.kafka.common.errors.TopicExistsException;
import org.apache.kafka.common.errors.UnknownTopicOrPartitionException;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Keeps the service's topics in place and notices when the broker lost them: missing topics are
 * (re-)created with the configured partitions (replication factor: the broker's default), and the
 * output topic's id is remembered in {@code ROOT/kafka-state/OUTPUT_TOPIC.topic-id}. A different
 * id means the topic was deleted and re-created (broker state lost, or another cluster): the
 * report events published before are gone, so every report in the ledger must be published again.
 */
public final class TopicKeeper {
    private static final Logger LOG = LoggerFactory.getLogger(TopicKeeper.class);

    private final KafkaSettings settings;
    private final String bootstrap;
    private final Path idFile;
    private String warnedAbout;

    /**
     * @param settings topics and partitions
     * @param bootstrap broker address (for messages)
     * @param stateDir folder of the remembered topic id
     */
    public TopicKeeper(KafkaSettings settings, String bootstrap, Path stateDir) {
        this.settings = settings;
        this.bootstrap = bootstrap;
        this.idFile = stateDir.resolve(settings.outputTopic() + ".topic-id");
    }

    /**
     * Creates missing topics and compares the output topic's id with the remembered one.
     *
     * @return the output topic's new id when it was re-created since the id was remembered
     *     (re-publish needed, then {@link #remember}); empty otherwise (a first id is remembered at once)
     * @throws ExecutionException when the broker refuses (the cause says why)
     * @throws TimeoutException when the broker does not answer
     */
    public Optional<String> check(Admin admin) throws ExecutionException, TimeoutException, InterruptedException {
        String id = outputTopicId(admin);
        String known = remembered();
        if (known == null) {
            remember(id);
            return Optional.empty();
        }
        if (!known.equals(id)) {
            if (id.equals(warnedAbout)) {
                return Optional.of(id);
            }
            warnedAbout = id;
            LOG.warn("topic {} on {} is not the one the service published to (topic id {} before, {} now): "
                    + "every report in the ledger will be published again", settings.outputTopic(), bootstrap, known, id);
            return Optional.of(id);
        }
        return Optional.empty();
    }

    /** @return the current id of the output topic, creating missing topics first */
    public String outputTopicId(Admin admin) throws ExecutionException, TimeoutException, InterruptedException {
        List<String> missing = new ArrayList<>();
        TopicDescription output = null;
        Map<String, KafkaFuture<TopicDescription>> found = admin.describeTopics(settings.topics()).topicNameValues();
        for (String t : settings.topics()) {
            try {
                TopicDescription d = found.get(t).get(KafkaClients.ADMIN_TIMEOUT_MS, TimeUnit.MILLISECONDS);
                if (t.equals(settings.outputTopic())) {
                    output = d;
                }
            } catch (ExecutionException e) {
                if (!(e.getCause() instanceof UnknownTopicOrPartitionException)) {
                    throw e;
                }
                missing.add(t);
            }
        }
        if (!missing.isEmpty()) {
            List<String> created = create(admin, missing);
            if (!created.isEmpty()) {
                LOG.warn("topics {} were missing on {}: created with {} partitions", created, bootstrap,
                        settings.partitions());
            }
            if (output == null) {
                output = admin.describeTopics(List.of(settings.outputTopic())).topicNameValues()
                        .get(settings.outputTopic()).get(KafkaClients.ADMIN_TIMEOUT_MS, TimeUnit.MILLISECONDS);
            }
        }
        return output.topicId().toString();
    }

    /** @return the topics this call created (not those someone else created meanwhile) */
    private List<String> create(Admin admin, List<String> names)
            throws ExecutionException, TimeoutException, InterruptedException {
        List<NewTopic> topics = new ArrayList<>();
        for (String n : names) {
            topics.add(new NewTopic(n, Optional.of(settings.partitions()), Optional.empty()));
        }
        List<String> created = new ArrayList<>();
        for (Map.Entry<String, KafkaFuture<Void>> f : admin.createTopics(topics).values().entrySet()) {
            try {
                f.getValue().get(KafkaClients.ADMIN_TIMEOUT_MS, TimeUnit.MILLISECONDS);
                created.add(f.getKey());
            } catch (ExecutionException e) {
                if (!(e.getCause() instanceof TopicExistsException)) {
                    throw e;
                }
            }
        }
        return created;
    }

    /** @return the remembered output topic id, or null */
    String remembered() {
        try {
            return Files.exists(idFile) ? Files.readString(idFile, StandardCharsets.UTF_8).trim() : null;
        } catch (IOException e) {
            throw new UncheckedIOException("could not read " + idFile + ": " + e.getMessage(), e);
        }
    }

    /** Remembers the output topic's id (written atomically). */
    public void remember(String topicId) {
        try {
            Files.createDirectories(idFile.getParent());
            Path tmp = idFile.resolveSibling(idFile.getFileName() + ".tmp");
            Files.writeString(tmp, topicId + "\n", StandardCharsets.UTF_8);
            try (FileChannel c = FileChannel.open(tmp, StandardOpenOption.WRITE)) {
                c.force(true);
            }
            Files.move(tmp, idFile, StandardCopyOption.ATOMIC_MOVE, StandardCopyOption.REPLACE_EXISTING);
        } catch (IOException e) {
            throw new UncheckedIOException("could not write " + idFile + ": " + e.getMessage(), e);
        }
    }
}
