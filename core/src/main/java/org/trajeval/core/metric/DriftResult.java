package org.trajeval.core.metric;

import java.util.List;

/**
 * KITTI-style length-normalised drift.
 *
 * @param transPct mean over all segments of |trans(E)| / L x 100 (%)
 * @param rotDegPerM mean over all segments of angle(E) / L (deg/m)
 * @param segments number of segments
 * @param stepFrames frames between segment starts
 * @param perLength figures per segment length
 * @param pathLengthM length of the reference path (m); no segment fits when it is shorter than the
 *     shortest segment length
 */
public record DriftResult(double transPct, double rotDegPerM, int segments, int stepFrames,
        List<AtLength> perLength, double pathLengthM) {

    /**
     * @param lengthM segment length L (m)
     * @param transPct mean translational drift (%)
     * @param rotDegPerM mean rotational drift (deg/m)
     * @param segments number of segments of this length
     */
    public record AtLength(double lengthM, double transPct, double rotDegPerM, int segments) {
    }
}
