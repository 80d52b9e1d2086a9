package org.trajeval.pipeline.kafka;

import java.io.IOException;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.trajeval.pipeline.PipelineCommand;

/**
 * {@code trajeval-pipeline kafka} in a child JVM with the production logging configuration (as
 * the launcher runs it), its output appended to a log file; /health and /metrics on a free port
 * that the service logs.
 */
final class ServiceProcess implements AutoCloseable {
    private static final Pattern HTTP = Pattern.compile("/health on http://127\\.0\\.0\\.1:(\\d+)");

    private final Process process;
    private final Path log;
    private final long logStart;
    private int httpPort;

    private ServiceProcess(Process process, Path log, long logStart) {
        this.process = process;
        this.log = log;
        this.logStart = logStart;
    }

    /** Starts {@code kafka --root ROOT --http-port 0 --bootstrap-servers BS --workers 2 ARGS...}. */
    static ServiceProcess start(Path root, String bootstrap, Path log, List<String> args) throws IOException {
        return start(root, bootstrap, log, args, java.util.Map.of());
    }

    /** As {@link #start(Path, String, Path, List)}, with environment variables added. */
    static ServiceProcess start(Path root, String bootstrap, Path log, List<String> args, java.util.Map<String, String> env)
            throws IOException {
        List<String> cmd = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-Xmx256m", "-XX:TieredStopAtLevel=1",
                "-cp", org.trajeval.pipeline.LauncherClasspath.withoutTestLogging(),
                PipelineCommand.class.getName(), "kafka", "--root", root.toString(), "--http-port", "0",
                "--bootstrap-servers", bootstrap, "--workers", "2"));
        cmd.addAll(args);
        long logStart = Files.exists(log) ? Files.size(log) : 0;
        ProcessBuilder pb = new ProcessBuilder(cmd).redirectErrorStream(true)
                .redirectOutput(ProcessBuilder.Redirect.appendTo(log.toFile()));
        pb.environment().putAll(env);
        Process p = pb.start();
        return new ServiceProcess(p, log, logStart);
    }

    boolean isAlive() {
        return process.isAlive();
    }

    Process process() {
        return process;
    }

    String log() throws IOException {
        return Files.readString(log);
    }

    /** @return "STATUS BODY" of GET /health, or "no answer ..." */
    String health() {
        return get("/health");
    }

    /** @return "STATUS BODY" of GET /metrics */
    String metrics() {
        return get("/metrics");
    }

    private String get(String path) {
        try {
            if (httpPort == 0) {
                // the log may hold an earlier instance's lines: only this instance's part counts
                Matcher m = HTTP.matcher(log().substring((int) Math.min(logStart, log().length())));
                if (m.find()) {
                    httpPort = Integer.parseInt(m.group(1));
                }
                if (httpPort == 0) {
                    return "no answer: the HTTP port is not logged yet";
                }
            }
            HttpResponse<String> r = HttpClient.newHttpClient().send(HttpRequest.newBuilder(
                    URI.create("http://127.0.0.1:" + httpPort + path)).timeout(Duration.ofSeconds(2)).build(),
                    HttpResponse.BodyHandlers.ofString());
            return r.statusCode() + " " + r.body();
        } catch (IOException e) {
            return "no answer " + e;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return "no answer: interrupted";
        }
    }

    /** Sends SIGTERM and @return the exit code (-1 when it did not stop within 60 s) */
    int terminate() throws InterruptedException {
        process.destroy();
        return process.waitFor(60, TimeUnit.SECONDS) ? process.exitValue() : -1;
    }

    /** SIGKILL. */
    void kill() throws InterruptedException {
        process.destroyForcibly();
        process.waitFor(30, TimeUnit.SECONDS);
    }

    @Override
    public void close() throws InterruptedException {
        if (process.isAlive()) {
            process.destroy();
            if (!process.waitFor(60, TimeUnit.SECONDS)) {
                kill();
            }
        }
    }
}
