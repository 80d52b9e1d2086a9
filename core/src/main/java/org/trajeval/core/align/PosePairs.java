package org.trajeval.core.align;

import org.trajeval.core.traj.PoseSequence;
import org.trajeval.core.traj.PositionColumns;

/**
 * Associated poses as an alignment reads them: pair k is reference pose k and estimate pose k,
 * read by index from whatever holds them (materialised sequences, or a trajectory's own columns
 * through index maps and an interpolated reference), so a fit needs no copy of the poses.
 */
public interface PosePairs {
    /** @return number of pairs */
    int size();

    /** @return the reference positions (m), pair k at index k */
    PositionColumns reference();

    /** @return the estimate positions (m), pair k at index k */
    PositionColumns estimate();

    /** Writes the rotation matrix (row-major) of reference pose k into {@code out[o..o+9)}. */
    void referenceRotation(int k, double[] out, int o);

    /** Writes the rotation matrix (row-major) of estimate pose k into {@code out[o..o+9)}. */
    void estimateRotation(int k, double[] out, int o);

    /** @return the pairs (reference k, estimate k) of two materialised sequences of equal length */
    static PosePairs of(PoseSequence reference, PoseSequence estimate) {
        return new PosePairs() {
            @Override
            public int size() {
                return estimate.size();
            }

            @Override
            public PositionColumns reference() {
                return reference;
            }

            @Override
            public PositionColumns estimate() {
                return estimate;
            }

            @Override
            public void referenceRotation(int k, double[] out, int o) {
                reference.rotation(k, out, o);
            }

            @Override
            public void estimateRotation(int k, double[] out, int o) {
                estimate.rotation(k, out, o);
            }
        };
    }
}
