package org.trajeval.core.report;

import java.util.List;

/**
 * What the HTML report draws for one sequence: the reference path and, per method and seed, the
 * aligned estimate with its position error over time. Not part of {@code report.json}.
 *
 * @param sequence sequence id
 * @param timeUnit unit of the traces' times: "s", or "frame" for files without stamps
 * @param referenceX reference x (m)
 * @param referenceY reference y (m)
 * @param referenceZ reference z (m)
 * @param estimates one trace per scored run (method, seed) on this sequence
 */
public record SequencePlot(String sequence, String timeUnit, double[] referenceX, double[] referenceY, double[] referenceZ,
        List<Trace> estimates) implements java.io.Serializable {

    /**
     * @param method method name
     * @param seed the seed of the run
     * @param x aligned estimate x (m)
     * @param y aligned estimate y (m)
     * @param z aligned estimate z (m)
     * @param t time of each pose from the reference's first stamp (s; frames for files without stamps)
     * @param errorM position error |p_aligned - p_ref(t)| (m), the reference interpolated at t
     * @param alignment the alignment model the evaluation applied ("none" when nothing was aligned)
     */
    public record Trace(String method, long seed, double[] x, double[] y, double[] z, double[] t, double[] errorM,
            String alignment) implements java.io.Serializable {
    }
}
