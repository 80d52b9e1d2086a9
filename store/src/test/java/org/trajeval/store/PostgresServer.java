package org.trajeval.store;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.UserPrincipalLookupService;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;
import org.junit.jupiter.api.Assumptions;

/**
 * A real PostgreSQL server for tests, started from Debian's {@code postgresql} binaries
 * ({@code initdb}, {@code pg_ctl}) on a temporary folder and a free port on 127.0.0.1, and stopped
 * by {@link #close()}. PostgreSQL refuses to run as root: when the tests run as root the server
 * runs as the unprivileged {@code postgres} user (via {@code runuser}). Password login
 * (SCRAM-SHA-256) for user {@link #USER}; with TLS, {@code hostssl} only and a server certificate
 * signed by a CA generated here ({@link #caFile()}), for host name 127.0.0.1.
 */
final class PostgresServer implements AutoCloseable {
    static final String USER = "trajeval";
    static final String PASSWORD = "s3cret-Pw-for-tests";
    private static final String OS_USER = "postgres";

    private final Path dir;
    private final Path bin;
    private final boolean asOtherUser;
    private final int port;
    private final boolean tls;

    private PostgresServer(Path dir, Path bin, boolean asOtherUser, int port, boolean tls) {
        this.dir = dir;
        this.bin = bin;
        this.asOtherUser = asOtherUser;
        this.port = port;
        this.tls = tls;
    }

    /** @return the folder holding initdb and pg_ctl, if PostgreSQL is installed */
    static Optional<Path> binaries() {
        String env = System.getenv("TRAJEVAL_PG_BIN");
        if (env != null && Files.isExecutable(Path.of(env, "initdb"))) {
            return Optional.of(Path.of(env));
        }
        Path debian = Path.of("/usr/lib/postgresql");
        if (Files.isDirectory(debian)) {
            try (Stream<Path> s = Files.list(debian)) {
                return s.map(p -> p.resolve("bin")).filter(p -> Files.isExecutable(p.resolve("initdb")))
                        .max(Comparator.comparing(p -> versionOf(p.getParent().getFileName().toString())));
            } catch (IOException e) {
                return Optional.empty();
            }
        }
        return Optional.empty();
    }

    private static int versionOf(String s) {
        try {
            return Integer.parseInt(s);
        } catch (NumberFormatException e) {
            return 0;
        }
    }

    /**
     * Starts a server, or skips the calling test loudly when no PostgreSQL is installed.
     *
     * @param tls whether to require TLS (hostssl only)
     */
    static PostgresServer start(boolean tls) throws IOException, InterruptedException {
        Optional<Path> bin = binaries();
        if (bin.isEmpty()) {
            System.err.println("WARNING: no PostgreSQL binaries (apt-get install postgresql, or TRAJEVAL_PG_BIN): "
                    + "the PostgreSQL store tests are SKIPPED");
        }
        Assumptions.assumeTrue(bin.isPresent(), "no PostgreSQL installed: scripts/ensure-tools installs it");
        boolean root = "root".equals(System.getProperty("user.name"));
        Path dir = Files.createTempDirectory("trajeval-pg-");
        IOException last = null;
        for (int attempt = 0; attempt < 3; attempt++) {
            int port = freePort();
            PostgresServer s = new PostgresServer(dir, bin.get(), root, port, tls);
            try {
                s.init();
                return s;
            } catch (IOException e) {
                last = e;
                s.stopQuietly();
                deleteTree(dir);
                Files.createDirectories(dir);
            }
        }
        throw last;
    }

    private void init() throws IOException, InterruptedException {
        Path data = dir.resolve("data");
        Path pw = dir.resolve("pw");
        Files.writeString(pw, PASSWORD + "\n");
        Files.createDirectories(dir.resolve("sock"));
        if (tls) {
            makeCertificates();
        }
        if (asOtherUser) {
            chownTree(dir);
        }
        run(List.of(bin.resolve("initdb").toString(), "-D", data.toString(), "-U", USER, "--pwfile=" + pw,
                "--auth=scram-sha-256", "-E", "UTF8", "--no-sync", "--locale=C"));
        StringBuilder conf = new StringBuilder();
        conf.append("listen_addresses = '127.0.0.1'\nport = ").append(port).append('\n')
                .append("unix_socket_directories = '").append(dir.resolve("sock")).append("'\n")
                .append("fsync = off\nsynchronous_commit = off\nfull_page_writes = off\nmax_connections = 40\n")
                .append("shared_buffers = 16MB\n");
        String hba;
        if (tls) {
            conf.append("ssl = on\nssl_cert_file = '").append(dir.resolve("server.crt")).append("'\n")
                    .append("ssl_key_file = '").append(dir.resolve("server.key")).append("'\n");
            hba = "local all all scram-sha-256\nhostssl all all 127.0.0.1/32 scram-sha-256\n";
        } else {
            hba = "local all all scram-sha-256\nhost all all 127.0.0.1/32 scram-sha-256\n";
        }
        Files.writeString(data.resolve("postgresql.conf"), conf, StandardCharsets.UTF_8,
                java.nio.file.StandardOpenOption.APPEND);
        Files.writeString(data.resolve("pg_hba.conf"), hba);
        run(List.of(bin.resolve("pg_ctl").toString(), "-D", data.toString(), "-l", dir.resolve("log").toString(),
                "-w", "-t", "60", "start"));
    }

