package org.trajeval.store;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.sql.Connection;
import java.sql.DriverManager;
import java.sql.Statement;
import java.util.HashMap;
import java.util.Map;
import java.util.Properties;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

/** The store contract against a real PostgreSQL server the test starts (and stops) itself. */
class PostgresStoreTest extends ResultsStoreContract {
    private static PostgresServer server;
    private static int databases;

    @BeforeAll
    static void startServer() throws Exception {
        server = PostgresServer.start(false);
    }

    @AfterAll
    static void stopServer() {
        if (server != null) {
            server.close();
        }
    }

    @Override
    StoreLocation freshLocation() throws Exception {
        String db = "t" + (databases++);
        Properties login = new Properties();
        login.setProperty("user", PostgresServer.USER);
        login.setProperty("password", PostgresServer.PASSWORD);
        try (Connection c = DriverManager.getConnection(server.url(""), login); Statement s = c.createStatement()) {
            s.execute("CREATE DATABASE " + db);
        }
        return StoreLocation.parse(server.url("").replace("/postgres", "/" + db), server.env());
    }

    @Test
    void aWrongPasswordIsRefusedWithoutShowingIt() {
        Map<String, String> env = new HashMap<>(server.env());
        env.put(StoreLocation.PASSWORD_ENV, "wrong-password-xyz");
        StoreException e = assertThrows(StoreException.class,
                () -> ResultsStore.open(StoreLocation.parse(server.url(""), env), CLOCK));
        assertEquals(StoreException.Problem.UNAVAILABLE, e.problem());
        assertTrue(e.getMessage().contains("password authentication failed"), e.getMessage());
        assertFalse(e.getMessage().contains("wrong-password-xyz"), e.getMessage());
    }
}
