package org.trajeval.pipeline.kafka;

import java.io.IOException;
import java.io.OutputStream;
import java.io.PrintStream;
import java.io.UncheckedIOException;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Properties;
import kafka.server.KafkaConfig;
import kafka.server.KafkaRaftServer;
import org.apache.kafka.common.Uuid;
import org.apache.kafka.common.utils.Time;
import org.apache.kafka.metadata.storage.Formatter;
import org.apache.kafka.server.common.MetadataVersion;

/**
 * A single-node Kafka (KRaft, combined broker + controller) running inside this JVM on
 * 127.0.0.1, for tests and the demo (in its own JVM: {@link BrokerMain}; never in the
 * launcher's runtime). Three listeners: CLIENT (PLAINTEXT unless {@code extra} says otherwise,
 * e.g. SASL_SSL), INTERNAL (PLAINTEXT, between the broker and itself, and for the test's admin
 * work such as creating SCRAM users) and CONTROLLER. The only class that
 * touches Kafka's internal server classes ({@code KafkaRaftServer}, the storage
 * {@code Formatter}); they may change between Kafka versions (written against 4.3.1).
 */
public final class EmbeddedBroker implements AutoCloseable {
    private final KafkaRaftServer server;
    private final Path dataDir;
    private final boolean deleteOnClose;
    private final String bootstrapServers;
    private final String internalBootstrapServers;

    private EmbeddedBroker(KafkaRaftServer server, Path dataDir, boolean deleteOnClose, String bootstrapServers,
            String internalBootstrapServers) {
        this.server = server;
        this.dataDir = dataDir;
        this.deleteOnClose = deleteOnClose;
        this.bootstrapServers = bootstrapServers;
        this.internalBootstrapServers = internalBootstrapServers;
    }

    /** @return host:port of the INTERNAL (PLAINTEXT) listener */
    public String internalBootstrapServers() {
        return internalBootstrapServers;
    }

    /**
     * Formats {@code dataDir} when it is new and starts the broker.
     *
     * @param dataDir folder for the broker's logs, or {@code null} for a temporary folder
     *     deleted on {@link #close()}
     * @param brokerPort client port, or 0 for a free one
     * @return the running broker
     */
    public static EmbeddedBroker start(Path dataDir, int brokerPort) {
        try {
            return start(dataDir, brokerPort == 0 ? freePort() : brokerPort, freePort(), freePort(), new Properties());
        } catch (IOException e) {
            throw new UncheckedIOException("could not find free ports", e);
        }
    }

    /**
     * Formats {@code dataDir} when it is new and starts the broker on the given ports (a restart
     * after a kill uses the same ports and folder).
     *
     * @param dataDir folder for the broker's logs, or {@code null} for a temporary folder
     * @param port CLIENT port
     * @param internalPort INTERNAL (PLAINTEXT) port
     * @param controllerPort CONTROLLER port
     * @param extra broker settings added or overridden (listener security, TLS stores, SASL)
     * @return the running broker
     */
    public static EmbeddedBroker start(Path dataDir, int port, int internalPort, int controllerPort, Properties extra) {
        try {
            boolean temporary = dataDir == null;
            Path dir = temporary ? Files.createTempDirectory("trajeval-kafka-") : dataDir;
            Files.createDirectories(dir);
            Properties p = new Properties();
            p.setProperty("process.roles", "broker,controller");
            p.setProperty("node.id", "1");
            p.setProperty("controller.quorum.voters", "1@127.0.0.1:" + controllerPort);
            p.setProperty("listeners", "CLIENT://127.0.0.1:" + port + ",INTERNAL://127.0.0.1:" + internalPort
                    + ",CONTROLLER://127.0.0.1:" + controllerPort);
            p.setProperty("advertised.listeners", "CLIENT://127.0.0.1:" + port + ",INTERNAL://127.0.0.1:" + internalPort);
            p.setProperty("controller.listener.names", "CONTROLLER");
            p.setProperty("inter.broker.listener.name", "INTERNAL");
            p.setProperty("listener.security.protocol.map", "CLIENT:PLAINTEXT,INTERNAL:PLAINTEXT,CONTROLLER:PLAINTEXT");
            p.setProperty("log.dirs", dir.toAbsolutePath().toString());
            p.setProperty("offsets.topic.replication.factor", "1");
            p.setProperty("offsets.topic.num.partitions", "3");
            p.setProperty("transaction.state.log.replication.factor", "1");
            p.setProperty("transaction.state.log.min.isr", "1");
            p.setProperty("share.coordinator.state.topic.replication.factor", "1");
            p.setProperty("share.coordinator.state.topic.min.isr", "1");
            p.setProperty("group.initial.rebalance.delay.ms", "0");
            p.setProperty("transaction.state.log.num.partitions", "3");
            p.setProperty("transaction.abort.timed.out.transaction.cleanup.interval.ms", "1000");
            p.setProperty("group.min.session.timeout.ms", "1000");
            p.setProperty("num.partitions", "3");
            p.setProperty("auto.create.topics.enable", "false");
            // the cleaner's dedupe buffer defaults to 128 MiB: far too much for a small heap
            p.setProperty("log.cleaner.dedupe.buffer.size", String.valueOf(2L << 20));
            p.setProperty("log.cleaner.io.buffer.size", String.valueOf(256 << 10));
            p.setProperty("num.network.threads", "2");
            p.setProperty("num.io.threads", "2");
            p.setProperty("background.threads", "2");
            p.setProperty("num.recovery.threads.per.data.dir", "1");
            p.setProperty("log.flush.interval.messages", "1");
            p.putAll(extra);
            KafkaConfig config = new KafkaConfig(p);
            if (!Files.exists(dir.resolve("meta.properties"))) {
                Formatter formatter = new Formatter()
                        .setClusterId(Uuid.randomUuid().toString())
                        .setNodeId(1)
                        .setControllerListenerName("CONTROLLER")
                        .setMetadataLogDirectory(config.metadataLogDir())
                        .setDirectories(List.of(dir.toAbsolutePath().toString()))
                        .setReleaseVersion(MetadataVersion.latestProduction())
                        .setPrintStream(new PrintStream(OutputStream.nullOutputStream()));
                formatter.run();
            }
            KafkaRaftServer server = new KafkaRaftServer(config, Time.SYSTEM);
            server.startup();
            return new EmbeddedBroker(server, dir, temporary, "127.0.0.1:" + port, "127.0.0.1:" + internalPort);
        } catch (IOException e) {
            throw new UncheckedIOException("could not start the embedded Kafka broker", e);
        } catch (RuntimeException e) {
            throw e;
        } catch (Exception e) {
            throw new IllegalStateException("could not format the embedded Kafka broker's storage: " + e, e);
        }
    }

    /** @return host:port for {@code bootstrap.servers} */
    public String bootstrapServers() {
        return bootstrapServers;
    }

    /** Stops the broker and waits for it; deletes a temporary data folder. */
    @Override
    public void close() {
        server.shutdown();
        server.awaitShutdown();
        if (deleteOnClose) {
            deleteTree(dataDir);
        }
    }

    /** @return a free TCP port on 127.0.0.1 (ephemeral range) */
    static int freePort() throws IOException {
        try (ServerSocket s = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
            s.setReuseAddress(true);
            return s.getLocalPort();
        }
    }

    private static void deleteTree(Path root) {
        try {
            BrokerProcess.deleteTree(root);
        } catch (UncheckedIOException ignored) {
            // best effort: a temporary folder
        }
    }
}
