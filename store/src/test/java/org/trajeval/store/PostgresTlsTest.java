package org.trajeval.store;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Clock;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The store over TLS against a real PostgreSQL that accepts only TLS ({@code hostssl}) with a
 * certificate for 127.0.0.1 signed by a CA the test generates: verify-full with that CA works;
 * no TLS, another CA and another host name are refused, with one line that names no secret.
 */
class PostgresTlsTest {
    private static PostgresServer server;

    @BeforeAll
    static void startServer() throws Exception {
        server = PostgresServer.start(true);
    }

    @AfterAll
    static void stopServer() {
        if (server != null) {
            server.close();
        }
    }

    private static StoreException refused(String url, Map<String, String> env) {
        StoreException e = assertThrows(StoreException.class,
                () -> ResultsStore.open(StoreLocation.parse(url, env), Clock.systemUTC()));
        assertEquals(StoreException.Problem.UNAVAILABLE, e.problem());
        assertFalse(e.getMessage().contains(PostgresServer.PASSWORD), e.getMessage());
        assertEquals(1, e.getMessage().lines().count(), e.getMessage());
        return e;
    }

    @Test
    void verifyFullWithTheCaFileConnectsWithThePasswordFromAFile(@TempDir Path dir) throws Exception {
        Path pw = dir.resolve("db-password");
        Files.writeString(pw, PostgresServer.PASSWORD + "\n");
        Map<String, String> env = Map.of(StoreLocation.USER_ENV, PostgresServer.USER, StoreLocation.PASSWORD_FILE_ENV,
                pw.toString());
        String url = server.url("sslmode=verify-full&sslrootcert=" + server.caFile());
        try (ResultsStore s = ResultsStore.open(StoreLocation.parse(url, env), Clock.systemUTC())) {
            s.record(List.of(Records.run(1, "bot-1", "hall", "2.4", 1, 0.1, 0, Map.of())));
            assertEquals(1, s.count());
            assertFalse(s.location().toString().contains("sslrootcert"), "the URL's query is not shown");
        }
    }

    @Test
    void aConnectionWithoutTlsIsRefusedByTheServer() {
        StoreException e = refused(server.url("sslmode=disable"), server.env());
        assertTrue(e.getMessage().contains("no pg_hba.conf entry"), e.getMessage());
    }

    @Test
    void aServerCertificateFromAnotherCaIsRefused(@TempDir Path dir) throws Exception {
        Path otherCa = dir.resolve("other-ca.crt");
        Process p = new ProcessBuilder("openssl", "req", "-x509", "-newkey", "rsa:2048", "-nodes", "-days", "1",
                "-subj", "/CN=another CA", "-keyout", dir.resolve("k").toString(), "-out", otherCa.toString())
                .redirectErrorStream(true).redirectOutput(dir.resolve("log").toFile()).start();
        assertEquals(0, p.waitFor());
        StoreException e = refused(server.url("sslmode=verify-full&sslrootcert=" + otherCa), server.env());
        assertTrue(e.getMessage().toLowerCase(java.util.Locale.ROOT).contains("ssl"), e.getMessage());
    }

    @Test
    void aHostNameTheCertificateDoesNotNameIsRefused() {
        String url = server.url("sslmode=verify-full&sslrootcert=" + server.caFile()).replace("127.0.0.1",
                "localhost");
        StoreException e = refused(url, server.env());
        assertTrue(e.getMessage().contains("localhost"), e.getMessage());
    }
}
