package org.trajeval.core.io;

import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;

/**
 * ICL-NUIM's TUM-compatible ground truth ({@code livingRoom0.gt.freiburg}, ...): the TUM columns
 * {@code i tx ty tz qx qy qz qw}, where the first column is the rendered frame's index, not a time.
 * Read as TUM, then checked to be whole frame numbers and marked as index stamps (like a KITTI file
 * without times), so the report says "frame" and association pairs equal indices.
 */
final class IclNuimReader {
    private IclNuimReader() {
    }

    static LoadedTrajectory read(ByteSource file, String source, ReadOptions options, String reason) {
        LoadedTrajectory tum = TumReader.read(file, source, options, reason);
        var t = tum.trajectory();
        for (int i = 0; i < t.size(); i++) {
            if (t.t(i) != Math.rint(t.t(i)) || t.t(i) < 0) {
                throw new InputException(source, 0, "i", InputProblem.NOT_A_NUMBER, "the first column of an "
                        + "ICL-NUIM trajectory must be a whole frame index >= 0 (pose " + (i + 1) + "); for stamps in "
                        + "seconds pass --format tum", Double.toString(t.t(i)));
            }
        }
        return new LoadedTrajectory(source, TrajectoryFormat.ICL_NUIM, reason, t, tum.sha256(), true);
    }
}
