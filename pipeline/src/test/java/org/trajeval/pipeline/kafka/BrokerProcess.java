package org.trajeval.pipeline.kafka;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.FileVisitResult;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.SimpleFileVisitor;
import java.nio.file.attribute.BasicFileAttributes;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;

/**
 * The test fixture: a single-node KRaft broker in its own JVM ({@link BrokerMain}, started from
 * the test runtime class path) on three free ports picked once, so that a test can SIGKILL it,
 * restart it on the same ports and log folder, or wipe the folder (broker state lost).
 */
public final class BrokerProcess implements AutoCloseable {
    private static final Duration START_TIMEOUT = Duration.ofSeconds(120);

    private final Path data;
    private final Path log;
    private final Path config;
    private final int port;
    private final int internalPort;
    private final int controllerPort;
    private final java.util.Map<String, Integer> listeners = new java.util.LinkedHashMap<>();
    private Process process;
    private int starts;

    private BrokerProcess(Path data, Path log, Path config, List<String> extraListeners) throws IOException {
        this.data = data;
        this.log = log;
        this.config = config;
        for (String l : extraListeners) {
            listeners.put(l, EmbeddedBroker.freePort());
        }
        this.port = EmbeddedBroker.freePort();
        this.internalPort = EmbeddedBroker.freePort();
        this.controllerPort = EmbeddedBroker.freePort();
    }

    /**
     * Starts a broker and waits until it serves.
     *
     * @param data its log folder
     * @param log where its output goes (appended on every start)
     * @param config broker properties to add (listener security ...), or null
     */
    public static BrokerProcess start(Path data, Path log, Path config) throws IOException, InterruptedException {
        return start(data, log, config, List.of());
    }

    /** As {@link #start(Path, Path, Path)}, with extra client listeners (their protocols set in {@code config}). */
    public static BrokerProcess start(Path data, Path log, Path config, List<String> extraListeners)
            throws IOException, InterruptedException {
        BrokerProcess b = new BrokerProcess(data, log, config, extraListeners);
        b.restart();
        return b;
    }

    /** @return host:port of an extra listener */
    public String bootstrapServers(String listener) {
        return "127.0.0.1:" + listeners.get(listener);
    }

    /** @return a broker with its ports picked, not started yet ({@link #restart()} starts it) */
    public static BrokerProcess prepare(Path data, Path log, Path config) throws IOException {
        return new BrokerProcess(data, log, config, List.of());
    }

    /** @return host:port of the CLIENT listener */
    public String bootstrapServers() {
        return "127.0.0.1:" + port;
    }

    /** @return host:port of the INTERNAL (PLAINTEXT) listener */
    public String internalBootstrapServers() {
        return "127.0.0.1:" + internalPort;
    }

    /** (Re)starts the broker on the same ports and folder and waits for its READY line. */
    public void restart() throws IOException, InterruptedException {
        List<String> cmd = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-Xmx384m", "-XX:+UseSerialGC", "-XX:TieredStopAtLevel=1", "-cp",
                System.getProperty("trajeval.testClasspath", System.getProperty("java.class.path")),
                BrokerMain.class.getName(), "--port", String.valueOf(port), "--internal-port", String.valueOf(internalPort),
                "--controller-port", String.valueOf(controllerPort), "--data", data.toString()));
        if (config != null) {
            cmd.addAll(List.of("--config", config.toString()));
        }
        listeners.forEach((name, p) -> cmd.addAll(List.of("--listener", name + "=" + p)));
        int readyBefore = countReady();
        process = new ProcessBuilder(cmd).redirectErrorStream(true)
                .redirectOutput(ProcessBuilder.Redirect.appendTo(log.toFile())).start();
        starts++;
        long deadline = System.nanoTime() + START_TIMEOUT.toNanos();
        while (countReady() == readyBefore) {
            if (!process.isAlive() || System.nanoTime() > deadline) {
                process.destroyForcibly();
                throw new IllegalStateException("the broker did not start (start " + starts + "); see " + log);
            }
            Thread.sleep(100);
        }
    }

    private int countReady() throws IOException {
        if (!Files.exists(log)) {
            return 0;
        }
        return (int) Files.readAllLines(log, java.nio.charset.StandardCharsets.ISO_8859_1).stream()
                .filter(l -> l.startsWith("READY ")).count();
    }

    /** Kills the broker with SIGKILL and waits for it to be gone. */
    public void kill() throws InterruptedException {
        process.destroyForcibly();
        if (!process.waitFor(30, TimeUnit.SECONDS)) {
            throw new IllegalStateException("the broker survived SIGKILL");
        }
    }

    /** Deletes the broker's log folder (after {@link #kill()}): the next start is a new, empty cluster. */
    public void wipe() {
        if (process.isAlive()) {
            throw new IllegalStateException("kill the broker before wiping its folder");
        }
        deleteTree(data);
    }

    /** Stops the broker (SIGTERM, then SIGKILL after 20 s). */
    @Override
    public void close() throws InterruptedException {
        if (process != null && process.isAlive()) {
            process.destroy();
            if (!process.waitFor(20, TimeUnit.SECONDS)) {
                process.destroyForcibly();
                process.waitFor(10, TimeUnit.SECONDS);
            }
        }
    }

    static void deleteTree(Path root) {
        if (!Files.exists(root)) {
            return;
        }
        try {
            Files.walkFileTree(root, new SimpleFileVisitor<>() {
                @Override
                public FileVisitResult visitFile(Path file, BasicFileAttributes attrs) throws IOException {
                    Files.delete(file);
                    return FileVisitResult.CONTINUE;
                }

                @Override
                public FileVisitResult postVisitDirectory(Path d, IOException e) throws IOException {
                    Files.delete(d);
                    return FileVisitResult.CONTINUE;
                }
            });
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
