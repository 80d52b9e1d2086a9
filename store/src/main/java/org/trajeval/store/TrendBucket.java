package org.trajeval.store;

/** How a trend groups a slice's runs along its history. */
public enum TrendBucket {
    /** One bucket per UTC day ({@code recorded_ms / 86 400 000}). */
    DAY,
    /** One bucket per UTC week of 7 days counted from the epoch. */
    WEEK,
    /** One bucket per software version, ordered by the version's first recording time. */
    VERSION;

    /** @return the SQL of the bucket label (the same in SQLite and PostgreSQL) */
    String expression() {
        return switch (this) {
            case DAY -> "CAST(r.recorded_ms / 86400000 AS TEXT)";
            case WEEK -> "CAST(r.recorded_ms / 604800000 AS TEXT)";
            case VERSION -> "r.software_version";
        };
    }
}
