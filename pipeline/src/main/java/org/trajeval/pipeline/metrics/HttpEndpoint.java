package org.trajeval.pipeline.metrics;

import com.sun.net.httpserver.HttpExchange;
import com.sun.net.httpserver.HttpServer;
import java.io.IOException;
import java.io.OutputStream;
import java.io.UncheckedIOException;
import java.net.InetSocketAddress;
import java.nio.charset.StandardCharsets;
import java.util.function.BooleanSupplier;
import java.util.function.Supplier;

/**
 * {@code GET /metrics} (Prometheus text format) and {@code GET /health} ({@code {"status":"UP"}}
 * with 200, or {@code {"status":"DOWN","reason":"..."}} with 503) on a local address, 127.0.0.1 by default.
 */
public final class HttpEndpoint implements AutoCloseable {
    private final HttpServer server;

    private HttpEndpoint(HttpServer server) {
        this.server = server;
    }

    /**
     * Starts serving.
     *
     * @param host address to bind (127.0.0.1 unless told otherwise)
     * @param port port, 0 for a free one
     * @param metrics text for /metrics
     * @param healthy whether /health says UP
     */
    public static HttpEndpoint start(String host, int port, Supplier<String> metrics, BooleanSupplier healthy) {
        return startWithReason(host, port, metrics,
                () -> healthy.getAsBoolean() ? HealthStatus.UP : HealthStatus.down("not running"));
    }

    /**
     * Starts serving, with a reason on /health when DOWN.
     *
     * @param host address to bind (127.0.0.1 unless told otherwise)
     * @param port port, 0 for a free one
     * @param metrics text for /metrics
     * @param health what /health answers
     */
    public static HttpEndpoint startWithReason(String host, int port, Supplier<String> metrics,
            Supplier<HealthStatus> health) {
        try {
            HttpServer s = HttpServer.create(new InetSocketAddress(host, port), 16);
            s.createContext("/metrics", ex -> reply(ex, 200, "text/plain; version=0.0.4; charset=utf-8", metrics.get()));
            s.createContext("/health", ex -> {
                HealthStatus h = health.get();
                reply(ex, h.up() ? 200 : 503, "application/json", h.json());
            });
            s.start();
            return new HttpEndpoint(s);
        } catch (IOException e) {
            throw new UncheckedIOException("could not serve metrics on " + host + ":" + port + ": " + e.getMessage(), e);
        }
    }

    /** @return the bound port */
    public int port() {
        return server.getAddress().getPort();
    }

    private static void reply(HttpExchange ex, int status, String type, String body) throws IOException {
        byte[] b = body.getBytes(StandardCharsets.UTF_8);
        ex.getResponseHeaders().set("Content-Type", type);
        ex.sendResponseHeaders(status, b.length);
        try (OutputStream out = ex.getResponseBody()) {
            out.write(b);
        }
    }

    @Override
    public void close() {
        server.stop(0);
    }
}
