package org.trajeval.core.stats;

/**
 * Split of a metric's variance into a between-sequence and a between-seed (within-sequence)
 * part: the one-way random-effects model y_sk = mu + a_s + e_sk, a_s ~ (0, sigma_seq^2),
 * e_sk ~ (0, sigma_seed^2), fitted by the ANOVA (method-of-moments) estimator (Searle, Casella
 * and McCulloch, Variance Components, 1992, section 3.5). With g sequences, n_s seeds on
 * sequence s, N = sum n_s:
 * <pre>
 *   MSB = sum_s n_s (ybar_s - ybar)^2 / (g - 1)        MSW = sum_s sum_k (y_sk - ybar_s)^2 / (N - g)
 *   n0 = (N - sum_s n_s^2 / N) / (g - 1)               (= K when every sequence has K seeds)
 *   sigma_seed^2 = MSW                                  sigma_seq^2 = max(0, (MSB - MSW) / n0)
 * </pre>
 * The mean over g sequences of K-seed means has variance sigma_seq^2/g + sigma_seed^2/(g K):
 * more seeds only shrink the second term, more sequences shrink both. The advice is
 * {@link Advice#MORE_SEEDS} when the seed term of one sequence's mean, sigma_seed^2 / K (K =
 * n0), exceeds sigma_seq^2, else {@link Advice#MORE_SEQUENCES}.
 */
public final class VarianceComponents {
    private VarianceComponents() {
    }

    /** What would shrink the uncertainty most. */
    public enum Advice {
        /** The seed noise in a sequence's mean dominates: run more seeds. */
        MORE_SEEDS,
        /** The sequences differ more than the seeds: add sequences. */
        MORE_SEQUENCES
    }

    /**
     * @param sequences g, sequences with at least one value
     * @param values N, values in all
     * @param seedsPerSequence n0 (K when balanced)
     * @param sequenceVariance sigma_seq^2 (unit squared)
     * @param seedVariance sigma_seed^2 (unit squared)
     * @param sequenceShare sigma_seq^2 / (sigma_seq^2 + sigma_seed^2), NaN when both are 0
     * @param advice more seeds or more sequences
     */
    public record Result(int sequences, int values, double seedsPerSequence, double sequenceVariance,
            double seedVariance, double sequenceShare, Advice advice) {
    }

    /**
     * @param groups per sequence the values over its seeds (sequences without a value are skipped)
     * @return the split, or null when there are fewer than 2 sequences or no sequence with 2 values
     */
    public static Result of(double[][] groups) {
        int g = 0;
        int total = 0;
        double sum = 0.0;
        double sumSq = 0.0;
        for (double[] grp : groups) {
            if (grp.length > 0) {
                g++;
                total += grp.length;
                sumSq += (double) grp.length * grp.length;
                for (double v : grp) {
                    sum += v;
                }
            }
        }
        if (g < 2 || total <= g) {
            return null;
        }
        double grand = sum / total;
        double ssb = 0.0;
        double ssw = 0.0;
        for (double[] grp : groups) {
            if (grp.length == 0) {
                continue;
            }
            double mean = SampleSummary.of(grp).mean();
            ssb += grp.length * (mean - grand) * (mean - grand);
            for (double v : grp) {
                ssw += (v - mean) * (v - mean);
            }
        }
        double msb = ssb / (g - 1);
        double msw = ssw / (total - g);
        double n0 = (total - sumSq / total) / (g - 1);
        double seq = Math.max(0.0, (msb - msw) / n0);
        double share = seq + msw == 0.0 ? Double.NaN : seq / (seq + msw);
        Advice advice = msw / n0 > seq ? Advice.MORE_SEEDS : Advice.MORE_SEQUENCES;
        return new Result(g, total, n0, seq, msw, share, advice);
    }
}
