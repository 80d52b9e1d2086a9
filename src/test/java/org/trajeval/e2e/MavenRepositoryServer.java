package org.trajeval.e2e;

import com.sun.net.httpserver.HttpExchange;
import com.sun.net.httpserver.HttpServer;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.nio.charset.StandardCharsets;
import java.util.Base64;
import java.util.Map;
import java.util.TreeMap;
import java.util.concurrent.ConcurrentHashMap;

/**
 * A minimal Maven repository over HTTP for the publication test, on 127.0.0.1 and a free port:
 * PUT stores a file at its path, GET returns it (404 when absent), and both need HTTP basic
 * authentication with the one user it is made with (401 otherwise), as a repository manager's
 * releases repository does. It keeps what was uploaded in memory.
 */
final class MavenRepositoryServer implements AutoCloseable {
    private final HttpServer server;
    private final String authorization;
    private final Map<String, byte[]> files = new ConcurrentHashMap<>();
    private final Map<String, Integer> unauthorised = new ConcurrentHashMap<>();

    private MavenRepositoryServer(String user, String password) throws IOException {
        this.authorization = "Basic " + Base64.getEncoder()
                .encodeToString((user + ":" + password).getBytes(StandardCharsets.UTF_8));
        this.server = HttpServer.create(new InetSocketAddress(InetAddress.getLoopbackAddress(), 0), 0);
        server.createContext("/", this::handle);
    }

    /** @return a started server accepting {@code user}/{@code password} */
    static MavenRepositoryServer start(String user, String password) throws IOException {
        MavenRepositoryServer s = new MavenRepositoryServer(user, password);
        s.server.start();
        return s;
    }

    /** @return the repository's base URL, ending in "/releases/" */
    String url() {
        return "http://127.0.0.1:" + server.getAddress().getPort() + "/releases/";
    }

    /** @return the uploaded files by path below the base URL, sorted */
    Map<String, byte[]> files() {
        Map<String, byte[]> sorted = new TreeMap<>();
        files.forEach((k, v) -> sorted.put(k.substring("/releases/".length()), v));
        return sorted;
    }

    /** @return requests refused for missing or wrong credentials, by "METHOD path" */
    Map<String, Integer> unauthorised() {
        return Map.copyOf(unauthorised);
    }

    private void handle(HttpExchange x) throws IOException {
        try (x) {
            String path = x.getRequestURI().getPath();
            if (!authorization.equals(x.getRequestHeaders().getFirst("Authorization"))) {
                unauthorised.merge(x.getRequestMethod() + " " + path, 1, Integer::sum);
                x.getResponseHeaders().add("WWW-Authenticate", "Basic realm=\"releases\"");
                x.sendResponseHeaders(401, -1);
                return;
            }
            switch (x.getRequestMethod()) {
                case "PUT" -> {
                    try (InputStream in = x.getRequestBody()) {
                        files.put(path, in.readAllBytes());
                    }
                    x.sendResponseHeaders(201, -1);
                }
                case "GET" -> {
                    byte[] body = files.get(path);
                    if (body == null) {
                        x.sendResponseHeaders(404, -1);
                        return;
                    }
                    x.sendResponseHeaders(200, body.length);
                    try (OutputStream out = x.getResponseBody()) {
                        out.write(body);
                    }
                }
                default -> x.sendResponseHeaders(405, -1);
            }
        }
    }

    @Override
    public void close() {
        server.stop(0);
    }
}
