package org.trajeval.store;

/**
 * One method's runs on one pairing sequence, both sides restricted to the (sequence, seed) keys
 * the other side also has, aggregated in the database.
 *
 * @param method the method ({@code -} for runs without one)
 * @param sequence the pairing sequence ({@link GatePairing})
 * @param metric the metric column
 * @param baselineN baseline values of the metric (successful runs; the score: every run with one)
 * @param baselineSum their sum (metric unit)
 * @param candidateN candidate values
 * @param candidateSum their sum (metric unit)
 */
public record PairedCell(String method, String sequence, String metric, long baselineN, double baselineSum,
        long candidateN, double candidateSum) {
    /** @return whether both sides have a value, so the sequence is paired */
    public boolean paired() {
        return baselineN > 0 && candidateN > 0;
    }

    /** @return the baseline's mean over the common keys, baselineSum / baselineN (metric unit) */
    public double baselineMean() {
        return baselineSum / baselineN;
    }

    /** @return the candidate's mean over the common keys (metric unit) */
    public double candidateMean() {
        return candidateSum / candidateN;
    }
}
