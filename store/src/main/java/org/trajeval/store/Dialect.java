package org.trajeval.store;

/** The SQL databases the store speaks to; the SQL differs between them only where noted. */
public enum Dialect {
    /** One SQLite file (the embedded default), in WAL mode. */
    SQLITE,
    /** A PostgreSQL server (shared deployments). */
    POSTGRESQL
}
