package org.trajeval.core.report;

import java.util.List;

/**
 * What the HTML report draws for one sequence: the reference path and, per method, one aligned
 * estimate with its position error over time. Not part of {@code report.json}.
 *
 * @param sequence sequence id
 * @param referenceX reference x (m)
 * @param referenceY reference y (m)
 * @param estimates one trace per method that has a scored run on this sequence
 */
public record SequencePlot(String sequence, double[] referenceX, double[] referenceY, List<Trace> estimates) {

    /**
     * @param method method name
     * @param seed the seed of the plotted run
     * @param x aligned estimate x (m)
     * @param y aligned estimate y (m)
     * @param t timestamps of the errors (s)
     * @param errorM position error |p_aligned - p_ref(t)| (m), the reference interpolated at t
     */
    public record Trace(String method, long seed, double[] x, double[] y, double[] t, double[] errorM) {
    }
}