    /** A CA and a server certificate for 127.0.0.1 signed by it (openssl, PEM files in the server's folder). */
    private void makeCertificates() throws IOException, InterruptedException {
        String d = dir.toString();
        run(List.of("openssl", "req", "-x509", "-newkey", "rsa:2048", "-nodes", "-days", "2", "-subj",
                "/CN=trajeval test CA", "-keyout", d + "/ca.key", "-out", d + "/ca.crt"), false);
        run(List.of("openssl", "req", "-newkey", "rsa:2048", "-nodes", "-subj", "/CN=127.0.0.1", "-keyout",
                d + "/server.key", "-out", d + "/server.csr"), false);
        Files.writeString(dir.resolve("ext.cnf"), "subjectAltName = IP:127.0.0.1\n");
        run(List.of("openssl", "x509", "-req", "-in", d + "/server.csr", "-CA", d + "/ca.crt", "-CAkey",
                d + "/ca.key", "-CAcreateserial", "-days", "2", "-extfile", d + "/ext.cnf", "-out",
                d + "/server.crt"), false);
        Files.setPosixFilePermissions(dir.resolve("server.key"),
                java.nio.file.attribute.PosixFilePermissions.fromString("rw-------"));
    }

    /** @return the CA certificate (PEM) that signed the server's certificate; TLS servers only */
    Path caFile() {
        return dir.resolve("ca.crt");
    }

    /** @return the server's folder (temporary) */
    Path folder() {
        return dir;
    }

    /** @return a JDBC URL of database {@code postgres} on this server, with {@code query} appended */
    String url(String query) {
        return "jdbc:postgresql://127.0.0.1:" + port + "/postgres" + (query.isEmpty() ? "" : "?" + query);
    }

    /** @return the environment that logs in as the test user */
    Map<String, String> env() {
        return Map.of(StoreLocation.USER_ENV, USER, StoreLocation.PASSWORD_ENV, PASSWORD);
    }

    private void run(List<String> cmd) throws IOException, InterruptedException {
        run(cmd, asOtherUser);
    }

    private void run(List<String> cmd, boolean switchUser) throws IOException, InterruptedException {
        List<String> full = new ArrayList<>();
        if (switchUser) {
            full.addAll(List.of("runuser", "-u", OS_USER, "--"));
        }
        full.addAll(cmd);
        Path out = Files.createTempFile("trajeval-pg-cmd", ".log");
        try {
            Process p = new ProcessBuilder(full).redirectErrorStream(true).redirectOutput(out.toFile()).start();
            if (!p.waitFor(120, TimeUnit.SECONDS)) {
                p.destroyForcibly();
                throw new IOException(String.join(" ", cmd) + ": timed out");
            }
            if (p.exitValue() != 0) {
                String log = Files.exists(dir.resolve("log")) ? Files.readString(dir.resolve("log")) : "";
                throw new IOException(String.join(" ", cmd) + " failed (" + p.exitValue() + "): "
                        + Files.readString(out) + log);
            }
        } finally {
            Files.deleteIfExists(out);
        }
    }

    private static void chownTree(Path root) throws IOException {
        UserPrincipalLookupService users = root.getFileSystem().getUserPrincipalLookupService();
        var owner = users.lookupPrincipalByName(OS_USER);
        try (Stream<Path> s = Files.walk(root)) {
            for (Path p : (Iterable<Path>) s::iterator) {
                Files.setOwner(p, owner);
            }
        }
    }

    private static int freePort() throws IOException {
        try (ServerSocket s = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
            return s.getLocalPort();
        }
    }

    private void stopQuietly() {
        try {
            if (Files.exists(dir.resolve("data/postmaster.pid"))) {
                run(List.of(bin.resolve("pg_ctl").toString(), "-D", dir.resolve("data").toString(), "-m", "immediate",
                        "-w", "-t", "30", "stop"));
            }
        } catch (IOException | InterruptedException ignored) {
            // the server never came up; the folder goes next
        }
    }

    @Override
    public void close() {
        stopQuietly();
        deleteTree(dir);
    }

    private static void deleteTree(Path root) {
        try (Stream<Path> s = Files.walk(root)) {
            s.sorted(Comparator.reverseOrder()).forEach(p -> p.toFile().delete());
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
