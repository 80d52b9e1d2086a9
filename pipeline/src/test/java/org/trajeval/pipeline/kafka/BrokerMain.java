package org.trajeval.pipeline.kafka;

import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Properties;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import org.apache.kafka.clients.admin.Admin;
import org.apache.kafka.clients.admin.NewTopic;

/**
 * A single-node broker in its own JVM: the tests' fixture ({@link BrokerProcess}, which kills it
 * with SIGKILL and restarts it) and the demo's broker ({@code gradle :pipeline:broker}). Prints
 * {@code READY host:port} once it serves. Arguments: {@code --port P} (CLIENT, default 9092),
 * {@code --internal-port P}, {@code --controller-port P} (default: free ports), {@code --data DIR}
 * (default: a temporary folder), {@code --topics a,b,c} (3 partitions each), {@code --config FILE}
 * (broker properties added: listener security, TLS stores, SASL), {@code --listener NAME=PORT}
 * (an extra client listener, repeatable).
 */
public final class BrokerMain {
    private BrokerMain() {
    }

    /** Runs the broker until SIGTERM. */
    public static void main(String[] args) throws Exception {
        int port = 9092;
        int internal = 0;
        int controller = 0;
        Path data = null;
        List<String> topics = List.of();
        Properties extra = new Properties();
        List<String> listeners = new ArrayList<>();
        for (int i = 0; i < args.length; i += 2) {
            String v = args[i + 1];
            switch (args[i]) {
                case "--port" -> port = Integer.parseInt(v);
                case "--internal-port" -> internal = Integer.parseInt(v);
                case "--controller-port" -> controller = Integer.parseInt(v);
                case "--data" -> data = Path.of(v);
                case "--listener" -> listeners.add(v);
                case "--topics" -> topics = List.of(v.split(","));
                case "--config" -> {
                    try (InputStream in = Files.newInputStream(Path.of(v))) {
                        extra.load(in);
                    }
                }
                default -> throw new IllegalArgumentException("unknown option " + args[i]);
            }
        }
        int p0 = port;
        int i0 = internal == 0 ? EmbeddedBroker.freePort() : internal;
        int c0 = controller == 0 ? EmbeddedBroker.freePort() : controller;
        if (!listeners.isEmpty()) {
            // extra client listeners NAME=PORT; their protocols come from --config's listener.security.protocol.map
            StringBuilder l = new StringBuilder("CLIENT://127.0.0.1:" + p0 + ",INTERNAL://127.0.0.1:" + i0);
            for (String nl : listeners) {
                String[] f = nl.split("=");
                l.append(',').append(f[0]).append("://127.0.0.1:").append(f[1]);
            }
            extra.setProperty("advertised.listeners", l.toString());
            extra.setProperty("listeners", l + ",CONTROLLER://127.0.0.1:" + c0);
        }
        EmbeddedBroker broker = EmbeddedBroker.start(data, p0, i0, c0, extra);
        CountDownLatch stop = new CountDownLatch(1);
        Runtime.getRuntime().addShutdownHook(new Thread(() -> {
            broker.close();
            stop.countDown();
        }, "broker-shutdown"));
        if (!topics.isEmpty()) {
            createTopics(broker.internalBootstrapServers(), topics);
        }
        System.out.println("READY " + broker.bootstrapServers());
        System.out.flush();
        stop.await();
    }

    static void createTopics(String bootstrap, List<String> names) throws Exception {
        try (Admin admin = Admin.create(Map.of("bootstrap.servers", bootstrap))) {
            List<NewTopic> topics = new ArrayList<>();
            for (String n : names) {
                topics.add(new NewTopic(n, 3, (short) 1));
            }
            admin.createTopics(topics).all().get(60, TimeUnit.SECONDS);
        } catch (java.util.concurrent.ExecutionException e) {
            if (!(e.getCause() instanceof org.apache.kafka.common.errors.TopicExistsException)) {
                throw e;
            }
        }
    }
}
