package org.trajeval.core.metric;

import java.util.Arrays;

/**
 * Settings of the KITTI-style length-normalised drift: segments of the given lengths (m) start
 * every {@code stepFrames} frames.
 *
 * @param segmentLengthsM segment lengths (m), each > 0
 * @param stepFrames frames between segment starts, >= 1
 */
public record DriftOptions(double[] segmentLengthsM, int stepFrames) {
    /** KITTI's odometry benchmark: 100, 200, ..., 800 m, a start every 10 frames. */
    public static final DriftOptions KITTI = new DriftOptions(
            new double[] {100, 200, 300, 400, 500, 600, 700, 800}, 10);

    /** @throws IllegalArgumentException on empty or non-positive lengths or a step below 1 */
    public DriftOptions {
        if (segmentLengthsM == null || segmentLengthsM.length == 0) {
            throw new IllegalArgumentException("drift needs at least one segment length (m)");
        }
        segmentLengthsM = segmentLengthsM.clone();
        for (double l : segmentLengthsM) {
            if (!(l > 0.0) || !Double.isFinite(l)) {
                throw new IllegalArgumentException("drift segment lengths must be positive (m), got " + l);
            }
        }
        if (stepFrames < 1) {
            throw new IllegalArgumentException("drift step must be >= 1 frame, got " + stepFrames);
        }
    }

    @Override
    public double[] segmentLengthsM() {
        return segmentLengthsM.clone();
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof DriftOptions d && d.stepFrames == stepFrames
                && Arrays.equals(d.segmentLengthsM, segmentLengthsM);
    }

    @Override
    public int hashCode() {
        return 31 * Arrays.hashCode(segmentLengthsM) + stepFrames;
    }

    @Override
    public String toString() {
        return "DriftOptions" + Arrays.toString(segmentLengthsM) + " m every " + stepFrames + " frames";
    }
}
