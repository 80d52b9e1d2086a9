package org.trajeval.cli;

import java.time.Clock;
import org.trajeval.store.ResultsStore;
import org.trajeval.store.StoreLocation;
import picocli.CommandLine.Option;

/** The results-store option shared by {@code db}, {@code gate}, {@code trend} and {@code suite}. */
final class StoreOptions {
    @Option(names = "--db", paramLabel = "URL",
            description = {"Results store: a SQLite file (e.g. trajeval.db) or jdbc:sqlite:PATH or "
                + "jdbc:postgresql://HOST:PORT/DB[?sslmode=verify-full&sslrootcert=CA.pem].",
                "Credentials only from the environment: TRAJEVAL_DB_USER, TRAJEVAL_DB_PASSWORD or "
                    + "TRAJEVAL_DB_PASSWORD_FILE (a URL holding a password is refused)."})
    String db;

    /** @return whether --db was given */
    boolean given() {
        return db != null;
    }

    /** Opens (and migrates) the store named by --db. */
    ResultsStore open() {
        return ResultsStore.open(StoreLocation.parse(db, System.getenv()), Clock.systemUTC());
    }
}
