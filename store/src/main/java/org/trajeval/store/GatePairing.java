package org.trajeval.store;

/**
 * How a gate over stored runs pairs the baseline's runs with the candidate's, within one method:
 * the "sequence" a pair is averaged over and the "seed" that must match. Runs without a route,
 * robot or method count as {@code -}; without a seed as seed 0.
 */
public enum GatePairing {
    /** By (route, seed), as suite runs are: sequence = route. */
    ROUTE_SEED("COALESCE(r.route, '-')", "COALESCE(r.seed, 0)", "r.method, r.route, r.seed"),
    /** By (robot, route), every run of a robot on a route averaged: sequence = robot/route, no seed. */
    ROBOT_ROUTE("COALESCE(r.robot, '-') || '/' || COALESCE(r.route, '-')", "CAST(0 AS BIGINT)",
            "r.method, r.robot, r.route");

    private final String sequence;
    private final String seed;
    private final String columns;

    GatePairing(String sequence, String seed, String columns) {
        this.sequence = sequence;
        this.seed = seed;
        this.columns = columns;
    }

    /**
     * @return the raw columns the pairing keys are made of, on table alias {@code r}: grouping by them
     *     (not by the keys' expressions) follows an index's order instead of sorting
     */
    String keyColumns() {
        return columns;
    }

    /** @return the SQL of the pairing sequence on table alias {@code r} (SQLite and PostgreSQL alike) */
    String sequenceExpression() {
        return sequence;
    }

    /** @return the SQL of the pairing seed on table alias {@code r} */
    String seedExpression() {
        return seed;
    }

    /** @return the SQL of the method on table alias {@code r} */
    static String methodExpression() {
        return "COALESCE(r.method, '-')";
    }
}
